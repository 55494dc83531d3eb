#include "core/csg_template.h"

#include <algorithm>
#include <map>
#include <tuple>
#include <unordered_map>

namespace rt {
namespace {

bool finite_box(const Aabb& box) { return is_finite(box.lo) && is_finite(box.hi); }

}  // namespace

CsgPlacement place_csg(const CsgTemplate& t, const std::vector<Mat4>& world, const SceneAssets& assets) {
  CsgPlacement out;
  CsgObject csg;
  std::vector<uint32_t> open;  // operations not yet closed, with their template ends
  std::vector<uint32_t> open_end;
  for (uint32_t i = 0; i < t.nodes.size(); ++i) {
    while (!open_end.empty() && open_end.back() <= i) {
      csg.close(open.back());
      open.pop_back();
      open_end.pop_back();
    }
    const CsgTemplateNode& n = t.nodes[i];
    if (!n.leaf) {
      open.push_back(csg.open(n.op));
      open_end.push_back(n.end);
      continue;
    }
    const uint32_t leaf = csg.begin_leaf();
    const auto place = [&](uint32_t node) -> std::optional<Transform> {
      const auto transform = make_transform(world[node]);
      if (!transform) out.singular_node = node;
      return transform;
    };
    if (n.shape) {
      const auto transform = place(n.node);
      if (!transform) return out;
      CsgSurface s;
      s.shape = AnalyticShape{*n.shape, n.material, *transform};
      if (!finite_box(s.bounds())) {
        out.beyond_range_node = n.node;
        return out;
      }
      csg.add_surface(s);
    }
    for (const CsgMeshPart& part : n.meshes) {
      const auto transform = place(part.node);
      if (!transform) return out;
      const MeshGeometry& g = assets.meshes[part.mesh];
      CsgSurface s;
      s.is_mesh = true;
      s.mesh =
          MeshInstance{&g.bvh, *transform, transform_bounds(transform->to_world, g.bounds), part.mesh, part.material};
      s.triangles = &g.mesh;
      if (!finite_box(s.bounds())) {
        out.beyond_range_node = part.node;
        return out;
      }
      csg.add_surface(s);
    }
    csg.close(leaf);
  }
  while (!open.empty()) {
    csg.close(open.back());
    open.pop_back();
  }
  csg.finish();
  if (!csg.bounds().empty()) out.object = std::move(csg);
  return out;
}

size_t count_open_edges(const std::vector<const TriangleMesh*>& parts) {
  std::map<std::tuple<float, float, float>, uint32_t> welded;
  std::unordered_map<uint64_t, uint32_t> uses;
  for (const TriangleMesh* m : parts) {
    std::vector<uint32_t> id(m->positions.size());
    for (size_t v = 0; v < m->positions.size(); ++v) {
      const Vec3 p = m->positions[v];
      id[v] = welded.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<uint32_t>(welded.size())).first->second;
    }
    for (size_t i = 0; i + 2 < m->indices.size(); i += 3) {
      for (int e = 0; e < 3; ++e) {
        uint32_t a = id[m->indices[i + e]], b = id[m->indices[i + (e + 1) % 3]];
        if (a == b) continue;  // a degenerate triangle's collapsed edge
        if (a > b) std::swap(a, b);
        ++uses[(uint64_t{a} << 32) | b];
      }
    }
  }
  return static_cast<size_t>(std::count_if(uses.begin(), uses.end(), [](const auto& u) { return u.second % 2 != 0; }));
}

}  // namespace rt
