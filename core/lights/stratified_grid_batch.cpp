#include "core/lights/stratified_grid_batch.h"

#include <cstring>

#include "core/avx2_clones.h"
#include "core/simd.h"

namespace rt {

static_assert(kPacketSize == 8, "a batch is one Float8");

RT_AVX2_CLONES
void stratified_points_batch(const StratifiedGrid& grid, int first, const float* jx, const float* jy,
                             float (&u)[2][kPacketSize]) {
  const Float8 cols = splat8(static_cast<float>(grid.cols)), rows = splat8(static_cast<float>(grid.rows));
  const Mask8 index = first + Mask8{0, 1, 2, 3, 4, 5, 6, 7};
  // index / cols, exactly: (index + 0.5) / cols lies at least 0.5 / cols from a whole number, and
  // its rounding moves it by less than that while index + 0.5 < 2^23, so truncation gives the
  // quotient.
  const Mask8 row = __builtin_convertvector((__builtin_convertvector(index, Float8) + 0.5f) / cols, Mask8);
  const Mask8 col = index - row * grid.cols;
  const Float8 x = (__builtin_convertvector(col, Float8) + load8(jx)) / cols;
  const Float8 y = (__builtin_convertvector(row, Float8) + load8(jy)) / rows;
  std::memcpy(u[0], &x, sizeof x);
  std::memcpy(u[1], &y, sizeof y);
}

}  // namespace rt
