// Four floats processed at once, written with GCC/Clang vector extensions: portable C++ that
// compiles to SSE on x86-64 and NEON on ARM, without intrinsics in the algorithms.
#pragma once

#include <cstdint>
#include <cstring>

namespace rt {

typedef float Float4 __attribute__((vector_size(16)));
typedef int32_t Mask4 __attribute__((vector_size(16)));

inline Float4 load4(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline Float4 splat4(float x) { return Float4{x, x, x, x}; }
inline Float4 min4(Float4 a, Float4 b) { return a < b ? a : b; }
inline Float4 max4(Float4 a, Float4 b) { return a > b ? a : b; }

// Bit i set when lane i of the mask is true (one movmskps on x86).
inline unsigned movemask4(Mask4 m) {
#if defined(__SSE__)
  return static_cast<unsigned>(__builtin_ia32_movmskps(reinterpret_cast<Float4>(m)));
#else
  return (m[0] ? 1u : 0u) | (m[1] ? 2u : 0u) | (m[2] ? 4u : 0u) | (m[3] ? 8u : 0u);
#endif
}

}  // namespace rt
