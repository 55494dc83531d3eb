#include "core/lights/light_selection.h"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

float luminance(Vec3 c) { return (c.x + c.y + c.z) / 3.0f; }  // as emission_weight

// What a light delivers, by kind: pi x colour x attenuation(d) / d^2 is its irradiance head-on at
// d (path tracer units), so a point light sends pi x colour x attenuation(1) x 4 pi.
struct PowerOf {
  float disk;  // pi R^2: the scene's cross-section, for lights from infinitely far
  float operator()(const PointLight& l) const { return kPi * luminance(l.color) * l.attenuation(1.0f) * 4.0f * kPi; }
  float operator()(const SpotLight& l) const {
    const float cos_mid = 0.5f * (l.cos_inner + l.cos_outer);
    return kPi * luminance(l.color) * l.attenuation(1.0f) * 2.0f * kPi * (1.0f - cos_mid);
  }
  float operator()(const DirectionalLight& l) const { return kPi * luminance(l.color) * disk; }
  // Its face's points light by the point-light rule times cos(theta_y): pi x that over the
  // hemisphere (pi x A x L for an emitter of radiance L: its colour when "radiance": true).
  float operator()(const RectLight& l) const {
    return kPi * luminance(l.color) * l.attenuation(1.0f) * kPi * (l.two_sided ? 2.0f : 1.0f);
  }
};

}  // namespace

LightSelection::LightSelection(const std::vector<float>& powers) {
  size_t with_power = 0;
  double total = 0.0;
  for (const float p : powers)
    if (std::isfinite(p) && p > 0.0f) {
      ++with_power;
      total += p;
    }
  if (with_power <= kSampleEach || !(total > 0.0)) return;
  cdf_.reserve(powers.size());
  double running = 0.0;
  for (const float p : powers) {
    if (std::isfinite(p) && p > 0.0f) running += p;
    cdf_.push_back(static_cast<float>(running / total));
  }
  cdf_.back() = 1.0f;
}

size_t LightSelection::sample(float u, float& probability) const {
  // The first entry whose running sum passes u (an entry of no power has none of the range).
  const size_t l = static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin());
  const size_t chosen = std::min(l, cdf_.size() - 1);
  probability = this->probability(chosen);
  return chosen;
}

float LightSelection::probability(size_t l) const {
  if (!active()) return 1.0f;
  return cdf_[l] - (l > 0 ? cdf_[l - 1] : 0.0f);
}

std::vector<float> light_powers(const std::vector<Light>& lights, const Emitters& emitters, const Environment& sky,
                                const Aabb& bounds) {
  const Vec3 extent = bounds.hi - bounds.lo;
  const float radius = is_finite(extent) && extent.x >= 0.0f ? 0.5f * glm::length(extent) : 1.0f;
  const PowerOf power{kPi * std::max(radius, 1e-3f) * std::max(radius, 1e-3f)};
  std::vector<float> out;
  out.reserve(lights.size() + 2);
  for (const Light& l : lights) out.push_back(std::visit(power, l));
  out.push_back(kPi * emitters.total_weight());
  out.push_back(sky.is_image() ? kPi * sky.mean_luminance() * power.disk : 0.0f);
  return out;
}

}  // namespace rt
