#include "materials/sheen.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/math.h"

namespace rt {
namespace {

constexpr float kMinRoughness = 1e-6f;  // the sample viewer's clamp: the lobe is defined on (0, 1]

float lambda_helper(float x, float alpha) {
  const float t = (1.0f - alpha) * (1.0f - alpha);
  const float a = 21.5473f + (25.3245f - 21.5473f) * t;
  const float b = 3.82987f + (3.32435f - 3.82987f) * t;
  const float c = 0.19823f + (0.16801f - 0.19823f) * t;
  const float d = -1.97760f + (-1.27393f + 1.97760f) * t;
  const float e = -4.32054f + (-4.85967f + 4.32054f) * t;
  return a / (1.0f + b * std::pow(x, c)) + d * x + e;
}

float lambda(float cos_theta, float alpha) {
  const float c = std::fabs(cos_theta);
  return c < 0.5f ? std::exp(lambda_helper(c, alpha))
                  : std::exp(2.0f * lambda_helper(0.5f, alpha) - lambda_helper(1.0f - c, alpha));
}

constexpr int kTable = 32;

struct AlbedoTable {
  std::array<float, kTable * kTable> e{};  // [roughness][cos_v]
  AlbedoTable() {
    // The hemisphere in (cos theta_l, phi): 64 x 64 midpoints, phi over a half turn doubled.
    constexpr int n = 64;
    for (int r = 0; r < kTable; ++r)
      for (int v = 0; v < kTable; ++v) {
        const float roughness = std::max(static_cast<float>(r) / (kTable - 1), 0.02f);
        const float cos_v = std::max(static_cast<float>(v) / (kTable - 1), 1e-3f);
        const Vec3 wo(std::sqrt(1.0f - cos_v * cos_v), 0.0f, cos_v);
        double sum = 0.0;
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) {
            const float cos_l = (static_cast<float>(i) + 0.5f) / n;
            const float phi = kPi * (static_cast<float>(j) + 0.5f) / n;
            const float sin_l = std::sqrt(1.0f - cos_l * cos_l);
            const Vec3 wi(sin_l * std::cos(phi), sin_l * std::sin(phi), cos_l);
            const Vec3 h = glm::normalize(wi + wo);
            sum += sheen_distribution(roughness, h.z) * sheen_visibility(cos_l, cos_v, roughness) * cos_l;
          }
        e[static_cast<size_t>(r * kTable + v)] = static_cast<float>(sum * (2.0 * kPi / (n * n)));
      }
  }
};

}  // namespace

float sheen_distribution(float roughness, float cos_h) {
  const float alpha = std::max(roughness, kMinRoughness) * std::max(roughness, kMinRoughness);
  const float inv = 1.0f / alpha;
  const float sin2 = std::max(0.0f, 1.0f - cos_h * cos_h);
  return (2.0f + inv) * std::pow(sin2, inv * 0.5f) / (2.0f * kPi);
}

float sheen_visibility(float cos_l, float cos_v, float roughness) {
  if (cos_l <= 0.0f || cos_v <= 0.0f) return 0.0f;
  const float r = std::max(roughness, kMinRoughness);
  const float alpha = r * r;
  const float v = 1.0f / ((1.0f + lambda(cos_v, alpha) + lambda(cos_l, alpha)) * (4.0f * cos_v * cos_l));
  return std::clamp(v, 0.0f, 1.0f);
}

float sheen_albedo(float cos_v, float roughness) {
  static const AlbedoTable table;  // immutable once built (thread-safe initialisation)
  const float x = std::clamp(cos_v, 0.0f, 1.0f) * (kTable - 1), y = std::clamp(roughness, 0.0f, 1.0f) * (kTable - 1);
  const int x0 = std::min(static_cast<int>(x), kTable - 2), y0 = std::min(static_cast<int>(y), kTable - 2);
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  const auto at = [&](int r, int v) { return table.e[static_cast<size_t>(r * kTable + v)]; };
  const float low = at(y0, x0) + (at(y0, x0 + 1) - at(y0, x0)) * fx;
  const float high = at(y0 + 1, x0) + (at(y0 + 1, x0 + 1) - at(y0 + 1, x0)) * fx;
  return std::clamp(low + (high - low) * fy, 0.0f, 1.0f);
}

}  // namespace rt
