#include "io/gltf/lights.h"

#include <algorithm>
#include <cmath>

namespace rt {

std::optional<Light> light_from_gltf(const std::string& type, const std::vector<double>& color, double intensity,
                                     double inner_cone, double outer_cone, std::string& why) {
  Vec3 rgb(1.0f);
  if (color.size() == 3)
    rgb = Vec3(static_cast<float>(color[0]), static_cast<float>(color[1]), static_cast<float>(color[2]));
  if (!is_finite(rgb) || std::min({rgb.x, rgb.y, rgb.z}) < 0.0f || !std::isfinite(intensity) || intensity < 0.0) {
    why = "expected a colour and an intensity that are finite and >= 0";
    return std::nullopt;
  }
  const Vec3 scaled = rgb * static_cast<float>(intensity / (kLumensPerWatt * M_PI));
  if (type == "point") return PointLight{Vec3(0.0f), scaled, Attenuation{0.0f, 0.0f, 1.0f}};
  if (type == "directional") return DirectionalLight{Vec3(0.0f, 0.0f, -1.0f), scaled};
  if (type == "spot") {
    // glTF: 0 <= inner < outer <= pi / 2 (defaults 0 and pi / 4).
    const double outer = std::clamp(std::isfinite(outer_cone) ? outer_cone : M_PI / 4, 1e-4, M_PI / 2);
    const double inner = std::clamp(std::isfinite(inner_cone) ? inner_cone : 0.0, 0.0, outer);
    SpotLight s;
    s.color = scaled;
    s.cos_inner = static_cast<float>(std::cos(inner));
    s.cos_outer = static_cast<float>(std::cos(outer));
    return s;
  }
  why = "expected the type \"point\", \"spot\" or \"directional\", found \"" + type + "\"";
  return std::nullopt;
}

}  // namespace rt
