// Rays traced, by kind. Each thread counts its own and the renderer sums them at the end,
// so counting costs no synchronisation.
#pragma once

#include <cstdint>

namespace rt {

struct RayCounters {
  uint64_t camera = 0;
  uint64_t shadow = 0;
  uint64_t secondary = 0;  // reflection, refraction, glossy

  uint64_t total() const { return camera + shadow + secondary; }
  RayCounters& operator+=(const RayCounters& o) {
    camera += o.camera;
    shadow += o.shadow;
    secondary += o.secondary;
    return *this;
  }
};

}  // namespace rt
