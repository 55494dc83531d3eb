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
    const auto reaches = [v](uint32_t bits) { return srgb8_by_formula(from_bits(bits)) >= v; };
    uint32_t lo = 0, hi = kOne;
    while (lo < hi) {
      const uint32_t mid = lo + (hi - lo) / 2;
      if (reaches(mid)) hi = mid;
      else lo = mid + 1;
    }
    threshold_[static_cast<size_t>(v)] = from_bits(lo);
  }
  threshold_[256] = kInfinity;
  // A bucket's first code from the thresholds (the largest v whose threshold it reaches), not
  // the formula: 65,025 pow calls took 0.7 ms of every PNG render's first encode.
  uint32_t code = 0;
  for (uint32_t i = 0; i < first_.size(); ++i) {
    const float x = from_bits(i << kShift);
    while (code < 255 && x >= threshold_[code + 1u]) ++code;
    first_[i] = static_cast<uint8_t>(code);
  }
}

const Srgb8Table& srgb8_table() {
  static const Srgb8Table table;  // immutable after construction (thread-safe static init)
  return table;
}

uint8_t srgb8_by_formula(float linear) { return static_cast<uint8_t>(std::lround(srgb_encode(linear) * 255.0f)); }

}  // namespace rt
