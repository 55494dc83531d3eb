#include "io/assemble/placement_warnings.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace rt {

void warn_hidden_files(const SceneGraph& g, const std::vector<std::string>& pointers,
                       const std::vector<bool>& from_file, const std::vector<PlacementIssue>& issues,
                       Reporter& report) {
  // Per file (the pointer that places it): its nodes with geometry, and those singular. A file's
  // parts scaled to nothing are hidden on purpose; all of them is a file that draws nothing.
  std::map<std::string, std::pair<size_t, std::set<uint32_t>>> files;
  for (size_t n = 0; n < g.nodes.size(); ++n)
    if (from_file[n] && g.nodes[n].has_geometry()) ++files[pointers[n]].first;
  for (const PlacementIssue& issue : issues)
    if (issue.kind == PlacementIssue::kSingular && from_file[issue.node])
      files[pointers[issue.node]].second.insert(issue.node);
  for (const auto& [pointer, nodes] : files)
    if (nodes.first > 0 && nodes.second.size() == nodes.first)
      report.warning(pointer,
                     "the glTF file has no triangles to render: every node of it that carries a mesh has a "
                     "singular world transform in the first frame (a zero scale, or a matrix that flattens "
                     "it)");
}

void warn_stacked_copies(const SceneGraph& g, const Pose& pose, const std::vector<std::string>& pointers,
                         Reporter& report) {
  // Every placement as (what: a mesh, or -1 - a shape kind; its world matrix; its node), sorted:
  // copies at one spot are neighbours.
  const std::vector<Mat4>& world = pose.world;
  using Placement = std::pair<int64_t, std::array<float, 16>>;
  std::vector<std::pair<Placement, size_t>> copies;
  for (size_t n = 0; n < g.nodes.size(); ++n) {
    const SceneNode& node = g.nodes[n];
    if (!node.has_geometry()) continue;
    const int64_t what = node.shape ? -1 - static_cast<int64_t>(*node.shape) : node.meshes.front().mesh;
    for (size_t c = 0; c < std::max<size_t>(1, node.instancing.size()); ++c) {
      const Mat4 m = node.instancing.empty() ? world[n] : world[n] * node.instancing[c];
      std::array<float, 16> matrix;
      for (int k = 0; k < 16; ++k) matrix[static_cast<size_t>(k)] = m[k / 4][k % 4];
      copies.push_back({{what, matrix}, n});
    }
  }
  std::sort(copies.begin(), copies.end());
  size_t most = 0, node = 0;
  for (size_t i = 0, j = 0; i < copies.size(); i = j) {
    for (j = i + 1; j < copies.size() && copies[j].first == copies[i].first; ++j) {
    }
    if (j - i > most) {
      most = j - i;
      node = copies[i].second;
    }
  }
  if (most < kStackedCopiesWarning) return;
  report.warning(pointers[node], std::to_string(most) + " copies of " + (g.nodes[node].shape ? "a shape" : "a mesh") +
                                     " are placed at exactly the same spot (the same world transform): no "
                                     "BVH can separate them, so every ray that reaches them tests all " +
                                     std::to_string(most) +
                                     " and the render will be slow (docs/errors-and-limits.md, \"Limits\")");
}

void warn_empty_csgs(const SceneGraph& g, const Pose& pose, const std::vector<std::string>& pointers,
                     Reporter& report) {
  for (const CsgTemplate& t : g.csgs) {
    const CsgPlacement placed = place_csg(t, pose.world, *g.assets);
    if (placed.object || placed.singular_node || placed.beyond_range_node) continue;
    report.warning(pointers[t.root_node()],
                   "this CSG solid encloses nothing (its intersection's operands do not overlap), so it draws nothing");
  }
}

}  // namespace rt
