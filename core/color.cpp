#include "core/color.h"

#include <array>
#include <cstring>
#include <vector>

#include "core/math.h"

namespace rt {
namespace {

// threshold[v] = the smallest float whose code is at least v, found by bisection over the float
// bit patterns of [0, 1] (the formula is monotonic). first[i] = the code of the first float of
// bucket i, the floats sharing their top bits (bits >> kShift). A bucket spans at most 1/512 of
// its value, and the formula's codes never step twice that close together, so a code is
// first[bucket] plus one comparison: bit for bit the formula's result, with no pow.
struct Srgb8Table {
  static constexpr int kShift = 14;
  static constexpr uint32_t kOne = 0x3f800000u;  // bit pattern of 1.0f
  std::array<float, 257> threshold{};
  std::vector<uint8_t> first;

  Srgb8Table() : first((kOne >> kShift) + 1) {
    for (int v = 1; v < 256; ++v) {
      uint32_t lo = 0, hi = kOne;
      while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        if (srgb8_by_formula(from_bits(mid)) >= v) hi = mid;
        else lo = mid + 1;
      }
      threshold[static_cast<size_t>(v)] = from_bits(lo);
    }
    threshold[256] = kInfinity;
    for (uint32_t i = 0; i < first.size(); ++i) first[i] = srgb8_by_formula(from_bits(i << kShift));
  }
  static float from_bits(uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }
  uint8_t encode(float linear) const {
    if (!(linear > 0.0f)) return 0;  // also NaN
    if (linear >= 1.0f) return 255;
    uint32_t bits;
    std::memcpy(&bits, &linear, sizeof bits);
    const uint8_t code = first[bits >> kShift];
    return linear >= threshold[code + 1u] ? static_cast<uint8_t>(code + 1) : code;
  }
};

const Srgb8Table& srgb8_table() {
  static const Srgb8Table table;  // immutable after construction (thread-safe static init)
  return table;
}

}  // namespace

uint8_t srgb8(float linear) { return srgb8_table().encode(linear); }

uint8_t srgb8_by_formula(float linear) { return static_cast<uint8_t>(std::lround(srgb_encode(linear) * 255.0f)); }

}  // namespace rt
