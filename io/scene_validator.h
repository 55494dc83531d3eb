// `rtcli validate`: load_scene (io/scene_loader.h) without building the BVH. Render and validate
// are one code path, so they report the same problems, in the same order, on every file.
#pragma once

#include <string>

#include "io/base/diagnostics.h"
#include "io/base/load_options.h"

namespace rt {

Diagnostics validate_file(const std::string& path, const LoadOptions& options);

}  // namespace rt
