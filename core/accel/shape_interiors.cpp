// find_shape_interiors, and the query that reads them: Bvh::intersect_from_inside.
#include "core/accel/shape_interiors.h"

#include <algorithm>

#include "core/accel/bvh.h"

namespace rt {
namespace {

bool closed(ShapeKind kind) { return kind != ShapeKind::kPlane; }  // convex, and bounded on every side

Aabb grown(const Aabb& box, float by) { return {box.lo - Vec3(by), box.hi + Vec3(by)}; }

// The primitives of leaf `leaf` other than `self` whose boxes meet `region`, added to `out`;
// false when one is not an analytic shape or there are too many.
bool add_leaf(const Bvh& bvh, uint32_t leaf, uint32_t self, const Aabb& region, ShapeInterior& out) {
  if (BvhRef::is_quad_leaf(leaf)) return false;  // triangles: whatever they are, not tested here
  const uint32_t first = BvhRef::first(leaf), end = first + BvhRef::count(leaf);
  for (uint32_t slot = first; slot < end; ++slot) {
    const Bvh::Slot& s = bvh.slots()[slot];
    if (s.id == self || !region.meets(bvh.primitive_bounds(s.id, s))) continue;
    if (bvh.kind(s.id) != PrimitiveKind::kShape || out.count == ShapeInterior::kMaxOthers) return false;
    out.others[out.count++] = s.id;
  }
  return true;
}

ShapeInterior interior_of(const Bvh& bvh, uint32_t id) {
  ShapeInterior in;
  const AnalyticShape& shape = bvh.shape(id);
  if (!closed(shape.kind)) return in;
  const Aabb box = world_bounds(shape);
  const float margin =
      1e-4f * (max_component(box.extent()) + max_component(glm::max(glm::abs(box.lo), glm::abs(box.hi))));
  in.box = grown(box, margin);
  const Aabb region = grown(box, 2.0f * margin);
  in.count = 0;
  if (!bvh.for_each_leaf_meeting([&](const Aabb& b) { return region.meets(b); },
                                 [&](uint32_t leaf) { return add_leaf(bvh, leaf, id, region, in); }))
    in.count = ShapeInterior::kUnusable;
  return in;
}

// A shape's crossing merged into `hit` as the kernels' leaves merge it (take_if_first, core/accel/
// bvh_kernels_impl.h): ray.tmax one float past the hit, so a crossing at an equal t is still tested.
bool take_shape(const Bvh& bvh, uint32_t id, Ray& ray, Hit& hit) {
  Hit candidate;
  if (!intersect_shape(bvh.shape(id), ray, candidate)) return false;
  candidate.prim = id;
  if (!precedes(candidate, hit)) return false;
  hit = candidate;
  ray.tmax = next_float_up(hit.t);
  return true;
}

}  // namespace

std::vector<ShapeInterior> find_shape_interiors(const Bvh& bvh) {
  std::vector<ShapeInterior> out;
  if (!std::any_of(bvh.shapes().begin(), bvh.shapes().end(), [](const AnalyticShape& s) { return closed(s.kind); }))
    return out;
  const uint32_t first = bvh.triangle_count();  // the shapes' ids follow the triangles'
  out.reserve(bvh.shapes().size());
  for (uint32_t i = 0; i < bvh.shapes().size(); ++i) out.push_back(interior_of(bvh, first + i));
  return out;
}

bool Bvh::intersect_from_inside(uint32_t inside, Ray& ray, Hit& hit) const {
  const uint32_t index = inside - ranges_.shape_begin;  // wraps past the end for any other id
  if (index >= interiors_.size()) return intersect(ray, hit);
  const ShapeInterior& interior = interiors_[index];
  if (!interior.usable() || !interior.box.contains(ray.origin)) return intersect(ray, hit);
  const float tmax = ray.tmax;
  hit = Hit{};
  // The segment from the origin to the shape's crossing lies in the box when both ends do, and
  // so does every crossing before it: the others' boxes are the only ones that reach there.
  if (!take_shape(*this, inside, ray, hit) || !interior.box.contains(ray.at(hit.t))) {
    ray.tmax = tmax;  // not the shape's inside after all (a ray that grazes it): the walk
    return intersect(ray, hit);
  }
  for (uint32_t k = 0; k < interior.count; ++k) take_shape(*this, interior.others[k], ray, hit);
  ray.tmax = hit.t;
  return true;
}

}  // namespace rt
