// A "csg" node of a scene file made into a CsgTemplate of the scene graph, once its subtree is in
// the graph's node list: each operand's geometry moves from its node into the template (so the
// node is not also drawn on its own), shapes get the material of the nearest CSG node above them
// that gives one, and mesh operands are checked to be closed.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/scene_graph.h"
#include "io/base/reporter.h"
#include "io/scene/description.h"

namespace rt {

struct CsgSource {
  const NodeDescription& root;
  const std::map<const NodeDescription*, uint32_t>& scene_index;  // description -> graph node
  const SceneAssets& assets;
};

// nodes: the graph's nodes so far (the root's subtree among them). Problems go to `report` at
// the description's pointers; returns nothing when there was one.
std::optional<CsgTemplate> make_csg_template(const CsgSource& source, std::vector<SceneNode>& nodes, Reporter& report);

}  // namespace rt
