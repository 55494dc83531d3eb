// Bounding volume hierarchy over a PrimitiveSet. Scenes use two levels: one BVH per mesh over its
// triangles in object space, built once, and a top level over the analytic shapes, the mesh
// instances and the CSG solids, rebuilt when placements change (each animation frame). Built as a
// binary tree with the binned surface area heuristic, then collapsed into an 8-wide tree: each node
// holds the boxes of up to eight children side by side, so one visit tests eight boxes with one
// SIMD slab test (one AVX instruction per step, two SSE ones). Nodes are a flat array; traversal
// uses a fixed-size stack, visits the nearest child first and skips entries farther than the
// closest hit found since they were pushed. No allocation and no virtual call per ray or primitive:
// the closest-hit and occlusion queries are compiled once per instruction set
// (core/accel/bvh_kernels.h) and the BVH calls the set chosen when it was built, one indirect call
// a query.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/accel/alpha_cutout.h"
#include "core/accel/bvh_kernels.h"
#include "core/accel/isa.h"
#include "core/accel/primitives.h"
#include "core/accel/shadow_volume.h"
#include "core/accel/shape_interiors.h"
#include "core/accel/triangle_quad.h"
#include "core/fill_vector.h"

namespace rt {

// A child reference: an interior node index, or (top bit set) a leaf of `count` primitives: from
// slot `first` of the primitive order, or, for a quad leaf (triangles alone, three or more), in
// the quads from `first` of Bvh::quads(), four a quad. A quad leaf holds its triangles' ids in its
// quads, so that visiting it reads nothing else.
struct BvhRef {
  static constexpr uint32_t kLeafBit = 0x80000000u;
  static constexpr int kCountShift = 27;
  static constexpr uint32_t kMaxLeafCount = 15;
  static constexpr uint32_t kQuadBit = 1u << 26;
  static constexpr uint32_t kMaxFirst = kQuadBit - 1;

  static uint32_t leaf(uint32_t first, uint32_t count) { return kLeafBit | (count << kCountShift) | first; }
  static uint32_t quad_leaf(uint32_t first_quad, uint32_t count) { return leaf(first_quad, count) | kQuadBit; }
  static bool is_leaf(uint32_t ref) { return (ref & kLeafBit) != 0; }
  static bool is_quad_leaf(uint32_t ref) { return (ref & (kLeafBit | kQuadBit)) == (kLeafBit | kQuadBit); }
  static uint32_t first(uint32_t ref) { return ref & kMaxFirst; }
  static uint32_t count(uint32_t ref) { return (ref >> kCountShift) & kMaxLeafCount; }
  static uint32_t quad_count(uint32_t ref) { return (count(ref) + 3) / 4; }
};

// Children per node. The traversal's slab test handles kBvhWidth lanes at once (core/simd.h
// has 4- and 8-lane vectors); docs/benchmark.md compares 4 and 8.
inline constexpr int kBvhWidth = 8;
// Rays per packet (Bvh::intersect_packet, Bvh::occluded_packet): one 8-lane vector.
inline constexpr int kPacketSize = 8;

struct alignas(64) BvhNode {
  // Child boxes as rows of kBvhWidth: lo x, hi x, lo y, hi y, lo z, hi z. An unused slot has an
  // inverted box (lo = +inf, hi = -inf) that no ray can enter.
  float bounds[6][kBvhWidth];
  uint32_t child[kBvhWidth];  // BvhRef values
  // Explicit, so that a zeroed node has every byte set: the tree's bytes are deterministic.
  uint8_t pad[(7 * kBvhWidth * 4 + 63) / 64 * 64 - 7 * kBvhWidth * 4];
};
static_assert(sizeof(BvhNode) % 64 == 0, "a BvhNode fills whole cache lines");

// Whether child slot `slot` of `node` is in use (an unused one's box is inverted).
inline bool child_used(const BvhNode& node, int slot) { return node.bounds[0][slot] <= node.bounds[1][slot]; }

// A few leaves of a BVH: those whose boxes meet a region (Bvh::leaves_meeting). A ray that stays
// inside the region can meet nothing in the other leaves, so these alone answer for it.
struct BvhLeafSet {
  static constexpr int kMax = 4;  // more, and the ray's own walk is as cheap
  uint32_t leaf[kMax];            // BvhRef values, in the order the tree lists them
  int count = 0;
};

struct BvhBuildOptions {
  unsigned threads = 1;  // subtrees are built in parallel; the tree does not depend on this
  // Which compiled traversal the BVH uses (and the mesh BVHs under it): the best this CPU runs
  // unless the caller chose one (rtcli's --isa). The images are the same with any of them.
  Isa isa = best_isa();
};

struct BvhStats {
  size_t nodes = 0;  // kBvhWidth-wide nodes
  size_t leaves = 0;
  int max_depth = 0;  // of the wide tree
  // Of the binary tree it was collapsed from, relative to one node visit; triangles tested four
  // at a time count 1 / kTraversalCost visits a quad (core/accel/bvh_bins.h), a top-level
  // primitive (shape, instance, CSG) two, as the builder counts them.
  double sah_cost = 0.0;
};

class Bvh {
 public:
  Bvh() = default;
  Bvh(const PrimitiveSet& prims, const BvhBuildOptions& options);

  // Closest hit in (ray.tmin, ray.tmax); narrows ray.tmax to it.
  bool intersect(Ray& ray, Hit& hit) const { return kernels_->intersect(*this, ray, hit); }
  // intersect()'s answer for a ray that starts inside primitive `inside` (a refraction into it, a
  // reflection within it), found without the walk where that is a closed shape with few
  // neighbours (core/accel/shape_interiors.h). Any id, a wrong one too, gives intersect()'s answer.
  bool intersect_from_inside(uint32_t inside, Ray& ray, Hit& hit) const;
  // intersect()'s answer for a ray that leaves primitive `from` outwards, without testing `from`
  // where it is an analytic shape: a sphere, box, cylinder or cone is convex and a plane flat, so
  // a ray that leaves one outwards cannot meet it again (the walk's test of it only found that
  // out). The caller vouches for "outwards": a ray into the shape would pass through it.
  bool intersect_leaving(uint32_t from, Ray& ray, Hit& hit) const {
    return from - ranges_.shape_begin < shapes_.size() ? kernels_->intersect_leaving(*this, ray, hit, from)
                                                       : intersect(ray, hit);
  }
  // Closest hit among the triangles `cutout` covers and whose front the ray meets if it is
  // single-sided (a mesh BVH with an alpha mask or a single-sided material).
  bool intersect(Ray& ray, Hit& hit, const AlphaCutout& cutout) const {
    return kernels_->intersect_cutout(*this, ray, hit, cutout);
  }
  // intersect() for count <= kPacketSize rays at once (bit i: rays[i] hit hits[i]), walked
  // together where the instruction set allows: for coherent rays, such as neighbouring camera rays.
  unsigned intersect_packet(Ray* rays, Hit* hits, int count) const {
    return kernels_->intersect_packet(*this, rays, hits, count);
  }
  // Whether anything is hit in (ray.tmin, ray.tmax): stops at the first hit found.
  bool occluded(const Ray& ray) const { return kernels_->occluded(*this, ray); }
  // occluded() for count <= kPacketSize rays at once (bit i: rays[i] is blocked), walked together
  // where the instruction set allows: for coherent rays, such as one point's shadow rays to an
  // area light.
  unsigned occluded_packet(const Ray* rays, int count) const { return kernels_->occluded_packet(*this, rays, count); }
  // Any-hit with a visitor: calls visit(const Hit&) for every crossing in (ray.tmin, ray.tmax)
  // (both crossings of a sphere, say) in no particular order, until it returns true ("stop").
  // Returns whether it was stopped. Defined in core/accel/bvh_traversal.h; include that to use it.
  template <class Visitor>
  bool for_each_hit(const Ray& ray, Visitor&& visit) const;
  // The same walk, in the kernels of the BVH's instruction set, calling visit through a pointer
  // once per crossing: for visitors that see few crossings (shadow rays), where the walk costs far
  // more than the call. Same crossings in the same order as for_each_hit.
  template <class Visitor>
  bool visit_hits(const Ray& ray, Visitor& visit) const {
    return visit_hits_through(
        ray, [](void* v, const Hit& hit) { return (*static_cast<Visitor*>(v))(hit); }, &visit);
  }
  bool visit_hits_through(const Ray& ray, HitVisitorFn visit, void* visitor) const {
    return kernels_->visit_hits(*this, ray, visit, visitor);
  }

  // The leaves whose boxes meet `volume` (core/accel/bvh_volume_query.cpp); false when there are
  // more than BvhLeafSet::kMax. A leaf of planes that no ray inside the volume can cross
  // (ShadowVolume::beside_plane: a floor or a wall under the rays' origin) is left out. Every
  // crossing such a ray can have lies in the leaves found: none, and nothing is in its way.
  bool leaves_meeting(const ShadowVolume& volume, BvhLeafSet& out) const;
  // Calls visit(leaf) for each leaf whose box, and every box above it, `meets` (a test of an
  // Aabb) accepts: depth first, each node's children in their order. Stops when visit returns
  // false, and then returns false.
  template <class Meets, class Visit>
  bool for_each_leaf_meeting(const Meets& meets, const Visit& visit) const;
  // visit_hits() for a ray inside a volume whose only leaf is `leaf`: the same crossings in the
  // same order (a walk would find no other leaf's).
  template <class Visitor>
  bool visit_hits_in_leaf(const Ray& ray, uint32_t leaf, Visitor& visit) const {
    return kernels_->visit_hits_in_leaf(
        *this, ray, leaf, [](void* v, const Hit& hit) { return (*static_cast<Visitor*>(v))(hit); }, &visit);
  }

  // Primitive ids as in the PrimitiveSet it was built from (its triangles are not kept: the
  // BVH holds its own copy in leaf order). A hit on an instance has hit.prim = the instance's
  // id here and hit.part = the triangle's index in its mesh, whether the instance is walked as
  // one or flattened (its triangles the tree's own: every query names their hits so).
  uint32_t primitive_count() const { return ranges_.end; }
  PrimitiveKind kind(uint32_t id) const { return ranges_.kind(id); }
  const AnalyticShape& shape(uint32_t id) const { return shapes_[id - ranges_.shape_begin]; }
  const MeshInstance& instance(uint32_t id) const { return instances_[id - ranges_.instance_begin]; }
  const CsgObject& csg(uint32_t id) const { return csgs_[id - ranges_.csg_begin]; }
  const std::vector<AnalyticShape>& shapes() const { return shapes_; }
  const std::vector<MeshInstance>& instances() const { return instances_; }
  const std::vector<CsgObject>& csgs() const { return csgs_; }
  // A hit on a flattened instance's triangle named as the instance's (prim: the instance's id,
  // part: the triangle in its mesh); any other hit is left as it is. The queries call it.
  void relabel(Hit& hit) const {
    if (hit.prim < owners_.size()) {
      const TriangleOwner& o = owners_[hit.prim];
      hit.part = o.triangle;
      hit.prim = ranges_.instance_begin + o.instance;
    }
  }
  const FillVector<BvhNode>& nodes() const { return nodes_; }
  const std::vector<ShapeInterior>& interiors() const { return interiors_; }
  // The instruction set whose traversal intersect() and occluded() run.
  Isa isa() const { return kernels_->isa; }
  uint32_t root() const { return root_; }
  Aabb bounds() const { return bounds_; }
  BvhStats stats() const;
  // Checks the tree against its primitives: every primitive in exactly one leaf, every child box
  // inside the box that refers to it, nothing deeper than the traversal stack allows. Empty when
  // sound, else what is wrong. For tests and the fuzzer (core/accel/bvh_check.cpp).
  std::string check_structure() const;

  // Deepest binary tree the builder makes; the traversal stack is sized from it.
  static constexpr int kMaxDepth = 64;
  // A constructor argument with bounds that are not finite throws std::invalid_argument; io
  // checks scenes first and reports such objects with their location.

  // What a leaf slot holds: the primitive id and, for a triangle, a copy of its data, so that a
  // leaf's primitives are one contiguous read.
  struct Slot {
    PackedTriangle triangle;  // unused for analytic shapes
    uint32_t id;
  };
  // The world box of the primitive in a leaf slot (a triangle's from the slot's own copy).
  Aabb primitive_bounds(uint32_t id, const Slot& slot) const {
    switch (kind(id)) {
      case PrimitiveKind::kTriangle: return slot.triangle.bounds();
      case PrimitiveKind::kShape: return world_bounds(shape(id));
      case PrimitiveKind::kInstance: return instance(id).bounds;
      case PrimitiveKind::kCsg: return csg(id).bounds();
    }
    return {};
  }
  // The layout the traversal (core/accel/bvh_traversal.h) reads.
  const FillVector<Slot>& slots() const { return slots_; }
  const FillVector<TriangleQuad>& quads() const { return quads_; }  // quad leaves' (BvhRef)
  uint32_t triangle_count() const { return ranges_.shape_begin; }

 private:
  const BvhKernels* kernels_ = &bvh_kernels(Isa::kSse);
  PrimitiveRanges ranges_;
  std::vector<AnalyticShape> shapes_;
  std::vector<MeshInstance> instances_;
  std::vector<CsgObject> csgs_;
  std::vector<TriangleOwner> owners_;  // PrimitiveSet::owners: empty, or one per triangle
  FillVector<BvhNode> nodes_;
  uint32_t root_ = 0;  // BvhRef: node 0, or a single leaf for tiny scenes
  Aabb bounds_;
  double binary_sah_cost_ = 0.0;
  // The leaves' primitives (core/accel/bvh_leaves.cpp): leaves of three or more triangles alone
  // as quads tested four at a time, four a quad, the last one padded; the other leaves' as slots,
  // a triangle copied there, so that leaves read memory in order.
  FillVector<Slot> slots_;
  FillVector<TriangleQuad> quads_;
  std::vector<ShapeInterior> interiors_;  // one per shape, or none (find_shape_interiors)
  // Fills slots_ and quads_ from the primitives in build order (`order`: ids, the leaves' first
  // and count refer to it) and points the leaf references at them.
  void fill_leaves(const PrimitiveSet& prims, const uint32_t* order, unsigned threads);
};

template <class Meets, class Visit>
bool Bvh::for_each_leaf_meeting(const Meets& meets, const Visit& visit) const {
  if (primitive_count() == 0) return true;
  if (BvhRef::is_leaf(root_)) return !meets(bounds_) || visit(root_);
  uint32_t stack[kBvhWidth * kMaxDepth + 4];
  int top = 0;
  stack[top++] = root_;
  while (top > 0) {
    const BvhNode& node = nodes_[stack[--top]];
    for (int c = 0; c < kBvhWidth; ++c) {
      if (!child_used(node, c)) continue;
      const Aabb box{Vec3(node.bounds[0][c], node.bounds[2][c], node.bounds[4][c]),
                     Vec3(node.bounds[1][c], node.bounds[3][c], node.bounds[5][c])};
      if (!meets(box)) continue;
      if (!BvhRef::is_leaf(node.child[c])) {
        stack[top++] = node.child[c];
      } else if (!visit(node.child[c])) {
        return false;
      }
    }
  }
  return true;
}

// A mesh's BVH placed by `transform`: the instance with its world bounds filled in.
MeshInstance place_mesh(const Bvh& mesh_bvh, const Transform& transform, uint32_t mesh, uint32_t material,
                        const AlphaCutout* cutout = nullptr);

}  // namespace rt
