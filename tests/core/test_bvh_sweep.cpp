// The SAH sweep (core/accel/bvh_sah_sweep.cpp) sweeps three axes at once in vector lanes; it must
// choose exactly what the scalar sweep, one axis at a time, chooses: the same plane, the same
// cost to the bit, the same side bounds. Random bins of every count, empty ones among them, and
// ties, for both leaf blocks.
#include <catch2/catch.hpp>

#include "core/accel/bvh_bins.h"
#include "core/rng.h"

using namespace rt;

namespace {

// The sweep as it was written before it went to vectors: float areas, one axis at a time.
Split scalar_sweep(const Bins& bins, int nb, const Box4& bounds, uint32_t block) {
  Split best;
  const float inv_area = 1.0f / std::max(bounds.half_area(), 1e-30f);
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
      const double cost =
          kTraversalCost + (acc.half_area() * static_cast<float>(leaf_tests(count, block)) +
                            right_bounds[k].half_area() * static_cast<float>(leaf_tests(right_count[k], block))) *
                               inv_area;
      if (cost < best.cost) best = Split{a, k, cost, acc, right_bounds[k]};
    }
  }
  return best;
}

bool same_box(const Box4& a, const Box4& b) {
  for (int i = 0; i < 3; ++i)
    if (a.lo[i] != b.lo[i] || a.hi[i] != b.hi[i]) return false;
  return true;
}

}  // namespace

TEST_CASE("SAH sweep: three axes at once choose what one axis at a time chooses", "[bvh][sweep]") {
  Rng rng(42);
  int splits = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int nb = 4 + static_cast<int>(rng.next_float() * (kBins - 3)) % (kBins - 3);
    const uint32_t block = trial % 2 ? 4 : 1;
    // Coarse coordinates make equal areas, so equal costs, common: ties must go the same way.
    const bool coarse = trial % 3 == 0;
    Bins bins;
    Box4 bounds = Box4::empty();
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < nb; ++k) {
        Bin& b = bins[a][k];
        b.bounds = Box4::empty();
        b.count = rng.next_float() < 0.3f ? 0 : 1 + static_cast<uint32_t>(rng.next_float() * 40.0f);
        if (trial % 7 == 0 && a == 1) b.count = k == 0 ? 50 : 0;  // an axis that cannot split
        if (b.count == 0) continue;
        Float4 lo, hi;
        for (int i = 0; i < 3; ++i) {
          float x = rng.next_float() * 10.0f, y = rng.next_float() * 10.0f;
          if (coarse) x = std::floor(x), y = std::floor(y) + 1.0f;
          lo[i] = std::min(x, y);
          hi[i] = std::max(x, y);
        }
        lo[3] = hi[3] = 0.0f;
        b.bounds.extend(lo, hi);
        bounds.extend(b.bounds);
      }
    if (bounds.lo[0] > bounds.hi[0]) continue;  // every bin empty
    const Split want = scalar_sweep(bins, nb, bounds, block);
    const Split got = sah_sweep(bins, nb, bounds, block);
    INFO("trial " << trial << " bins " << nb << " block " << block);
    REQUIRE(got.axis == want.axis);
    if (want.axis < 0) continue;
    ++splits;
    REQUIRE(got.bin == want.bin);
    REQUIRE(got.cost == want.cost);
    REQUIRE(same_box(got.left_bounds, want.left_bounds));
    REQUIRE(same_box(got.right_bounds, want.right_bounds));
  }
  CHECK(splits > 3000);
}
