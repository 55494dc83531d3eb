// `rtcli validate`: every check the loader makes, without rendering and without building the
// BVH, plus the JSON Schema (schemas/scene.schema.json) for scene files. One run reports every
// problem: parse errors do not stop the glTF files and transforms from being checked. Schema
// failures at values the loader already reported (or above or below them) are not repeated: the
// loader's messages say more; any other is reported with the prefix "schema:".
#pragma once

#include <string>

#include "io/base/diagnostics.h"
#include "io/base/load_options.h"

namespace rt {

Diagnostics validate_file(const std::string& path, const LoadOptions& options);

}  // namespace rt
