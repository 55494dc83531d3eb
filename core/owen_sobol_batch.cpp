#include "core/owen_sobol_batch.h"

#include "core/avx2_clones.h"
#include "core/owen_sobol.h"
#include "core/rng.h"

namespace rt {
namespace {

// 8K pairs as K eight-lane vectors, each step taken for all K before the next: their chains of
// dependent multiplies overlap (the lanes past `count` computed from key 0, not stored).
template <int K>
[[gnu::always_inline]] inline void pairs(uint64_t point_key, const uint64_t* dimension, int count,
                                         uint32_t reversed_sample, float* x, float* y) {
  Uint8 shuffle_seed[K], x_seed[K], y_seed[K], shuffled[K], xs[K], ys[K];
  for (int v = 0; v < K; ++v)
    for (int j = 0; j < 8; ++j) {
      const int lane = 8 * v + j;
      const uint64_t h = mix64(point_key ^ (lane < count ? dimension[lane] : 0));
      shuffle_seed[v][j] = static_cast<uint32_t>(h);
      x_seed[v][j] = static_cast<uint32_t>(h >> 32);
      y_seed[v][j] = static_cast<uint32_t>(mix64(h));
    }
  for (int v = 0; v < K; ++v) shuffled[v] = shuffled_index(Uint8{} + reversed_sample, shuffle_seed[v]);
  for (int v = 0; v < K; ++v) {
    xs[v] = owen_sobol_x_bits(shuffled[v], x_seed[v]) >> 8;
    ys[v] = owen_sobol_y_bits(shuffled[v], y_seed[v]) >> 8;
  }
  for (int lane = 0; lane < count; ++lane) {  // unit_float's conversion
    x[lane] = static_cast<float>(xs[lane / 8][lane % 8]) * 0x1p-24f;
    y[lane] = static_cast<float>(ys[lane / 8][lane % 8]) * 0x1p-24f;
  }
}

}  // namespace

// No AVX-512 clone: GCC's code for it (512-bit multiplies, as one 16-lane vector or two 8-lane
// ones) made csg.json 1.09x the time of AVX2's.
RT_AVX2_CLONES
void owen_sobol_pairs(uint64_t point_key, const uint64_t* dimension, int count, uint32_t reversed_sample, float* x,
                      float* y) {
  if (count <= 8) pairs<1>(point_key, dimension, count, reversed_sample, x, y);
  else pairs<2>(point_key, dimension, count, reversed_sample, x, y);
}

}  // namespace rt
