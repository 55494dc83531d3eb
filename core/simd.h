// Four and eight floats processed at once, written with GCC/Clang vector extensions: portable C++
// that the compiler maps to whatever the translation unit is built for (two SSE registers or one
// AVX register for eight lanes, NEON on ARM), without intrinsics in the algorithms. Each lane is
// plain IEEE arithmetic, so every instruction set gives the same bits.
#pragma once

#include <cstdint>
#include <cstring>

// Always inlined: these are compiled into the kernels of each instruction set
// (core/accel/bvh_kernels.h), and an out-of-line copy built with AVX flags could be the one the
// linker keeps for baseline callers. (An 8-float vector is also passed in different registers
// with and without AVX, which GCC's -Wpsabi note is about: never an issue for code that is
// always inlined.)
#define RT_SIMD_INLINE inline __attribute__((always_inline))

namespace rt {

typedef float Float4 __attribute__((vector_size(16)));
typedef int32_t Mask4 __attribute__((vector_size(16)));
typedef int32_t Int4 __attribute__((vector_size(16)));  // whole numbers, as the BVH builder's bins
typedef float Float8 __attribute__((vector_size(32)));
typedef int32_t Mask8 __attribute__((vector_size(32)));

RT_SIMD_INLINE Float4 load4(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
RT_SIMD_INLINE Float4 splat4(float x) { return Float4{x, x, x, x}; }
RT_SIMD_INLINE Float4 min4(Float4 a, Float4 b) { return a < b ? a : b; }
RT_SIMD_INLINE Float4 max4(Float4 a, Float4 b) { return a > b ? a : b; }
// |v|, lane by lane: the sign bit cleared, as std::fabs.
RT_SIMD_INLINE Float4 abs4(Float4 v) { return reinterpret_cast<Float4>(reinterpret_cast<Mask4>(v) & 0x7fffffff); }

// Bit i set when lane i of the mask is true (one movmskps on x86).
RT_SIMD_INLINE unsigned movemask4(Mask4 m) {
#if defined(__SSE__)
  return static_cast<unsigned>(__builtin_ia32_movmskps(reinterpret_cast<Float4>(m)));
#else
  return (m[0] ? 1u : 0u) | (m[1] ? 2u : 0u) | (m[2] ? 4u : 0u) | (m[3] ? 8u : 0u);
#endif
}

RT_SIMD_INLINE Float8 load8(const float* p) {
  Float8 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
RT_SIMD_INLINE Float8 splat8(float x) { return Float8{x, x, x, x, x, x, x, x}; }
RT_SIMD_INLINE Float8 min8(Float8 a, Float8 b) { return a < b ? a : b; }
RT_SIMD_INLINE Float8 max8(Float8 a, Float8 b) { return a > b ? a : b; }

// Correctly rounded square roots, lane by lane (sqrtps: the same bits as std::sqrt).
RT_SIMD_INLINE Float8 sqrt8(Float8 v) {
#if defined(__AVX__)
  return __builtin_ia32_sqrtps256(v);
#elif defined(__SSE__)
  // The halves taken apart and put together in registers: through memory, an AVX2 clone
  // (core/avx2_clones.h, which compiles this branch) loaded the whole from two half-width stores,
  // a load no store forwards to (a third of rect_light_batch's time waited on it).
  const Float4 lo = __builtin_shufflevector(v, v, 0, 1, 2, 3), hi = __builtin_shufflevector(v, v, 4, 5, 6, 7);
  return __builtin_shufflevector(__builtin_ia32_sqrtps(lo), __builtin_ia32_sqrtps(hi), 0, 1, 2, 3, 4, 5, 6, 7);
#else
  for (int i = 0; i < 8; ++i) v[i] = __builtin_sqrtf(v[i]);
  return v;
#endif
}

// |v|, lane by lane: the sign bit cleared, as std::fabs.
RT_SIMD_INLINE Float8 abs8(Float8 v) { return reinterpret_cast<Float8>(reinterpret_cast<Mask8>(v) & 0x7fffffff); }

// Bit i set when lane i is true: one vmovmskps with AVX, two movmskps without.
RT_SIMD_INLINE unsigned movemask8(Mask8 m) {
#if defined(__AVX__)
  return static_cast<unsigned>(__builtin_ia32_movmskps256(reinterpret_cast<Float8>(m)));
#else
  const Mask4 lo = __builtin_shufflevector(m, m, 0, 1, 2, 3), hi = __builtin_shufflevector(m, m, 4, 5, 6, 7);
  return movemask4(lo) | (movemask4(hi) << 4);
#endif
}

}  // namespace rt
