#include "materials/thin_film.h"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

float square(float x) { return x * x; }

float schlick(float f0, float cos_theta) {
  const float m = std::clamp(1.0f - cos_theta, 0.0f, 1.0f);
  return f0 + (1.0f - f0) * (m * m) * (m * m) * m;
}

float reflectance(float transmitted_ior, float incident_ior) {
  return square((transmitted_ior - incident_ior) / (transmitted_ior + incident_ior));
}

// The XYZ sensitivity of an optical path difference `opd` (nm) with phase shift `shift`, in
// Fourier space (Belcour and Barla's supplemental), as linear Rec.709.
Vec3 sensitivity(float opd, Vec3 shift) {
  const double phase = 2.0 * kPi * opd * 1.0e-9;
  const double val[3] = {5.4856e-13, 4.4201e-13, 5.2481e-13};
  const double pos[3] = {1.6810e+06, 1.7953e+06, 2.2084e+06};
  const double var[3] = {4.3278e+09, 9.3046e+09, 6.6121e+09};
  double xyz[3];
  for (int i = 0; i < 3; ++i)
    xyz[i] = val[i] * std::sqrt(2.0 * kPi * var[i]) * std::cos(pos[i] * phase + shift[i]) *
             std::exp(-phase * phase * var[i]);
  xyz[0] += 9.7470e-14 * std::sqrt(2.0 * kPi * 4.5282e+09) * std::cos(2.2399e+06 * phase + shift[0]) *
            std::exp(-4.5282e+09 * phase * phase);
  for (double& c : xyz) c /= 1.0685e-7;
  return Vec3(static_cast<float>(3.2404542 * xyz[0] - 1.5371385 * xyz[1] - 0.4985314 * xyz[2]),
              static_cast<float>(-0.9692660 * xyz[0] + 1.8760108 * xyz[1] + 0.0415560 * xyz[2]),
              static_cast<float>(0.0556434 * xyz[0] - 0.2040259 * xyz[1] + 1.0572252 * xyz[2]));
}

}  // namespace

Vec3 thin_film_fresnel(float outside_ior, float film_ior, float cos_theta, float thickness_nm, Vec3 base_f0) {
  cos_theta = std::clamp(cos_theta, 0.0f, 1.0f);
  // The film's index goes to the outside's as it thins away, so that no film means no film.
  const float t = std::clamp(thickness_nm / 0.03f, 0.0f, 1.0f);
  const float film = outside_ior + (film_ior - outside_ior) * (t * t * (3.0f - 2.0f * t));
  const float sin2_t = square(outside_ior / film) * (1.0f - cos_theta * cos_theta);
  if (sin2_t >= 1.0f) return Vec3(1.0f);  // total internal reflection in the film
  const float cos_t = std::sqrt(1.0f - sin2_t);

  // The first interface (outside to film), and its phase change.
  const float r12 = schlick(reflectance(film, outside_ior), cos_theta);
  const float t121 = 1.0f - r12;
  const float phi12 = film < outside_ior ? kPi : 0.0f;
  const float phi21 = kPi - phi12;

  // The second (film to base): the base's index from its F0, per channel.
  Vec3 r23(0.0f), phi23(0.0f);  // every channel set below (zeroed for GCC's flow analysis)
  for (int c = 0; c < 3; ++c) {
    const float root = std::sqrt(std::clamp(base_f0[c], 0.0f, 0.9999f));
    const float base_ior = (1.0f + root) / (1.0f - root);
    r23[c] = schlick(reflectance(base_ior, film), cos_t);
    phi23[c] = base_ior < film ? kPi : 0.0f;
  }

  const float opd = 2.0f * film * thickness_nm * cos_t;  // optical path difference
  const Vec3 phi = Vec3(phi21) + phi23;
  const Vec3 r123 = glm::clamp(r12 * r23, Vec3(1e-5f), Vec3(0.9999f));
  const Vec3 root123 = glm::sqrt(r123);
  const Vec3 rs = (t121 * t121) * r23 / (Vec3(1.0f) - r123);

  Vec3 result = Vec3(r12) + rs;  // the order-0 (incoherent) term
  Vec3 cm = rs - Vec3(t121);
  for (int m = 1; m <= 2; ++m) {
    cm *= root123;
    result += cm * 2.0f * sensitivity(static_cast<float>(m) * opd, static_cast<float>(m) * phi);
  }
  return glm::clamp(result, Vec3(0.0f), Vec3(1.0f));
}

}  // namespace rt
