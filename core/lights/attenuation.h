// The proposal's quadratic attenuation, shared by every light: radiance arriving at distance d
// is divided by c0 + c1 d + c2 d^2.
#pragma once

namespace rt {

struct Attenuation {
  float c0 = 1.0f, c1 = 0.0f, c2 = 0.0f;

  float operator()(float distance) const { return 1.0f / (c0 + distance * (c1 + distance * c2)); }
};

}  // namespace rt
