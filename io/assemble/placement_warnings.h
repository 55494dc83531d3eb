// What the builder says about a scene once it is placed, when nothing is wrong enough to refuse
// it: a glTF file that draws nothing (every node of it with a mesh scaled to nothing), and many
// copies of one mesh or shape at one spot (no BVH can separate them: every ray that reaches them
// tests each copy, and the render crawls). Each is a warning at the JSON pointer of the node.
#pragma once

#include <string>
#include <vector>

#include "core/scene_graph.h"
#include "io/base/reporter.h"

namespace rt {

// Copies at one spot from which a scene gets a warning.
inline constexpr size_t kStackedCopiesWarning = 64;

// pointers / from_file: per node, where the scene describes it and whether it came from a glTF file.
void warn_hidden_files(const SceneGraph& g, const std::vector<std::string>& pointers,
                       const std::vector<bool>& from_file, const std::vector<PlacementIssue>& issues, Reporter& report);

// From the placements in `pose` (so that validate, which builds no BVH, says it too).
void warn_stacked_copies(const SceneGraph& g, const Pose& pose, const std::vector<std::string>& pointers,
                         Reporter& report);

// A CSG solid that encloses nothing (an intersection of operands that do not meet).
void warn_empty_csgs(const SceneGraph& g, const Pose& pose, const std::vector<std::string>& pointers, Reporter& report);

}  // namespace rt
