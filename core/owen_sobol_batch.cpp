#include "core/owen_sobol_batch.h"

#include <cstring>

#include "core/avx2_clones.h"
#include "core/owen_sobol.h"
#include "core/rng.h"

namespace rt {
namespace {

typedef uint64_t Uint64x4 __attribute__((vector_size(32)));
typedef int32_t Int32x8 __attribute__((vector_size(32)));
typedef float Floatx8 __attribute__((vector_size(32)));

// The low (high) 32 bits of the eight 64-bit lanes of a and b, in lane order (little-endian: the
// low half first).
inline Uint8 low_halves(Uint64x4 a, Uint64x4 b) {
  return __builtin_shufflevector((Uint8)a, (Uint8)b, 0, 2, 4, 6, 8, 10, 12, 14);
}
inline Uint8 high_halves(Uint64x4 a, Uint64x4 b) {
  return __builtin_shufflevector((Uint8)a, (Uint8)b, 1, 3, 5, 7, 9, 11, 13, 15);
}

// 8K pairs as K eight-lane vectors, each step taken for all K before the next: their chains of
// dependent multiplies overlap (the lanes past `count` computed from key 0, not stored). The
// seeds' 64-bit mixes too, four lanes a vector: one lane at a time, they and the lanes' inserts
// were a third of the time here.
template <int K>
[[gnu::always_inline]] inline void pairs(uint64_t point_key, const uint64_t* dimension, int count,
                                         uint32_t reversed_sample, float* x, float* y) {
  uint64_t keys[8 * K];  // (a loop: zeroing and memcpy were a string store and a library call)
  for (int lane = 0; lane < 8 * K; ++lane) keys[lane] = lane < count ? dimension[lane] : 0;
  Uint8 shuffle_seed[K], x_seed[K], y_seed[K], shuffled[K], xs[K], ys[K];
  for (int v = 0; v < K; ++v) {
    Uint64x4 h[2], g[2];
    for (int half = 0; half < 2; ++half) {
      Uint64x4 key;
      std::memcpy(&key, keys + 8 * v + 4 * half, sizeof key);
      h[half] = splitmix64_finaliser(key ^ point_key);  // get2's h
      g[half] = splitmix64_finaliser(h[half]);
    }
    shuffle_seed[v] = low_halves(h[0], h[1]);
    x_seed[v] = high_halves(h[0], h[1]);
    y_seed[v] = low_halves(g[0], g[1]);
  }
  for (int v = 0; v < K; ++v) shuffled[v] = shuffled_index(Uint8{} + reversed_sample, shuffle_seed[v]);
  for (int v = 0; v < K; ++v) {
    xs[v] = owen_sobol_x_bits(shuffled[v], x_seed[v]) >> 8;
    ys[v] = owen_sobol_y_bits(shuffled[v], y_seed[v]) >> 8;
  }
  // unit_float's conversion, eight lanes at once (exact: the values are below 2^24).
  float xf[8 * K], yf[8 * K];
  for (int v = 0; v < K; ++v) {
    const Floatx8 xv = __builtin_convertvector((Int32x8)xs[v], Floatx8) * 0x1p-24f;
    const Floatx8 yv = __builtin_convertvector((Int32x8)ys[v], Floatx8) * 0x1p-24f;
    std::memcpy(xf + 8 * v, &xv, sizeof xv);
    std::memcpy(yf + 8 * v, &yv, sizeof yv);
  }
  if (count == 8 * K) {  // whole vectors: a caller loading them as vectors waits on no narrow store
    std::memcpy(x, xf, sizeof xf);
    std::memcpy(y, yf, sizeof yf);
    return;
  }
  for (int lane = 0; lane < count; ++lane) {
    x[lane] = xf[lane];
    y[lane] = yf[lane];
  }
}

}  // namespace

// With x86-64-v4's clone the seeds' 64-bit multiplies are one instruction each (vpmullq on 4-lane
// registers): soft_shadows.json 0.97x the time of AVX2's on an AMD EPYC, csg.json the same
// (docs/benchmark.md, "Round two, an eighteenth session"). An AVX-512 clone without DQ and VL,
// its multiplies on 512-bit registers, had made csg.json 1.09x.
RT_AVX2_V4_CLONES
void owen_sobol_pairs(uint64_t point_key, const uint64_t* dimension, int count, uint32_t reversed_sample, float* x,
                      float* y) {
  if (count <= 8) pairs<1>(point_key, dimension, count, reversed_sample, x, y);
  else pairs<2>(point_key, dimension, count, reversed_sample, x, y);
}

}  // namespace rt
