// Which light of the scene's list (core/render/scene_lights.h: the scene's lights, its emissive
// surfaces as one, the sky) a shading point samples. With a few, the path tracer samples every
// one at every bounce; with more than kSampleEach, one drawn by power (what each can deliver to
// the scene), so that a scene of a hundred lamps costs one shadow ray a bounce, spent mostly on
// the bright ones, and its estimate divided by the light's probability stays unbiased.
#pragma once

#include <cstddef>
#include <vector>

#include "core/aabb.h"
#include "core/lights/emitters.h"
#include "core/lights/environment.h"
#include "core/lights/light.h"

namespace rt {

class LightSelection {
 public:
  static constexpr size_t kSampleEach = 8;

  LightSelection() = default;
  // `powers`: one per entry of the light list (0: nothing to draw). Active (drawing one light)
  // when more than kSampleEach entries have power.
  explicit LightSelection(const std::vector<float>& powers);

  bool active() const { return !cdf_.empty(); }
  // The entry u in [0, 1) picks, and its probability.
  size_t sample(float u, float& probability) const;
  // The probability of entry l (1 when not active: every light is sampled).
  float probability(size_t l) const;

 private:
  std::vector<float> cdf_;  // running sums, the last 1
};

// The power of each entry of the light list, in the path tracer's units (point lights at their
// attenuation 1 m away; the sky and directional lights through a disk the size of `bounds`).
std::vector<float> light_powers(const std::vector<Light>& lights, const Emitters& emitters, const Environment& sky,
                                const Aabb& bounds);

}  // namespace rt
