#include "core/csg/csg_object.h"

#include <algorithm>
#include <cmath>

#include "core/csg/csg_mesh_hits.h"
#include "core/float_error.h"
#include "core/shapes/sphere.h"

namespace rt {
namespace {

// The box grown by a little more than rounding: leaf boxes are tested in world space, the
// shapes in their own, and a box as tight as a cube's faces could otherwise lose a real span.
Aabb padded(const Aabb& box) {
  if (box.empty()) return box;
  const Vec3 pad = 1e-4f * box.extent() + Vec3(1e-6f) + 1e-6f * glm::max(glm::abs(box.lo), glm::abs(box.hi));
  return Aabb{box.lo - pad, box.hi + pad};
}

float frobenius(const Mat3& m) { return std::sqrt(glm::dot(m[0], m[0]) + glm::dot(m[1], m[1]) + glm::dot(m[2], m[2])); }

Aabb overlap(const Aabb& a, const Aabb& b) { return Aabb{glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)}; }

// Crossings a closed mesh operand can report along one line before the farthest are dropped.
constexpr int kMaxMeshCrossings = 2 * CsgSpanList::kCapacity;

struct Crossing {
  CsgBoundary at;
  bool entering;  // along the line: the triangle faces against it (its outward winding)
};

// Whether triangle `triangle` of a mesh operand faces against object-space `direction`.
bool faces_against(const CsgSurface& s, uint32_t triangle, Vec3 direction) {
  if (!s.triangles) return true;
  const TriangleMesh& m = *s.triangles;
  const Vec3 p0 = m.positions[m.indices[3 * triangle]], p1 = m.positions[m.indices[3 * triangle + 1]],
             p2 = m.positions[m.indices[3 * triangle + 2]];
  return glm::dot(glm::cross(p1 - p0, p2 - p0), direction) < 0.0f;
}

}  // namespace

uint32_t CsgObject::open(CsgOp op) {
  CsgNode n;
  n.op = op;
  nodes_.push_back(n);
  return static_cast<uint32_t>(nodes_.size() - 1);
}

uint32_t CsgObject::begin_leaf() {
  CsgNode n;
  n.leaf = true;
  n.first_surface = static_cast<uint32_t>(surfaces_.size());
  nodes_.push_back(n);
  return static_cast<uint32_t>(nodes_.size() - 1);
}

void CsgObject::add_surface(const CsgSurface& s) {
  surfaces_.push_back(s);
  ++nodes_.back().surface_count;
}

void CsgObject::close(uint32_t node) { nodes_[node].end = static_cast<uint32_t>(nodes_.size()); }

void CsgObject::finish(bool index_children) {
  // Children follow their parent, so a backward pass sees every subtree before its root.
  for (size_t i = nodes_.size(); i-- > 0;) {
    CsgNode& n = nodes_[i];
    n.bounds = Aabb{};
    if (n.leaf) {
      for (uint32_t s = 0; s < n.surface_count; ++s) n.bounds.extend(surfaces_[n.first_surface + s].bounds());
      n.bounds = padded(n.bounds);
      continue;
    }
    bool first = true;
    for (uint32_t c = static_cast<uint32_t>(i) + 1; c < n.end; c = nodes_[c].end) {
      const Aabb& b = nodes_[c].bounds;
      if (first || n.op == CsgOp::kUnion || n.op == CsgOp::kMerge) n.bounds.extend(b);
      else if (n.op == CsgOp::kIntersection) n.bounds = overlap(n.bounds, b);
      first = false;
    }
    if (n.bounds.empty()) n.bounds = Aabb{};
  }
  rounding_linear_ = rounding_translation_ = 0.0f;
  for (const CsgSurface& s : surfaces_) {
    const Transform& t = s.transform();
    const float world = frobenius(Mat3(t.to_world));
    rounding_linear_ = std::max(rounding_linear_, frobenius(Mat3(t.to_object)) * world);
    rounding_translation_ = std::max(rounding_translation_, glm::length(Vec3(t.to_object[3])) * world);
  }
  // Operations of many children get their children's boxes in a tree (core/csg/csg_child_index.h).
  child_indices_.clear();
  for (size_t i = 0; index_children && i < nodes_.size(); ++i) {
    CsgNode& n = nodes_[i];
    n.child_index = CsgNode::kNoChildIndex;
    if (n.leaf) continue;
    std::vector<uint32_t> children;
    std::vector<Aabb> boxes;
    for (uint32_t c = static_cast<uint32_t>(i) + 1; c < n.end; c = nodes_[c].end) {
      children.push_back(c);
      boxes.push_back(nodes_[c].bounds);
    }
    if (children.size() < CsgChildIndex::kMinIndexedChildren) continue;
    n.child_index = static_cast<uint32_t>(child_indices_.size());
    child_indices_.emplace_back(children, boxes);
  }
}

void CsgObject::spans(const Ray& ray, CsgSpanList& out) const {
  out.clear();
  if (!nodes_.empty()) node_spans(0, CsgReach::whole(ray), out);
}

void CsgObject::spans_in_reach(const Ray& ray, CsgSpanList& out) const {
  out.clear();
  if (!nodes_.empty()) node_spans(0, CsgReach::of(ray), out);
}

void CsgObject::node_spans(uint32_t index, const CsgReach& reach, CsgSpanList& out) const {
  const CsgNode& n = nodes_[index];
  out.clear();
  if (!reach_meets_box(n.bounds, reach)) return;
  if (n.leaf) {
    leaf_spans(n, reach.line, out);
    return;
  }
  const bool cuts = n.op == CsgOp::kIntersection || n.op == CsgOp::kDifference;
  // The children's spans combined in order. The running result alternates between two lists, and
  // the last child's step writes straight into `out`: copying the result back after every step
  // (a list holds 1.4 KB) cost csg.json 2% in memmove.
  CsgSpanList lists[2], operand;
  const CsgSpanList* result = nullptr;  // once the first child is in
  // False when nothing can change the result any more (a cut with nothing left to cut).
  const auto take = [&](uint32_t child, bool last) {
    if (!result) {
      CsgSpanList& first = last ? out : lists[0];
      node_spans(child, reach, first);
      result = &first;
    } else {
      node_spans(child, reach, operand);
      if (operand.empty() && n.op != CsgOp::kIntersection) return true;
      CsgSpanList& next = last ? out : lists[result == &lists[0] ? 1 : 0];
      csg_combine(n.op, *result, operand, next);
      result = &next;
    }
    return !(cuts && result->empty());
  };
  const auto finish = [&] {
    if (result && result != &out) out = *result;
  };
  if (n.child_index != CsgNode::kNoChildIndex) {
    // Only the children whose boxes the line meets within the reach: the others have no spans
    // there, which union, merge and difference skip and which empty an intersection.
    constexpr int kMet = 256;
    uint32_t met[kMet];
    const int count = child_indices_[n.child_index].met(reach, met, kMet);
    if (count >= 0) {
      const bool first_met = count > 0 && met[0] == index + 1;
      if (cuts && !first_met) return;
      if (n.op == CsgOp::kIntersection && static_cast<uint32_t>(count) < child_indices_[n.child_index].size()) return;
      for (int k = 0; k < count; ++k)
        if (!take(met[k], k + 1 == count)) return;  // `out` stays empty
      finish();
      return;
    }
  }
  for (uint32_t child = index + 1; child < n.end; child = nodes_[child].end)
    if (!take(child, nodes_[child].end >= n.end)) return;
  finish();
}

void CsgObject::leaf_spans(const CsgNode& leaf, const Ray& line, CsgSpanList& out) const {
  if (leaf.surface_count == 0) return;
  const CsgSurface& first = surfaces_[leaf.first_surface];
  const uint32_t medium = first.material();
  if (!first.is_mesh) {
    // A convex shape: its two crossings of the line (a grazing ray's single one is no span).
    Ray r = to_object_ray(first.shape, line);
    Hit a, b;
    if (first.shape.kind == ShapeKind::kSphere) {
      // One quadratic for both crossings (a tenth of csg.json's render solved each twice).
      if (!intersect_sphere_twice(r, a, b)) return;
    } else {
      if (!intersect_object_space(first.shape.kind, r, a)) return;
      r.tmin = next_float_up(a.t);
      if (!intersect_object_space(first.shape.kind, r, b)) return;
    }
    out.add(CsgSpan{CsgBoundary{a.t, leaf.first_surface, a.part, 0.0f, 0.0f},
                    CsgBoundary{b.t, leaf.first_surface, b.part, 0.0f, 0.0f}, medium});
    return;
  }
  // A closed mesh (all its primitives together): its crossings sorted, paired by parity.
  Crossing crossings[kMaxMeshCrossings];
  int count = 0;
  bool dropped = false;
  for (uint32_t s = 0; s < leaf.surface_count; ++s) {
    const uint32_t surface = leaf.first_surface + s;
    const CsgSurface& operand = surfaces_[surface];
    const MeshInstance& m = operand.mesh;
    // The line as two rays from its origin, forwards and backwards, so that the BVH sees only
    // positive distances (its boxes are widened for rounding on that side).
    for (const float sign : {1.0f, -1.0f}) {
      Ray half = object_ray(m.transform, line);
      half.direction *= sign;
      half.tmin = 0.0f;
      auto add = [&](const Hit& h) {
        const Crossing c{CsgBoundary{sign * h.t, surface, h.prim, h.b1, h.b2},
                         faces_against(operand, h.prim, half.direction) == (sign > 0.0f)};
        if (count < kMaxMeshCrossings) {
          crossings[count++] = c;
        } else {  // keep the nearest
          dropped = true;
          Crossing* far = std::max_element(crossings, crossings + count, [](const Crossing& x, const Crossing& y) {
            return std::fabs(x.at.t) < std::fabs(y.at.t);
          });
          if (std::fabs(c.at.t) < std::fabs(far->at.t)) *far = c;
        }
        return false;
      };
      visit_mesh_hits(*m.bvh, half, add);
    }
  }
  std::sort(crossings, crossings + count, [](const Crossing& x, const Crossing& y) { return x.at.t < y.at.t; });
  // A line through an edge or a vertex meets each triangle there: one crossing of the surface,
  // reported twice or more. Such repeats (as near as rounding, the same way through) count once.
  int kept = 0;
  for (int i = 0; i < count; ++i) {
    if (kept > 0) {
      const Crossing& last = crossings[kept - 1];
      const float near = 1e-5f * std::max(1.0f, std::fabs(last.at.t));
      if (crossings[i].entering == last.entering && crossings[i].at.t - last.at.t <= near) continue;
    }
    crossings[kept++] = crossings[i];
  }
  for (int i = 0; i + 1 < kept; i += 2) out.add(CsgSpan{crossings[i].at, crossings[i + 1].at, medium});
  if (dropped) out.mark_truncated();
}

float CsgObject::rounding_bound(const Ray& ray) const {
  // |o| and |d| in the norms that bound the Euclidean from the safe side: |o|_2 <= |o|_1, |d|_2 >= |d|_inf.
  const Vec3 o = abs3(ray.origin), d = abs3(ray.direction);
  const float direction = std::max(d.x, std::max(d.y, d.z));
  const float bound =
      2.0f * float_gamma(3) * (rounding_linear_ * (o.x + o.y + o.z) + rounding_translation_) / direction;
  return bound >= 0.0f ? bound : kInfinity;  // a NaN: ask every surface
}

bool csg_boundary_in_reach(const CsgObject& csg, const CsgBoundary& b, const Ray& ray, float bound) {
  if (!(b.t > ray.tmin)) return false;
  if (b.t > ray.tmin + bound) return true;  // then also past the surface's own rounding
  const Transform& t = csg.surface(b.surface).transform();
  return b.t > ray.tmin + origin_rounding(t, ray.origin, t.vector_to_object(ray.direction));
}

bool intersect_csg(const CsgObject& csg, const Ray& ray, Hit& hit) {
  CsgSpanList spans;
  csg.spans_in_reach(ray, spans);
  const float bound = csg.rounding_bound(ray);
  float best = ray.tmax;
  const CsgBoundary* found = nullptr;
  bool leaving = false;
  uint32_t medium = 0;
  for (const CsgSpan& s : spans) {
    if (s.in.t >= best) break;  // sorted by entry: nothing nearer follows
    if (csg_boundary_in_reach(csg, s.in, ray, bound)) {
      found = &s.in;
      leaving = false;
    } else if (s.out.t < best && csg_boundary_in_reach(csg, s.out, ray, bound)) {
      found = &s.out;
      leaving = true;
    } else {
      continue;
    }
    best = found->t;
    medium = s.medium;
  }
  if (!found) return false;
  const uint32_t prim = hit.prim;  // intersect_csg leaves prim to its caller
  hit = csg_hit(*found, leaving, medium, prim);
  return true;
}

void orient_csg_surface(SurfaceInteraction& si, const Ray& ray, const Hit& hit) {
  const bool leaving = csg_leaving(hit);
  const bool faces_ray = glm::dot(ray.direction, si.geometric_normal) < 0.0f;
  if (faces_ray == leaving) {  // entering must face the ray, leaving must face away
    si.geometric_normal = -si.geometric_normal;
    si.shading_normal = -si.shading_normal;
  }
  si.front_face = !leaving;
  si.medium = hit.medium;
}

}  // namespace rt
