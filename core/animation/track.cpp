#include "core/animation/track.h"

#include <algorithm>

namespace rt {

Vec4 slerp(Vec4 a, Vec4 b, float s) {
  float cos_theta = glm::dot(a, b);
  if (cos_theta < 0.0f) {  // q and -q are the same rotation: take the nearer one
    b = -b;
    cos_theta = -cos_theta;
  }
  if (cos_theta > 0.9995f) return glm::normalize(glm::mix(a, b, s));  // nearly equal: lerp is exact enough
  const float theta = std::acos(std::min(cos_theta, 1.0f));
  const float sin_theta = std::sin(theta);
  return (std::sin((1.0f - s) * theta) * a + std::sin(s * theta) * b) / sin_theta;
}

Vec4 sample_track(const Track& track, float seconds) {
  const std::vector<float>& times = track.keys->times;
  const std::vector<Vec4>& values = track.keys->values;
  const bool cubic = track.interpolation == Interpolation::kCubicSpline;
  const auto value = [&](size_t key) { return values[cubic ? 3 * key + 1 : key]; };
  if (times.empty()) return Vec4(0.0f);
  if (!(seconds > times.front())) return value(0);  // also NaN
  if (seconds >= times.back()) return value(times.size() - 1);
  // times[k] <= seconds < times[k + 1]
  const size_t k = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), seconds) - times.begin()) - 1;
  const float dt = times[k + 1] - times[k];
  const float s = (seconds - times[k]) / dt;
  const bool rotation = track.part == TrsPart::kRotation;
  switch (track.interpolation) {
    case Interpolation::kStep: return value(k);
    case Interpolation::kLinear:
      return rotation ? slerp(value(k), value(k + 1), s) : glm::mix(value(k), value(k + 1), s);
    case Interpolation::kCubicSpline: {
      // Hermite basis on [t_k, t_k+1] with tangents scaled by the interval (glTF 2.0, Appendix C).
      const Vec4 p0 = values[3 * k + 1], m0 = dt * values[3 * k + 2];
      const Vec4 p1 = values[3 * (k + 1) + 1], m1 = dt * values[3 * (k + 1)];
      const float s2 = s * s, s3 = s2 * s;
      const Vec4 v = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
      if (!rotation) return v;
      const float len = glm::length(v);
      return len > 0.0f ? v / len : p0;
    }
  }
  return value(k);
}

void apply_track(const Track& track, float seconds, Trs& trs) {
  const Vec4 v = sample_track(track, seconds);
  switch (track.part) {
    case TrsPart::kTranslation: trs.translation = Vec3(v); break;
    case TrsPart::kRotation: trs.rotation = Quat(v.w, v.x, v.y, v.z); break;
    case TrsPart::kScale: trs.scale = Vec3(v); break;
  }
}

}  // namespace rt
