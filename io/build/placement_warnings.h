// What the builder says about a scene once it is placed, when nothing is wrong enough to refuse
// it: a glTF file that draws nothing (every node of it with a mesh scaled to nothing), and many
// copies of one mesh or shape at one spot (no BVH can separate them: every ray that reaches them
// tests each copy, and the render crawls). Each is a (JSON pointer, message) pair.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/scene_graph.h"

namespace rt {

using PlacementWarning = std::pair<std::string, std::string>;

// Copies at one spot from which a scene gets a warning.
inline constexpr size_t kStackedCopiesWarning = 64;

// pointers / from_file: per node, where the scene describes it and whether it came from a glTF file.
std::vector<PlacementWarning> hidden_file_warnings(const SceneGraph& g, const std::vector<std::string>& pointers,
                                                   const std::vector<bool>& from_file,
                                                   const std::vector<PlacementIssue>& issues);

// From the placements at `seconds` (so that validate, which builds no BVH, says it too).
std::optional<PlacementWarning> stacked_copies_warning(const SceneGraph& g, float seconds,
                                                       const std::vector<std::string>& pointers);

}  // namespace rt
