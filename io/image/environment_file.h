// Environment images for `background: {"environment": FILE}`: Radiance .hdr (io/image/hdr_file.h)
// or OpenEXR (.exr, through Debian's libopenexr: its RGBA interface, any compression, half or
// float), told apart by their first bytes. Both are linear radiance. The texel count is checked
// against the scene's limits before the pixels are read, and counted in its texture budget.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/lights/environment.h"
#include "io/base/load_options.h"

namespace rt {

// The image, with its sampling distribution; null and `error` (naming the file) on failure.
std::shared_ptr<const EnvironmentImage> load_environment_image(const std::string& path, const LoadLimits& limits,
                                                               LimitUsage& usage, std::string& error);

}  // namespace rt
