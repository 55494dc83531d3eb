// One CSG solid as the top-level BVH holds it: a tree of operations over operands, flattened in
// prefix order, and the operand surfaces (analytic shapes and placed closed meshes) in world
// placement. The BVH sees one primitive with the tree's bound; a ray that reaches it is answered
// by span lists along its whole line (core/csg/csg_spans.h), so a ray that starts inside the
// solid (a refracted ray in a lens) finds the right boundary; operands the line meets only
// outside the ray's interval are left out (CsgReach). Built per frame by the scene graph,
// read-only afterwards; a query allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "core/csg/csg_child_index.h"
#include "core/csg/csg_spans.h"
#include "core/hit.h"
#include "core/mesh.h"
#include "core/mesh_instance.h"
#include "core/shapes/analytic_shape.h"

namespace rt {

// An operand's surface: an analytic shape, or a closed mesh placed in the world.
struct CsgSurface {
  bool is_mesh = false;
  AnalyticShape shape;                      // material and transform (used when !is_mesh)
  MeshInstance mesh;                        // used when is_mesh: no alpha cutout (an operand is a closed solid)
  const TriangleMesh* triangles = nullptr;  // the mesh's own, to tell entering from leaving crossings

  uint32_t material() const { return is_mesh ? mesh.material : shape.material; }
  Aabb bounds() const { return is_mesh ? mesh.bounds : world_bounds(shape); }
  const Transform& transform() const { return is_mesh ? mesh.transform : shape.transform; }
};

struct CsgNode {
  bool leaf = false;
  CsgOp op = CsgOp::kUnion;              // an operation's
  uint32_t end = 0;                      // one past the last node of this subtree
  uint32_t first_surface = 0;            // a leaf's surfaces: [first_surface, first_surface + surface_count)
  uint32_t surface_count = 0;            // a shape has one; a mesh operand one per primitive
  Aabb bounds;                           // a little wider than exact, so rounding never drops a span
  uint32_t child_index = kNoChildIndex;  // an operation of many children: its CsgChildIndex

  static constexpr uint32_t kNoChildIndex = ~0u;
};

class CsgObject {
 public:
  // Nesting the tree may have (io refuses deeper trees): each level holds two span lists on the
  // stack while a ray is answered.
  static constexpr int kMaxDepth = 16;

  // Building, in prefix order: open(op) ... operands ... close(index); a leaf is begin_leaf(),
  // its surfaces, close(index). Then finish() computes the bounds, and the child indices of
  // operations with many children (`index_children`: false only to test them against the plain walk).
  uint32_t open(CsgOp op);
  uint32_t begin_leaf();
  void add_surface(const CsgSurface& s);
  void close(uint32_t node);
  void finish(bool index_children = true);

  const std::vector<CsgNode>& nodes() const { return nodes_; }
  const std::vector<CsgSurface>& surfaces() const { return surfaces_; }
  const CsgSurface& surface(uint32_t i) const { return surfaces_[i]; }
  // Empty when the solid is (an intersection of operands that do not meet).
  Aabb bounds() const { return nodes_.empty() ? Aabb{} : nodes_[0].bounds; }
  // At least origin_rounding(surface's transform, ray.origin, ...) for every operand surface:
  // a boundary past ray.tmin by more is in reach without asking its surface (the rounding's
  // bound, ||e|| / ||d_object||, with e's terms and d_object's stretch bounded by the matrices'
  // Frobenius norms, and twice that for the float arithmetic of both). Infinite for a zero
  // direction. Once per ray: csg_boundary_in_reach asks the surface only inside it.
  float rounding_bound(const Ray& ray) const;

  // The solid's spans along the whole line of `ray` (its interval ignored).
  void spans(const Ray& ray, CsgSpanList& out) const;
  // Spans whose boundaries in ray's interval are exactly those of spans(): operands the line
  // meets only outside it are left out (CsgReach), so spans wholly outside may be missing or
  // differ. What a ray's hits and crossings need, for less work than the whole line.
  void spans_in_reach(const Ray& ray, CsgSpanList& out) const;

 private:
  void node_spans(uint32_t node, const CsgReach& reach, CsgSpanList& out) const;
  void leaf_spans(const CsgNode& leaf, const Ray& line, CsgSpanList& out) const;

  std::vector<CsgNode> nodes_;
  std::vector<CsgSurface> surfaces_;
  // rounding_bound's factors, the largest over the surfaces (finish): ||L_object|| ||L_world||
  // and |T_object| ||L_world||, L the linear parts and T the translation.
  float rounding_linear_ = 0.0f, rounding_translation_ = 0.0f;
  std::vector<CsgChildIndex> child_indices_;
};

// Hit records of a CSG solid: hit.part, b1, b2 are the operand surface's own; hit.operand is
// the surface index times two, plus one when the ray leaves the solid there; hit.medium the
// material inside.
inline uint32_t csg_operand(uint32_t surface, bool leaving) { return surface * 2u + (leaving ? 1u : 0u); }
inline uint32_t csg_surface_index(const Hit& hit) { return hit.operand / 2u; }
inline bool csg_leaving(const Hit& hit) { return (hit.operand & 1u) != 0; }

// The hit record of boundary `b` of solid `id` (the one place a CSG hit is built): entering or
// leaving the solid there, `medium` the material inside the span.
inline Hit csg_hit(const CsgBoundary& b, bool leaving, uint32_t medium, uint32_t id) {
  Hit hit;
  hit.t = b.t;
  hit.prim = id;
  hit.part = b.part;
  hit.b1 = b.b1;
  hit.b2 = b.b2;
  hit.operand = csg_operand(b.surface, leaving);
  hit.medium = medium;
  return hit;
}

// The nearest boundary of the solid in (ray.tmin, ray.tmax); on a hit fills `hit` (not its prim)
// and leaves ray.tmax alone.
bool intersect_csg(const CsgObject& csg, const Ray& ray, Hit& hit);

// Whether boundary b lies inside the ray's interval from its start: beyond ray.tmin and beyond
// the rounding of the ray's origin in the space of b's operand. The spans are found along the
// whole line, so this is where the rule object_ray applies to one shape (core/transform.h) is
// applied: a ray leaving the solid's surface must not find it again on this side of the
// rounding. Worked out per boundary, and only past ray.tmin: a die with 21 pips has 22 spaces.
// `bound`: csg.rounding_bound(ray), or more; boundaries past ray.tmin + bound need no surface.
bool csg_boundary_in_reach(const CsgObject& csg, const CsgBoundary& b, const Ray& ray, float bound = kInfinity);

// Calls visit(hit) for each boundary in reach before ray.tmax, nearest first (equal distances in
// the list's order), with hit.prim = id. Returns true when the visitor asked to stop.
// A union's spans overlap, so its boundaries are not in order along the list: they are sorted
// here, which also makes the order independent of the operands the reach leaves out (a merged
// span's entry behind the ray moves with them).
template <class Visitor>
bool visit_csg_crossings(const CsgObject& csg, uint32_t id, const Ray& ray, Visitor& visit) {
  CsgSpanList spans;
  csg.spans_in_reach(ray, spans);
  const float bound = csg.rounding_bound(ray);
  struct Crossing {
    const CsgSpan* span;
    bool leaving;
    float t() const { return leaving ? span->out.t : span->in.t; }
  };
  Crossing crossings[2 * CsgSpanList::kCapacity];
  int count = 0;
  for (const CsgSpan& s : spans) {
    if (s.in.t >= ray.tmax) break;
    for (int leaving = 0; leaving < 2; ++leaving) {
      const CsgBoundary& b = leaving ? s.out : s.in;
      if (!(b.t < ray.tmax) || !csg_boundary_in_reach(csg, b, ray, bound)) continue;
      // Insertion in order: a normal list's boundaries come in order, and stay where they are.
      int k = count++;
      for (; k > 0 && crossings[k - 1].t() > b.t; --k) crossings[k] = crossings[k - 1];
      crossings[k] = Crossing{&s, leaving != 0};
    }
  }
  for (int k = 0; k < count; ++k) {
    const CsgSpan& s = *crossings[k].span;
    const bool leaving = crossings[k].leaving;
    if (visit(csg_hit(leaving ? s.out : s.in, leaving, s.medium, id))) return true;
  }
  return false;
}

// Turns an operand surface's record at a CSG boundary to face out of the solid: towards the ray
// where it enters, away where it leaves (a subtracted operand's surface, seen from inside the
// result, is flipped); then sets the medium.
void orient_csg_surface(SurfaceInteraction& si, const Ray& ray, const Hit& hit);

}  // namespace rt
