// The binned SAH's bins and the sweep that finds a node's cheapest split in them
// (core/accel/bvh_build.cpp bins, core/accel/bvh_sah_sweep.cpp sweeps). Internal to core/accel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/accel/bvh_binary_tree.h"
#include "core/simd.h"

namespace rt {

constexpr int kBins = 32;
// A node visit's cost, in triangle quad tests (the SAH's unit). A visit reads four cache lines to
// a quad's three and tests eight boxes: at 1.5 (and at 2, no faster) the stone's incoherent rays
// ran 1.03x and its shadow and camera rays 1.015x what they did at 1 (docs/benchmark.md, "Round
// two, a twentieth session"); at 0.7, 0.93x.
constexpr float kTraversalCost = 1.5f;

// What testing one top-level primitive costs: two node visits (kTraversalCost each). An analytic
// shape carries the ray into its object space (18 multiplies) before its own test, a mesh
// instance does that and walks its BVH, a CSG solid finds every operand's spans; one node visit
// tests eight boxes at once.
// Counted as 1 (a triangle's cost), the SAH kept the Cornell box's five walls and two blocks in
// one leaf, whose flat boxes a split separates: every ray tested all seven. At 2 the path-traced
// box renders in 0.70x the time (the same bytes: the closest hit does not depend on the tree; 4
// and 8 were no faster), other shipped scenes unchanged (docs/benchmark.md). A shadow ray through
// glass multiplies its crossings' transmittances in the tree's order, which may round apart by
// an ulp: panorama.json moved by at most 1 level in a few pixels.
constexpr double kObjectTestCost = 2.0 * kTraversalCost;

// A leaf's cost in quad tests: `block` primitives a test (4: a mesh's triangles, as quads), or
// one primitive a test (block 1: a set holding shapes, instances or CSG solids).
inline double leaf_tests(uint32_t count, uint32_t block) {
  if (block == 1) return kObjectTestCost * count;
  return static_cast<double>((count + block - 1) / block);
}

// No default member initialisers: arrays of bins are filled only as far as a node needs.
struct Box4 {
  Float4 lo, hi;
  static Box4 empty() { return Box4{splat4(kInfinity), splat4(-kInfinity)}; }
  void extend(Float4 l, Float4 h) {
    lo = min4(lo, l);
    hi = max4(hi, h);
  }
  void extend(const Box4& b) { extend(b.lo, b.hi); }
  float half_area() const {
    const Float4 e = hi - lo;
    return e[0] < 0.0f ? 0.0f : e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
  }
  // In double: extents up to 2 x 3.4e38 and their products stay finite. For nodes whose float
  // area overflows (extents beyond ~1.8e19), so that SAH costs stay comparable there too.
  double half_area_wide() const { return rt::half_area(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]); }
  Aabb aabb() const { return Aabb{Vec3(lo[0], lo[1], lo[2]), Vec3(hi[0], hi[1], hi[2])}; }
};

// Maps centroids to bins: bin = min(count - 1, (c/2 - lo/2) * scale), per axis at once. Halved
// coordinates make every difference finite (|c/2 - lo/2| <= 3.4e38) for any finite input, so
// the product is a finite number in [0, count] and the clamp happens before the conversion to
// int: no NaN or infinity can become an out-of-range bin. An axis whose centroids (nearly)
// coincide gets scale 0: everything lands in bin 0 and the axis is not split. Small nodes get
// fewer bins: with a handful of primitives, more bins than primitives only costs time.
struct Binner {
  Float4 half_lo, scale, last;
  int count;
  Binner(const Box4& centroids, uint32_t prims)
      : half_lo(splat4(0.5f) * centroids.lo), count(static_cast<int>(std::clamp<uint32_t>(prims, 4, kBins))) {
    const Float4 half_extent = splat4(0.5f) * centroids.hi - half_lo;
    for (int a = 0; a < 3; ++a) {
      const float s = half_extent[a] > 0.0f ? static_cast<float>(count) / half_extent[a] : 0.0f;
      scale[a] = std::isfinite(s) ? s : 0.0f;
    }
    scale[3] = 0.0f;
    last = splat4(static_cast<float>(count - 1));
  }
  Int4 bins(Float4 c) const { return __builtin_convertvector(min4((splat4(0.5f) * c - half_lo) * scale, last), Int4); }
};

struct Bin {
  Box4 bounds;
  uint32_t count;
};
using Bins = Bin[3][kBins];  // [axis][bin]

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin) go left
  double cost = kInfinity;
  Box4 left_bounds = Box4::empty(), right_bounds = Box4::empty();
};

// The cheapest split between the first `count` bins of `bins`, by the SAH: a node visit plus
// each side's leaf_tests(..., block) weighted by its share of `bounds`' area. Planes with an
// empty side are skipped; equal costs go to the lowest axis, then the lowest plane. axis -1 when
// no plane separates two primitives (every axis's primitives share one bin).
Split sah_sweep(const Bins& bins, int count, const Box4& bounds, uint32_t block);

}  // namespace rt
