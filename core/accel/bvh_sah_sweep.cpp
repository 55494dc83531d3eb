// The SAH sweep over a node's bins (Wald 2007): the bounds and counts of everything on each side
// of every plane, the cost of each plane, the cheapest. The three axes are swept at once, lane a
// of each vector for axis a; a third of a mesh build's binary-tree time went to the sweep when
// it ran one axis at a time. Nodes too large for float areas take the same sweep in double.
#include <algorithm>

#include "core/accel/bvh_bins.h"

namespace rt {
namespace {

// The half areas of three boxes, lane a for box a (lane 3 unused): the operations of
// Box4::half_area in the same order, so each lane is that function's result bit for bit.
Float4 half_areas(const Box4 (&b)[3]) {
  const Float4 e0 = b[0].hi - b[0].lo, e1 = b[1].hi - b[1].lo, e2 = b[2].hi - b[2].lo;
  const Float4 xy = __builtin_shufflevector(e0, e1, 0, 4, 1, 5);  // e0.x e1.x e0.y e1.y
  const Float4 z_ = __builtin_shufflevector(e0, e1, 2, 6, 2, 6);  // e0.z e1.z
  const Float4 x = __builtin_shufflevector(xy, e2, 0, 1, 4, 4);
  const Float4 y = __builtin_shufflevector(xy, e2, 2, 3, 5, 5);
  const Float4 z = __builtin_shufflevector(z_, e2, 0, 1, 6, 6);
  return x * y + y * z + z * x;
}

// leaf_tests of each lane's count, as float (as the scalar sweep converted each): exact, as
// counts stay below 2^26 (BvhRef::kMaxFirst).
Float4 leaf_tests4(Int4 count, uint32_t block) {
  if (block == 4) return __builtin_convertvector((count + 3) >> 2, Float4);
  Float4 tests{};
  for (int a = 0; a < 3; ++a) tests[a] = static_cast<float>(leaf_tests(static_cast<uint32_t>(count[a]), block));
  return tests;
}

Int4 counts(const Bins& bins, int k) {
  return Int4{static_cast<int>(bins[0][k].count), static_cast<int>(bins[1][k].count),
              static_cast<int>(bins[2][k].count), 0};
}

// The sweep in float, all axes at once.
Split sweep(const Bins& bins, int nb, float inv_area, uint32_t block) {
  // From the right: area x leaf tests of everything right of each plane.
  Float4 right_cost[kBins];
  Int4 right_count[kBins];
  Box4 acc[3] = {Box4::empty(), Box4::empty(), Box4::empty()};
  Int4 count{};
  for (int k = nb - 1; k > 0; --k) {
    for (int a = 0; a < 3; ++a) acc[a].extend(bins[a][k].bounds);
    count += counts(bins, k);
    right_cost[k] = half_areas(acc) * leaf_tests4(count, block);
    right_count[k] = count;
  }
  // From the left: each plane's cost, the cheapest (the first of equals) per axis. A plane with an
  // empty side costs infinity, so is never chosen; so is every plane of an axis whose primitives
  // all fall in bin 0 (Binner's scale 0).
  for (Box4& b : acc) b = Box4::empty();
  count = Int4{};
  Float4 best = splat4(kInfinity);
  Int4 best_bin{};
  for (int k = 1; k < nb; ++k) {
    for (int a = 0; a < 3; ++a) acc[a].extend(bins[a][k - 1].bounds);
    count += counts(bins, k - 1);
    const Float4 cost =
        splat4(kTraversalCost) + (half_areas(acc) * leaf_tests4(count, block) + right_cost[k]) * splat4(inv_area);
    const Mask4 better = (count > 0) & (right_count[k] > 0) & (cost < best);
    best = better ? cost : best;
    best_bin = better ? Int4{k, k, k, k} : best_bin;
  }
  Split split;
  for (int a = 0; a < 3; ++a)
    if (best[a] < split.cost) split = Split{a, best_bin[a], best[a], Box4::empty(), Box4::empty()};
  if (split.axis >= 0)
    for (int k = 0; k < nb; ++k)
      (k < split.bin ? split.left_bounds : split.right_bounds).extend(bins[split.axis][k].bounds);
  return split;
}

// The sweep in double, one axis at a time, for nodes whose float area overflows (extents beyond
// ~1.8e19): every box inside such a node has a finite double area.
Split sweep_wide(const Bins& bins, int nb, double inv_area, uint32_t block) {
  Split best;
  for (int a = 0; a < 3; ++a) {
    Box4 right_bounds[kBins];
    uint32_t right_count[kBins];
    Box4 acc = Box4::empty();
    uint32_t count = 0;
    for (int k = nb - 1; k > 0; --k) {
      acc.extend(bins[a][k].bounds);
      count += bins[a][k].count;
      right_bounds[k] = acc;
      right_count[k] = count;
    }
    acc = Box4::empty();
    count = 0;
    for (int k = 1; k < nb; ++k) {
      acc.extend(bins[a][k - 1].bounds);
      count += bins[a][k - 1].count;
      if (count == 0 || right_count[k] == 0) continue;
      const double cost = kTraversalCost + (acc.half_area_wide() * leaf_tests(count, block) +
                                            right_bounds[k].half_area_wide() * leaf_tests(right_count[k], block)) *
                                               inv_area;
      if (cost < best.cost) best = Split{a, k, cost, acc, right_bounds[k]};
    }
  }
  return best;
}

}  // namespace

Split sah_sweep(const Bins& bins, int count, const Box4& bounds, uint32_t block) {
  // Every box below is inside the node's: if its float area is finite, so are theirs.
  const float area = bounds.half_area();
  if (std::isfinite(area)) return sweep(bins, count, 1.0f / std::max(area, 1e-30f), block);
  return sweep_wide(bins, count, 1.0 / std::max(bounds.half_area_wide(), 1e-300), block);
}

}  // namespace rt
