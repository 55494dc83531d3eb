#include "core/lights/emitters.h"

#include <algorithm>

#include "core/direction_sampling.h"

namespace rt {

Emitters::Emitters(const Bvh& bvh, const SceneAssets& assets) {
  for (uint32_t id = 0; id < bvh.primitive_count(); ++id) {
    if (!bvh.is_instance(id)) continue;
    const MeshInstance& inst = bvh.instance(id);
    if (inst.material >= assets.materials.size() || inst.mesh >= assets.meshes.size()) continue;
    const float w = emission_weight(assets.materials[inst.material].emission);
    if (!(w > 0.0f)) continue;
    const TriangleMesh& mesh = assets.meshes[inst.mesh].mesh;
    bool any = false;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      const Vec3 a = inst.transform.point_to_world(mesh.positions[mesh.indices[3 * t]]);
      const Vec3 b = inst.transform.point_to_world(mesh.positions[mesh.indices[3 * t + 1]]);
      const Vec3 c = inst.transform.point_to_world(mesh.positions[mesh.indices[3 * t + 2]]);
      const float area = 0.5f * glm::length(glm::cross(b - a, c - a));
      if (!(area > 0.0f) || !std::isfinite(area)) continue;  // degenerate: never met by a ray either
      triangles_.push_back(Triangle{a, b - a, c - a, id, static_cast<uint32_t>(t), area * w});
      any = true;
    }
    if (any) {
      if (drawn_.size() <= id) drawn_.resize(id + 1, 0);
      drawn_[id] = 1;
    }
  }
  cdf_.reserve(triangles_.size());
  double sum = 0.0;  // in double: many small triangles must not stop adding up
  for (const Triangle& t : triangles_) {
    sum += t.weight;
    cdf_.push_back(static_cast<float>(sum));
  }
  total_ = static_cast<float>(sum);
}

EmitterSample Emitters::sample(float u_pick, Vec2 u) const {
  EmitterSample s;
  if (triangles_.empty()) return s;
  const float target = u_pick * total_;
  const size_t i = std::min<size_t>(static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin()),
                                    triangles_.size() - 1);
  const Triangle& t = triangles_[i];
  const Vec2 b = uniform_triangle(u);
  s.point = t.p0 + b.x * t.e1 + b.y * t.e2;
  s.hit.prim = t.prim;
  s.hit.part = t.index;
  s.hit.b1 = b.x;
  s.hit.b2 = b.y;
  // weight / total / area = the material's emission weight / total (area x weight / area).
  s.area_pdf = t.weight / total_ / (0.5f * glm::length(glm::cross(t.e1, t.e2)));
  return s;
}

}  // namespace rt
