// Scene file (JSON) and the files it includes (io/scene/scene_sources.h) -> SceneDescription. Checks types, ranges,
// names and local transforms; collects every problem in `diags` and returns nothing if there was any error. The format
// is described by schemas/scene.schema.json and docs/scene-format.md.
#pragma once

#include <optional>

#include "io/base/load_options.h"
#include "io/json/document.h"
#include "io/scene/description.h"
#include "io/scene/scene_sources.h"

namespace rt {

std::optional<SceneDescription> parse_scene(const SceneSources& sources, const LoadOptions& options,
                                            Diagnostics& diags);

// Everything that could be read, even where there were errors (a value in error keeps its
// default): for `rtcli validate`, which goes on to check files and transforms so that one run
// reports every problem. Never rendered.
SceneDescription parse_scene_partial(const SceneSources& sources, const LoadOptions& options, Diagnostics& diags);

}  // namespace rt
