#include "core/lights/emitters.h"

#include <algorithm>
#include <cmath>

#include "core/direction_sampling.h"
#include "core/shapes/shape_sampling.h"

namespace rt {
namespace {

// A shape's world area, near enough to weigh it against other emitters: exact under a uniform
// scale.
float approximate_world_area(const AnalyticShape& shape) {
  return object_area(shape.kind) * std::pow(std::fabs(glm::determinant(Mat3(shape.transform.to_world))), 2.0f / 3.0f);
}

// Whether the point of operand surface `surface` of `csg` at `point` (unit outward normal
// `normal`) lies on the solid's boundary: the spans along the normal's line through it have a
// boundary of that surface there. `scale` is the operand's size, which sets how near is "there".
bool on_csg_boundary(const CsgObject& csg, uint32_t surface, Vec3 point, Vec3 normal, float scale) {
  Ray line;
  line.direction = normal * scale;
  line.origin = point - line.direction;  // the point at t = 1
  CsgSpanList spans;
  csg.spans(line, spans);
  constexpr float kNear = 1e-4f;  // in t: a ten-thousandth of the operand's size
  for (const CsgSpan& s : spans)
    for (const CsgBoundary* b : {&s.in, &s.out})
      if (b->surface == surface && std::fabs(b->t - 1.0f) < kNear) return true;
  return false;
}

}  // namespace

void Emitters::add(const Entry& e) {
  if (drawn_.size() <= e.prim) drawn_.resize(e.prim + 1, Drawn{});
  Drawn& d = drawn_[e.prim];
  if (d.count == 0) d.first = static_cast<uint32_t>(entries_.size());
  ++d.count;
  entries_.push_back(e);
}

Emitters::Emitters(const Bvh& bvh, const SceneAssets& assets) {
  const auto weight_of = [&](uint32_t material) {
    return material < assets.materials.size() ? emission_weight(assets.materials[material].emission) : 0.0f;
  };
  const auto add_shape = [&](Kind kind, uint32_t prim, uint32_t index, const AnalyticShape& shape) {
    const float w = weight_of(shape.material);
    const float area = approximate_world_area(shape);
    if (!(w > 0.0f) || !(area > 0.0f) || !std::isfinite(area)) return;
    Entry e;
    e.kind = kind;
    e.prim = prim;
    e.index = index;
    e.weight = area * w;
    add(e);
  };
  for (uint32_t id = 0; id < bvh.primitive_count(); ++id) {
    switch (bvh.kind(id)) {
      // A flattened instance's triangles are sampled through its entry below; a one-level BVH's
      // loose triangles carry no material.
      case PrimitiveKind::kTriangle: continue;
      case PrimitiveKind::kShape: add_shape(Kind::kShape, id, 0, bvh.shape(id)); continue;
      case PrimitiveKind::kCsg: {
        const CsgObject& csg = bvh.csg(id);
        for (uint32_t k = 0; k < csg.surfaces().size(); ++k)
          if (!csg.surface(k).is_mesh) add_shape(Kind::kCsgOperand, id, k, csg.surface(k).shape);
        continue;
      }
      case PrimitiveKind::kInstance: break;
    }
    const MeshInstance& inst = bvh.instance(id);
    if (inst.material >= assets.materials.size() || inst.mesh >= assets.meshes.size()) continue;
    const float w = weight_of(inst.material);
    if (!(w > 0.0f)) continue;
    const TriangleMesh& mesh = assets.meshes[inst.mesh].mesh;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      const Vec3 a = inst.transform.point_to_world(mesh.positions[mesh.indices[3 * t]]);
      const Vec3 b = inst.transform.point_to_world(mesh.positions[mesh.indices[3 * t + 1]]);
      const Vec3 c = inst.transform.point_to_world(mesh.positions[mesh.indices[3 * t + 2]]);
      const float area = 0.5f * glm::length(glm::cross(b - a, c - a));
      if (!(area > 0.0f) || !std::isfinite(area)) continue;  // degenerate: never met by a ray either
      Entry e;
      e.prim = id;
      e.index = static_cast<uint32_t>(t);
      e.p0 = a;
      e.e1 = b - a;
      e.e2 = c - a;
      e.weight = area * w;
      add(e);
      drawn_[id].emission_weight = w;
    }
  }
  cdf_.reserve(entries_.size());
  double sum = 0.0;  // in double: many small triangles must not stop adding up
  for (const Entry& e : entries_) {
    sum += e.weight;
    cdf_.push_back(static_cast<float>(sum));
  }
  total_ = static_cast<float>(sum);
}

const AnalyticShape& Emitters::shape_of(const Bvh& bvh, const Entry& e) const {
  return e.kind == Kind::kShape ? bvh.shape(e.prim) : bvh.csg(e.prim).surface(e.index).shape;
}

// The entry's probability over the point's area: the area it covers is its object-space area
// stretched by the transform where the point is.
float Emitters::shape_area_pdf(const Entry& e, const AnalyticShape& shape, Vec3 normal) const {
  const float area = object_area(shape.kind) * area_scale(shape.transform, normal);
  return total_ > 0.0f && area > 0.0f ? e.weight / total_ / area : 0.0f;
}

EmitterSample Emitters::sample(const Bvh& bvh, float u_pick, Vec2 u) const {
  EmitterSample s;
  if (entries_.empty()) return s;
  const float target = u_pick * total_;
  const size_t i = std::min<size_t>(
      static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin()), entries_.size() - 1);
  const Entry& e = entries_[i];
  s.hit.prim = e.prim;
  if (e.kind == Kind::kTriangle) {
    const Vec2 b = uniform_triangle(u);
    s.point = e.p0 + b.x * e.e1 + b.y * e.e2;
    s.hit.part = e.index;
    s.hit.b1 = b.x;
    s.hit.b2 = b.y;
    // weight / total / area = the material's emission weight / total (area x weight / area).
    s.area_pdf = e.weight / total_ / (0.5f * glm::length(glm::cross(e.e1, e.e2)));
    return s;
  }
  const AnalyticShape& shape = shape_of(bvh, e);
  const ShapePoint p = sample_object_surface(shape.kind, u);
  s.point = shape.transform.point_to_world(p.position);
  const Vec3 normal = shape.transform.normal_to_world_unit(p.normal);
  s.hit.part = p.part;
  if (e.kind == Kind::kCsgOperand) {
    s.hit.operand = csg_operand(e.index, false);
    const Aabb bounds = world_bounds(shape);
    const float scale = glm::length(bounds.hi - bounds.lo);
    if (!on_csg_boundary(bvh.csg(e.prim), e.index, s.point, normal, scale)) return EmitterSample{};
  }
  s.area_pdf = shape_area_pdf(e, shape, normal);
  return s;
}

float Emitters::area_pdf(const Bvh& bvh, const Hit& hit, Vec3 normal) const {
  if (hit.prim >= drawn_.size() || drawn_[hit.prim].count == 0) return 0.0f;
  const Drawn& d = drawn_[hit.prim];
  const Entry& first = entries_[d.first];
  switch (first.kind) {
    case Kind::kTriangle: return total_ > 0.0f ? d.emission_weight / total_ : 0.0f;
    case Kind::kShape: return shape_area_pdf(first, bvh.shape(hit.prim), normal);
    case Kind::kCsgOperand:
      for (uint32_t k = d.first; k < d.first + d.count; ++k)
        if (entries_[k].index == csg_surface_index(hit))
          return shape_area_pdf(entries_[k], shape_of(bvh, entries_[k]), normal);
      return 0.0f;
  }
  return 0.0f;
}

}  // namespace rt
