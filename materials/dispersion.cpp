#include "materials/dispersion.h"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

float lobe(float x, float mu, float below, float above) {
  const float t = (x - mu) / (x < mu ? below : above);
  return std::exp(-0.5f * t * t);
}

// Linear Rec.709 of the CIE matching functions at one wavelength, negatives cut.
Vec3 unscaled(float w) {
  const float x = 1.056f * lobe(w, 599.8f, 37.9f, 31.0f) + 0.362f * lobe(w, 442.0f, 16.0f, 26.7f) -
                  0.065f * lobe(w, 501.1f, 20.4f, 26.2f);
  const float y = 0.821f * lobe(w, 568.8f, 46.9f, 40.5f) + 0.286f * lobe(w, 530.9f, 16.3f, 31.1f);
  const float z = 1.217f * lobe(w, 437.0f, 11.8f, 36.0f) + 0.681f * lobe(w, 459.0f, 26.0f, 13.8f);
  const Vec3 rgb(3.2404542f * x - 1.5371385f * y - 0.4985314f * z, -0.9692660f * x + 1.8760108f * y + 0.0415560f * z,
                 0.0556434f * x - 0.2040259f * y + 1.0572252f * z);
  return glm::max(rgb, Vec3(0.0f));
}

struct Scale {
  Vec3 inverse_mean{1.0f};
  Scale() {
    constexpr int n = 4000;
    Vec3 sum(0.0f);
    for (int i = 0; i < n; ++i) sum += unscaled(wavelength_from((static_cast<float>(i) + 0.5f) / n));
    inverse_mean = Vec3(static_cast<float>(n)) / sum;
  }
};

}  // namespace

float dispersed_ior(float ior, float dispersion, float wavelength_nm) {
  if (!(dispersion > 0.0f)) return ior;
  const float abbe = 20.0f / dispersion;
  return std::max(1.0f, ior + (ior - 1.0f) / abbe * (523655.0f / (wavelength_nm * wavelength_nm) - 1.5168f));
}

Vec3 wavelength_weight(float wavelength_nm) {
  static const Scale scale;  // immutable once computed (thread-safe initialisation)
  return unscaled(wavelength_nm) * scale.inverse_mean;
}

}  // namespace rt
