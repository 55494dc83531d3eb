// glTF animation channels as Tracks on the imported nodes. The file's first animation plays
// (a file may hold alternatives, such as "walk" and "run", that animate the same nodes); its
// translation, rotation and scale channels with LINEAR, STEP or CUBICSPLINE samplers. Morph
// target weights and channels on nodes outside the default scene are skipped with a warning.
// Channels that use one sampler share its keys (read once, counted once against
// LoadLimits::animation_keys, before they are read).
#pragma once

#include <string>
#include <vector>

#include "io/base/load_options.h"
#include "io/base/reporter.h"
#include "io/gltf/imported_model.h"

namespace tinygltf {
class Model;
}

namespace rt {

// node_map: per file node, its index in out.nodes (-1 if the scene does not use it). Appends the
// tracks of every animation (played together, as the Khronos sample viewer plays a file), or of
// the one `which` names (its name, or its index), to out.tracks and sets out.animation_end. False
// for a broken channel or one past the key limit (report.over_limit), each reported at its
// pointer, and for an unknown `which` (error.unknown_animation, with the names there are).
bool import_animations(const tinygltf::Model& model, const std::vector<int32_t>& node_map,
                       const std::optional<std::string>& which, const LoadLimits& limits, LimitUsage& usage,
                       ImportedModel& out, Reporter& report, ImportError& error);

}  // namespace rt
