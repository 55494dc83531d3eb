// Eight samples of a stratified grid (StratifiedGrid::point, core/sampling.h) at once, in vector
// registers: a rect light's samples are drawn eight at a time (core/lights/rect_light_batch.h),
// and one by one their two divisions and the stores of each coordinate, which the batch then
// loaded as a vector (no store forwards to a wider load), were a tenth of direct lighting's time
// in soft_shadows.json (docs/benchmark.md, "Round two, an eighteenth session"). Each lane performs
// StratifiedGrid::point's operations: the same floats. Compiled for the baseline and for AVX2
// (core/avx2_clones.h).
#pragma once

#include "core/accel/bvh.h"
#include "core/sampling.h"

namespace rt {

// u[0][j], u[1][j] = grid.point(first + j, (jx[j], jy[j])) for j in [0, kPacketSize): jx and jy
// hold kPacketSize numbers each (those past the samples wanted are worked out too, and ignored);
// first + kPacketSize at most 2^22.
void stratified_points_batch(const StratifiedGrid& grid, int first, const float* jx, const float* jy,
                             float (&u)[2][kPacketSize]);

}  // namespace rt
