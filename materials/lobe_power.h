// A cosine raised to a lobe's exponent (Phong's shininess).
//
// A whole exponent (every shininess in the shipped scenes) is raised by squaring in double
// precision, then rounded once to float: at most 2 x 16 double roundings, whose error (below
// 2^-36 of the value for exponents up to 65536) is far inside a float's half unit, so the float is
// the correctly rounded power in all but a vanishing few cases. glibc's powf is within 0.82 of a
// unit, and was 6% of soft_shadows.json's profile, called one lane at a time; the squarings run on
// a batch's lanes in vector registers (materials/phong_batch.cpp), the same operations lane by
// lane, so a batch gives phong_reflectance's bits (docs/benchmark.md, "Round two, an eighteenth
// session"). Other exponents take std::pow.
//
// Where the power is certainly 0 it is not worked out: glibc's powf returns 0 once exponent x
// log2(c) is at most -150 (below half the smallest denormal) and takes a slow path to do it; the
// squarings would go through denormals. A narrow highlight (shininess 300-400 on the glass and
// mirrors) is asked about far outside its lobe by most light samples (docs/benchmark.md, "Round
// two, a twelfth session").
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rt {

// True when c^exponent (c > 0, a cosine) is certainly below 2^-151, so 0 as a float.
[[gnu::always_inline]] inline bool lobe_power_vanishes(float c, float exponent) {
  if (!(c >= std::numeric_limits<float>::min())) return false;  // a denormal cosine: not decided here
  // c = 2^e (1 + m), m in [0, 1): log2(c) <= e + m / ln 2, as ln(1 + m) <= m; 1.4427 is above
  // 1 / ln 2 = 1.442695. The bound below -151 keeps a margin of 1 over the float rounding of this
  // product (about 1e-4).
  const uint32_t bits = std::bit_cast<uint32_t>(c);
  const float e = static_cast<float>(static_cast<int>(bits >> 23) - 127);
  const float m = static_cast<float>(bits & 0x7fffffu) * 0x1p-23f;
  return exponent * (e + 1.4427f * m) < -151.0f;
}

// The exponents raised by squaring: whole numbers in [1, 65536].
[[gnu::always_inline]] inline bool is_whole_exponent(float exponent) {
  return exponent >= 1.0f && exponent <= 65536.0f && static_cast<float>(static_cast<int32_t>(exponent)) == exponent;
}

// base^n for n >= 1 by squaring, the lowest bits first: for a double, or for a vector of doubles
// (GCC's vector extensions), one lane's operations the same as one number's. Always inline: GCC
// does not inline it into an AVX2 clone otherwise (core/avx2_clones.h).
template <class Real>
[[gnu::always_inline]] inline Real whole_power(Real base, uint32_t n) {
  while (!(n & 1u)) {
    base *= base;
    n >>= 1;
  }
  Real result = base;
  while (n >>= 1) {
    base *= base;
    if (n & 1u) result *= base;
  }
  return result;
}

// c^exponent for c > 0 (a cosine) and any exponent.
inline float lobe_power(float c, float exponent) {
  if (lobe_power_vanishes(c, exponent)) return 0.0f;
  if (is_whole_exponent(exponent))
    return static_cast<float>(whole_power(static_cast<double>(c), static_cast<uint32_t>(exponent)));
  return std::pow(c, exponent);
}

}  // namespace rt
