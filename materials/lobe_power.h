// A cosine raised to a lobe's exponent (Phong's shininess): std::pow's value, bit for bit, without
// calling it where that value is certainly 0. glibc's powf returns 0 once exponent x log2(c) is at
// most -150 (below half the smallest denormal), and takes a slow path to do it (xflowf, 1.4% of
// csg.json's profile): a narrow highlight (shininess 300-400 on the glass and mirrors) is asked
// about far outside its lobe by most light samples (docs/benchmark.md, "Round two, a twelfth
// session").
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rt {

// c^exponent for c > 0 (a cosine) and any exponent.
inline float lobe_power(float c, float exponent) {
  if (c >= std::numeric_limits<float>::min()) {  // normal: c = 2^e (1 + m), m in [0, 1)
    // log2(c) <= e + m / ln 2, as ln(1 + m) <= m; 1.4427 is above 1 / ln 2 = 1.442695. The bound
    // below -151 keeps a margin of 1 over the float rounding of this product (about 1e-4).
    const uint32_t bits = std::bit_cast<uint32_t>(c);
    const float e = static_cast<float>(static_cast<int>(bits >> 23) - 127);
    const float m = static_cast<float>(bits & 0x7fffffu) * 0x1p-23f;
    if (exponent * (e + 1.4427f * m) < -151.0f) return 0.0f;
  }
  return std::pow(c, exponent);
}

}  // namespace rt
