#include "core/color.h"

#include <array>
#include <cstring>
#include <vector>

#include "core/math.h"

namespace rt {
namespace {

constexpr uint32_t kOne = 0x3f800000u;  // bit pattern of 1.0f

float from_bits(uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

}  // namespace

// threshold_ by bisection over the float bit patterns of [0, 1] (the formula is monotonic).
Srgb8Table::Srgb8Table() : first_((kOne >> kShift) + 1) {
  for (int v = 1; v < 256; ++v) {
    uint32_t lo = 0, hi = kOne;
    while (lo < hi) {
      const uint32_t mid = lo + (hi - lo) / 2;
      if (srgb8_by_formula(from_bits(mid)) >= v) hi = mid;
      else lo = mid + 1;
    }
    threshold_[static_cast<size_t>(v)] = from_bits(lo);
  }
  threshold_[256] = kInfinity;
  for (uint32_t i = 0; i < first_.size(); ++i) first_[i] = srgb8_by_formula(from_bits(i << kShift));
}

const Srgb8Table& srgb8_table() {
  static const Srgb8Table table;  // immutable after construction (thread-safe static init)
  return table;
}

uint8_t srgb8_by_formula(float linear) { return static_cast<uint8_t>(std::lround(srgb_encode(linear) * 255.0f)); }

}  // namespace rt
