// Scene file (JSON) -> SceneDescription. Checks types, ranges, names and local transforms;
// collects every problem in `diags` and returns nothing if there was any error.
// The format is described by schemas/scene.schema.json and README.md.
#pragma once

#include <optional>

#include "io/json_document.h"
#include "io/load_options.h"
#include "io/scene_description.h"

namespace rt {

std::optional<SceneDescription> parse_scene(const JsonDocument& doc, const LoadOptions& options, Diagnostics& diags);

}  // namespace rt
