// Rays traced, by kind. Each thread counts its own and the renderer sums them at the end,
// so counting costs no synchronisation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace rt {

// kBounce: the path tracer's rays after the camera ray, whatever lobe sent them.
enum class RayKind : uint8_t { kCamera, kShadow, kReflection, kRefraction, kGlossy, kBounce };
inline constexpr size_t kRayKindCount = 6;
// Names as printed in summaries and `rtcli bench`, in RayKind order.
inline constexpr std::array<const char*, kRayKindCount> kRayKindNames = {"camera",     "shadow", "reflection",
                                                                         "refraction", "glossy", "bounce"};

struct RayCounters {
  std::array<uint64_t, kRayKindCount> count{};
  // Camera samples whose radiance was not a finite, non-negative colour: dropped (counted as
  // black) before the film. The path tracer's tests require 0.
  uint64_t invalid_samples = 0;

  uint64_t& operator[](RayKind k) { return count[static_cast<size_t>(k)]; }
  uint64_t operator[](RayKind k) const { return count[static_cast<size_t>(k)]; }
  uint64_t total() const {
    uint64_t sum = 0;
    for (const uint64_t c : count) sum += c;
    return sum;
  }
  RayCounters& operator+=(const RayCounters& o) {
    for (size_t i = 0; i < kRayKindCount; ++i) count[i] += o.count[i];
    invalid_samples += o.invalid_samples;
    return *this;
  }
};

}  // namespace rt
