// KHR_lights_punctual in rtcli's light units. glTF gives point and spot intensities in candela
// and directional ones in lux, photometric units; our lights give what a surface facing them
// receives, and our Phong diffuse term is kd * cos (no 1/pi). The rule, as Blender's importer
// reads these files (683 lm/W):
//   point, spot:   colour = color * intensity / (683 pi), falling off as 1 / d^2
//   directional:   colour = color * intensity / (683 pi)
// so a Blender point light of P watts exported "Standard" (intensity = P 683 / 4 pi candela)
// lights a white surface at distance d to P / (4 pi d^2) / pi, the value Cycles renders. Spot
// cones fade with glTF's t^2 between the inner and outer angles; `range` is not modelled.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/lights/light.h"

namespace rt {

inline constexpr double kLumensPerWatt = 683.0;

// The light of `type` ("point", "spot", "directional") at the origin of its node, pointing down
// -Z; nothing (with `why`) for an unknown type or values that are not finite and >= 0.
std::optional<Light> light_from_gltf(const std::string& type, const std::vector<double>& color, double intensity,
                                     double inner_cone, double outer_cone, std::string& why);

}  // namespace rt
