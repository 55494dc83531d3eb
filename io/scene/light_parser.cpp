#include "io/scene/light_parser.h"

#include <algorithm>
#include <cmath>

#include "io/json/locate.h"

namespace rt {
namespace {

std::optional<Attenuation> parse_attenuation(const JsonReader& r, ObjectReader& o) {
  const Json* a = o.get("attenuation");
  if (!a) return Attenuation{};
  const std::string ptr = o.child("attenuation");
  const auto c = read_vec3(r, *a, ptr);
  if (!c) return std::nullopt;
  if (c->x < 0 || c->y < 0 || c->z < 0 || c->x + c->y + c->z <= 0) {
    r.expected(ptr, "[c0, c1, c2] >= 0, not all zero (radiance / (c0 + c1 d + c2 d^2))", *a);
    return std::nullopt;
  }
  return Attenuation{c->x, c->y, c->z};
}

// A rectangle needs two edges that span an area: not zero, not parallel.
bool check_rect_edges(const JsonReader& r, const ObjectReader& o, Vec3 e1, Vec3 e2) {
  const float scale = std::max(glm::length(e1), glm::length(e2));
  if (!(glm::length(glm::cross(e1, e2)) > 1e-6f * scale * scale)) {
    r.error(o.child("edge2"),
            "expected two edge vectors that span a rectangle (not zero, not parallel), found " +
                std::string(glm::length(e1) == 0.0f || glm::length(e2) == 0.0f ? "a zero edge" : "parallel edges"));
    return false;
  }
  return true;
}

// A spot light: a point light whose emission fades (glTF's t^2) from the inner cone to the outer.
std::optional<SpotLight> parse_spot_light(const JsonReader& r, ObjectReader& o, Vec3 emitted,
                                          const std::optional<Attenuation>& attenuation) {
  const auto position = o.vec3("position", true);
  const auto direction = o.vec3("direction", true);
  const auto inner = o.number("inner_angle", NumberRule{0.0, 90.0});
  const auto outer = o.number("outer_angle", NumberRule{0.0, 90.0});
  o.finish();
  if (!position || !direction || !attenuation) return std::nullopt;
  if (!(glm::length(*direction) > 0.0f)) {
    r.error(o.child("direction"), "expected a direction that is not zero, found [0, 0, 0]");
    return std::nullopt;
  }
  const double in = inner.value_or(0.0), out = outer.value_or(30.0);
  if (!(in < out)) {
    r.expected(o.child(outer ? "outer_angle" : "inner_angle"),
               "outer_angle > inner_angle (" + Json(in).dump() + " degrees)", Json(out));
    return std::nullopt;
  }
  SpotLight light;
  light.position = *position;
  light.direction = glm::normalize(*direction);
  light.color = emitted;
  light.attenuation = *attenuation;
  light.cos_inner = static_cast<float>(std::cos(in * 3.14159265358979323846 / 180.0));
  light.cos_outer = static_cast<float>(std::cos(out * 3.14159265358979323846 / 180.0));
  return light;
}

}  // namespace

void parse_lights(const JsonReader& r, const Json& v, const std::string& ptr, std::vector<Light>& out,
                  std::vector<std::string>& pointers) {
  if (!v.is_array()) {
    r.expected(ptr, "an array of lights", v);
    return;
  }
  for (size_t i = 0; i < v.size(); ++i) {
    pointers.resize(out.size());  // a light in error adds none
    pointers.push_back(pointer_child(ptr, i));
    ObjectReader o(r, v[i], pointer_child(ptr, i));
    std::optional<size_t> type;
    if (const Json* t = o.get("type", true, "\"point\", \"rect\", \"spot\" or \"directional\""))
      type = read_choice(r, *t, o.child("type"), {"point", "rect", "spot", "directional"});
    const Vec3 color = o.color("color").value_or(Vec3(1.0f));
    const auto intensity = o.number("intensity", kNonNegative);
    const Vec3 emitted = color * static_cast<float>(intensity.value_or(1.0));
    const auto attenuation = parse_attenuation(r, o);
    if (type == 1u) {
      RectLight light;
      const auto corner = o.vec3("corner", true);
      const auto e1 = o.vec3("edge1", true);
      const auto e2 = o.vec3("edge2", true);
      const Json* two_sided = o.get("two_sided");
      if (two_sided && !two_sided->is_boolean()) r.expected(o.child("two_sided"), "true or false", *two_sided);
      // "radiance": true: the colour is the face's radiance, the physical emitter's falloff
      // (core/lights/rect_light.h), which no attenuation of the scene's may change.
      const Json* radiance = o.get("radiance");
      if (radiance && !radiance->is_boolean()) r.expected(o.child("radiance"), "true or false", *radiance);
      const bool is_radiance = radiance && radiance->is_boolean() && radiance->get<bool>();
      if (is_radiance && o.get("attenuation"))
        r.error(o.child("attenuation"),
                "a rect light with \"radiance\": true falls off as a physical emitter; expected no attenuation");
      o.finish();
      if (!corner || !e1 || !e2 || !attenuation || !check_rect_edges(r, o, *e1, *e2)) continue;
      light.corner = *corner;
      light.edge1 = *e1;
      light.edge2 = *e2;
      light.color = emitted;
      light.attenuation = *attenuation;
      if (is_radiance) light.attenuation = radiance_attenuation(light);
      light.two_sided = two_sided && two_sided->is_boolean() && two_sided->get<bool>();
      out.emplace_back(light);
    } else if (type == 2u) {
      if (auto light = parse_spot_light(r, o, emitted, attenuation)) out.emplace_back(*light);
    } else if (type == 3u) {
      const auto direction = o.vec3("direction", true);
      o.finish();
      if (!direction) continue;
      if (!(glm::length(*direction) > 0.0f)) {
        r.error(o.child("direction"), "expected a direction that is not zero, found [0, 0, 0]");
        continue;
      }
      out.emplace_back(DirectionalLight{glm::normalize(*direction), emitted});
    } else {
      PointLight light;
      const auto position = o.vec3("position", type == 0u);
      o.finish();
      if (position) light.position = *position;
      light.color = emitted;
      if (attenuation) light.attenuation = *attenuation;
      out.emplace_back(light);
    }
  }
  pointers.resize(out.size());
}

}  // namespace rt
