#include "io/gltf/extras.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <tiny_gltf.h>

#include "io/base/input_file.h"
#include "io/gltf/file.h"
#include "io/gltf/images.h"
#include "io/gltf/values.h"
#include "io/json/locate.h"
#include "io/json/reader.h"

namespace rt {
namespace {

// Blender writes booleans of custom properties as 0 or 1.
bool flag(const tinygltf::Value& object, const char* key) {
  if (!object.Has(key)) return false;
  const tinygltf::Value& v = object.Get(key);
  return v.IsBool() ? v.Get<bool>() : (v.IsNumber() && v.GetNumberAsDouble() != 0.0);
}

// Other exporters' lights in extras (objects under `rt_area_light`, `area_light`, `lamp`, ...): rtcli reads
// only its own key, so each key that looks like a light is named in a warning rather than dropped
// without a word (the model would get the default lamp instead).
void warn_unknown_light_extras(const tinygltf::Value& extras, const std::string& where, const std::string& at,
                               Reporter& report) {
  for (const std::string& key : extras.Keys()) {
    std::string lower = key;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    // A light is an object of its own ("lightmap_scale": 2 is not one).
    if (key == "rtcli_area_light" || !extras.Get(key).IsObject() ||
        (lower.find("light") == std::string::npos && lower.find("lamp") == std::string::npos))
      continue;
    std::string message = where + ": extras key \"" + key +
                          "\" looks like a light, which rtcli does not read: no light is made from it (rtcli reads "
                          "\"rtcli_area_light\": {shape, size, color, power, two_sided}, as tools/blender_export.py "
                          "writes it)";
    if (closest_match(key, {"rtcli_area_light"})) message += " (did you mean \"rtcli_area_light\"?)";
    report.warning(pointer_child(at + "/extras", key), message, Anchor::kKey);
  }
}

}  // namespace

std::optional<RectLight> area_light_from_extras(const tinygltf::Value& extras, const std::string& where,
                                                const std::string& at, Reporter& report) {
  if (extras.IsObject()) warn_unknown_light_extras(extras, where, at, report);
  if (!extras.IsObject() || !extras.Has("rtcli_area_light")) return std::nullopt;
  const tinygltf::Value& a = extras.Get("rtcli_area_light");
  const auto size = gltf_numbers(a, "size", 2);
  const auto power = gltf_number(a, "power");
  const auto color = gltf_numbers(a, "color", 3);
  if (!size || !power || !((*size)[0] > 0.0f) || !((*size)[1] > 0.0f) || *power < 0.0f) {
    report.warning(at + "/extras/rtcli_area_light",
                   where + ": rtcli_area_light needs size [x, y] > 0 and power >= 0 (watts); ignored");
    return std::nullopt;
  }
  if (a.Has("shape") && a.Get("shape").IsString()) {
    const std::string shape = a.Get("shape").Get<std::string>();
    if (shape == "DISK" || shape == "ELLIPSE")
      report.warning(at + "/extras/rtcli_area_light/shape",
                     where + ": a " + shape + " area light is drawn as the rectangle of the same size");
  }
  const float sx = (*size)[0], sy = (*size)[1];
  RectLight light;
  // Centred on the node; edge1 x edge2 = -Z, the way Blender's area lights face.
  light.corner = Vec3(-0.5f * sx, 0.5f * sy, 0.0f);
  light.edge1 = Vec3(sx, 0.0f, 0.0f);
  light.edge2 = Vec3(0.0f, -sy, 0.0f);
  const Vec3 c = color ? glm::max(Vec3((*color)[0], (*color)[1], (*color)[2]), Vec3(0.0f)) : Vec3(1.0f);
  // Cycles' area light of power P has radiance P / (4 A): head-on it lights like a point light
  // of the same power (intensity P / (4 pi) W/sr, times pi for the cosine lobe's peak).
  const float area = sx * sy;
  light.color = c * (*power / (4.0f * area));
  // The attenuation under which a rect light's colour is its radiance in both integrators
  // (core/lights/rect_light.h): head-on at 1 m it lights with P / (4 pi), as in Cycles.
  light.attenuation = radiance_attenuation(light);
  light.two_sided = flag(a, "two_sided");
  light.camera_visible = !a.Has("camera") || flag(a, "camera");
  return light;
}

void apply_material_extras(const tinygltf::Value& extras, ImageDecoder& images, const std::string& where,
                           const std::string& at, Material& material, Reporter& report) {
  if (!extras.IsObject() || !extras.Has("rtcli_bump")) return;
  const tinygltf::Value& b = extras.Get("rtcli_bump");
  if (!b.IsObject() || !b.Has("image") || !b.Get("image").IsString()) {
    report.warning(at + "/extras/rtcli_bump", where + ": rtcli_bump needs an \"image\" file name; ignored");
    return;
  }
  material.bump.height =
      images.file_slot(b.Get("image").Get<std::string>(), where + " rtcli_bump", at + "/extras/rtcli_bump/image");
  material.bump.strength = gltf_number(b, "strength").value_or(1.0f);
  material.bump.epsilon = std::max(0.0f, gltf_number(b, "epsilon").value_or(0.0f));
  // Blender's exporter wrote the Bump node's height image as a normal map: not one.
  if (material.bump.height.present()) material.normal_map = NormalMap{};
}

std::optional<ImportedWorld> world_from_extras(const tinygltf::Value& extras, const std::string& base_dir,
                                               bool outside_files, const std::string& at, Reporter& report) {
  if (!extras.IsObject() || !extras.Has("rtcli_world")) return std::nullopt;
  const std::string here = at + "/extras/rtcli_world";
  const tinygltf::Value& w = extras.Get("rtcli_world");
  const auto strength = w.IsObject() && w.Has("strength") ? gltf_number(w, "strength") : std::optional<float>(1.0f);
  const bool has_image = w.IsObject() && w.Has("image");
  const auto color = w.IsObject() && !has_image ? gltf_numbers(w, "color", 3) : std::nullopt;
  const auto rotation = w.IsObject() && w.Has("rotation") ? gltf_number(w, "rotation") : std::optional<float>(0.0f);
  const bool good_color = color && (*color)[0] >= 0.0f && (*color)[1] >= 0.0f && (*color)[2] >= 0.0f;
  const bool good_image = has_image && w.Get("image").IsString() && !w.Get("image").Get<std::string>().empty();
  // Bounded as --environment-intensity and --environment-rotate are.
  if (!strength || !(*strength >= 0.0f && *strength <= 1e6f) || !rotation || !(std::fabs(*rotation) <= 360.0f) ||
      !(good_color || good_image)) {
    report.warning(here,
                   "the scene's rtcli_world needs {color [r, g, b] >= 0, strength >= 0} or {image (a file name), "
                   "strength >= 0, rotation (degrees, -360 to 360)}; ignored: the model's default world is used");
    return std::nullopt;
  }
  ImportedWorld world;
  world.intensity = *strength;
  world.rotate = *rotation;
  if (!good_image) {
    world.color = Vec3((*color)[0], (*color)[1], (*color)[2]) * *strength;
    return world;
  }
  const std::string uri = w.Get("image").Get<std::string>();
  world.image = resolve_path(base_dir, percent_decoded(uri));
  // As a texture's file: a downloaded model must not show the user's other files.
  if (!outside_files && !is_inside_folder(world.image, base_dir)) {
    report.error(here + "/image", "the scene's world image: " + outside_folder_message(uri, base_dir));
    return std::nullopt;
  }
  return world;
}

}  // namespace rt
