#include "io/gltf/node_parts.h"

#include <cmath>
#include <tuple>

#include <tiny_gltf.h>
#include <glm/gtc/type_ptr.hpp>

#include "io/gltf/accessor.h"
#include "io/gltf/lights.h"

namespace rt {

using std::to_string;

// The node's local transform as glTF gives it: a matrix, or translation, rotation and scale.
void read_node_transform(const tinygltf::Node& node, ImportedNode& out) {
  if (node.matrix.size() == 16) {
    Mat4 m;
    for (int i = 0; i < 16; ++i)
      glm::value_ptr(m)[i] = static_cast<float>(node.matrix[static_cast<size_t>(i)]);  // column-major
    out.matrix = m;
    return;
  }
  const auto vec3 = [](const std::vector<double>& v) {
    return Vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
  };
  if (node.translation.size() == 3) out.trs.translation = vec3(node.translation);
  if (node.rotation.size() == 4) {  // glTF quaternions are (x, y, z, w)
    const Quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                 static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
    const float len = glm::length(q);
    out.trs.rotation = len > 0.0f && std::isfinite(len) ? q / len : Quat(1.0f, 0.0f, 0.0f, 0.0f);
  }
  if (node.scale.size() == 3) out.trs.scale = vec3(node.scale);
}

// glTF cameras look down their node's -Z with +Y up; perspective (yfov) or orthographic (xmag,
// the view's half width; ymag follows from the image's aspect, as viewers do).
bool import_camera(const tinygltf::Model& model, const tinygltf::Node& node, const std::string& at, int32_t index,
                   ImportedModel& out, Reporter& report) {
  if (node.camera < 0) return true;
  if (static_cast<size_t>(node.camera) >= model.cameras.size()) {
    report.error(at + "/camera",
                 "node \"" + node.name + "\" uses camera " + to_string(node.camera) + ", which does not exist");
    return false;
  }
  const tinygltf::Camera& c = model.cameras[static_cast<size_t>(node.camera)];
  float fov = 40.0f;
  const bool orthographic = c.type == "orthographic" && c.orthographic.xmag > 0.0 && c.orthographic.xmag < 1e30;
  if (c.type == "perspective" && c.perspective.yfov > 0.0 && c.perspective.yfov < 3.1)
    fov = static_cast<float>(c.perspective.yfov * 180.0 / 3.14159265358979);
  else if (!orthographic)
    report.warning("/cameras/" + to_string(node.camera),
                   "camera " + to_string(node.camera) + " (\"" + c.name + "\") is " +
                       (c.type == "perspective" ? "a perspective camera without a usable yfov"
                                                : "an orthographic camera without a usable xmag") +
                       "; rendered as a perspective camera with a 40 degree field of view");
  CameraPlacement placement;
  placement.name = !c.name.empty() ? c.name : !node.name.empty() ? node.name : "camera " + to_string(node.camera);
  placement.camera = Camera::look_at(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), Vec3(0.0f, 1.0f, 0.0f), fov);
  if (orthographic) {
    placement.camera.projection = CameraProjection::kOrthographic;
    placement.camera.ortho_width = 2.0f * static_cast<float>(c.orthographic.xmag);
  }
  placement.node = index;
  out.cameras.push_back(placement);
  return true;
}

// KHR_lights_punctual, converted to our units by the rule in io/gltf/lights.h.
bool import_light(const tinygltf::Model& model, const tinygltf::Node& node, const std::string& at, int32_t index,
                  ImportedModel& out, Reporter& report) {
  const auto ext = node.extensions.find("KHR_lights_punctual");
  if (ext == node.extensions.end() || !ext->second.Has("light")) return true;
  const tinygltf::Value& v = ext->second.Get("light");
  const int light = v.IsInt() ? v.GetNumberAsInt() : -1;
  if (light < 0 || static_cast<size_t>(light) >= model.lights.size()) {
    report.error(at + "/extensions/KHR_lights_punctual/light",
                 "node \"" + node.name + "\" uses light " + to_string(light) + ", which does not exist");
    return false;
  }
  const tinygltf::Light& l = model.lights[static_cast<size_t>(light)];
  const std::string light_at = "/extensions/KHR_lights_punctual/lights/" + to_string(light);
  std::string why;
  const auto converted =
      light_from_gltf(l.type, l.color, l.intensity, l.spot.innerConeAngle, l.spot.outerConeAngle, why);
  if (!converted) {
    report.warning(light_at, "light " + to_string(light) + " (\"" + l.name + "\"): " + why + "; ignored");
    return true;
  }
  if (l.range > 0.0)
    report.warning(light_at + "/range",
                   "light " + to_string(light) + " (\"" + l.name +
                       "\"): range is not modelled; the inverse-square falloff continues beyond it");
  out.lights.push_back(LightPlacement{*converted, index});
  return true;
}

// EXT_mesh_gpu_instancing: the node's mesh drawn once per row of its TRANSLATION, ROTATION and
// SCALE accessors (each optional, all of one count), in the node's space.
bool import_instancing(const tinygltf::Model& model, const tinygltf::Node& node, const std::string& at,
                       const LoadLimits& limits, ImportedNode& out, Reporter& report) {
  const auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
  if (ext == node.extensions.end() || !ext->second.Has("attributes")) return true;
  const tinygltf::Value& attributes = ext->second.Get("attributes");
  const std::string where = "node \"" + node.name + "\" EXT_mesh_gpu_instancing ";
  std::vector<float> t, r, s;
  size_t count = 0;
  bool any = false;
  for (auto [name, components, values] :
       {std::tuple{"TRANSLATION", 3, &t}, std::tuple{"ROTATION", 4, &r}, std::tuple{"SCALE", 3, &s}}) {
    if (!attributes.Has(name)) continue;
    const tinygltf::Value& index = attributes.Get(name);
    const std::string attribute_at = at + "/extensions/EXT_mesh_gpu_instancing/attributes/" + name;
    if (!index.IsInt()) {
      report.error(attribute_at, where + name + ": expected an accessor index");
      return false;
    }
    if (!read_float_accessor(model, index.GetNumberAsInt(), components, limits.instances, *values,
                             AccessorUse{report, where + name + ": ", attribute_at}))
      return false;
    const size_t n = values->size() / static_cast<size_t>(components);
    if (any && n != count) {
      report.error(attribute_at, where + name + ": expected " + to_string(count) +
                                     " values like the other attributes, found " + to_string(n));
      return false;
    }
    count = n;
    any = true;
  }
  out.instancing.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    Trs trs;
    if (!t.empty()) trs.translation = Vec3(t[3 * i], t[3 * i + 1], t[3 * i + 2]);
    if (!r.empty()) {
      const Quat q(r[4 * i + 3], r[4 * i], r[4 * i + 1], r[4 * i + 2]);  // stored (x, y, z, w)
      const float len = glm::length(q);
      trs.rotation = len > 0.0f && std::isfinite(len) ? q / len : Quat(1.0f, 0.0f, 0.0f, 0.0f);
    }
    if (!s.empty()) trs.scale = Vec3(s[3 * i], s[3 * i + 1], s[3 * i + 2]);
    out.instancing.push_back(trs.matrix());
  }
  if (any && count == 0) out.instancing.push_back(Mat4(0.0f));  // zero copies: a singular placement draws none
  return true;
}

}  // namespace rt
