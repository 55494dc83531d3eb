#include "io/assemble/scene_warnings.h"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

bool any_corner_in_front(const Aabb& box, Vec3 origin, Vec3 normal) {
  for (int c = 0; c < 8; ++c) {
    const Vec3 p(c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y, c & 4 ? box.hi.z : box.lo.z);
    if (glm::dot(p - origin, normal) > 0.0f) return true;
  }
  return false;
}

// The box's bounding sphere against the cone: the angle to its centre, less the angle it spans.
bool cone_can_reach(Vec3 apex, Vec3 axis, float cos_half_angle, const Aabb& box) {
  const Vec3 to = box.centre() - apex;
  const float d = glm::length(to), r = 0.5f * glm::length(box.extent());
  if (!(d > r)) return true;  // the light is within the box's sphere (or the sizes are not finite)
  const float to_centre = std::acos(std::clamp(glm::dot(to / d, axis), -1.0f, 1.0f));
  const float spans = std::asin(std::clamp(r / d, 0.0f, 1.0f));
  return to_centre - spans < std::acos(std::clamp(cos_half_angle, -1.0f, 1.0f)) + 1e-4f;
}

std::string light_word(const Light& light) {
  return std::visit(
      [](const auto& l) -> std::string {
        using T = std::decay_t<decltype(l)>;
        if constexpr (std::is_same_v<T, RectLight>) return "rect light";
        else if constexpr (std::is_same_v<T, SpotLight>) return "spot light";
        else if constexpr (std::is_same_v<T, DirectionalLight>) return "directional light";
        else return "point light";
      },
      light);
}

}  // namespace

std::vector<Aabb> geometry_bounds(const PrimitiveSet& placed) {
  std::vector<Aabb> out(1);
  for (const PackedTriangle& t : placed.triangles) out.front().extend(t.bounds());
  for (uint32_t id = static_cast<uint32_t>(placed.triangles.size()); id < placed.size(); ++id)
    out.push_back(placed.bounds(id));
  return out;
}

bool light_can_reach(const Light& light, const Aabb& box) {
  if (box.empty()) return false;
  if (const auto* rect = std::get_if<RectLight>(&light))
    return rect->two_sided || any_corner_in_front(box, rect->corner, glm::cross(rect->edge1, rect->edge2));
  if (const auto* spot = std::get_if<SpotLight>(&light))
    return cone_can_reach(spot->position, spot->direction, spot->cos_outer, box);
  return true;  // point and directional lights shine every way that matters
}

bool inside_shape(ShapeKind kind, const Mat4& to_world, Vec3 point) {
  const std::optional<Transform> t = make_transform(to_world);
  if (!t || kind == ShapeKind::kPlane) return false;
  const Vec3 p = Vec3(t->to_object * Vec4(point, 1.0f));
  const float radial = p.x * p.x + p.y * p.y;
  switch (kind) {
    case ShapeKind::kSphere: return glm::dot(p, p) < 1.0f;
    case ShapeKind::kCube: return std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}) < 1.0f;
    case ShapeKind::kCylinder: return radial < 1.0f && p.z > 0.0f && p.z < 1.0f;
    case ShapeKind::kCone: return p.z > 0.0f && p.z < 1.0f && radial < p.z * p.z;
    case ShapeKind::kPlane: break;
  }
  return false;
}

void warn_unlit_or_empty(const Scene& scene, bool path_traced, const std::vector<Aabb>& geometry,
                         const std::vector<std::string>& light_pointers, Reporter& report) {
  const bool empty = std::all_of(geometry.begin(), geometry.end(), [](const Aabb& b) { return b.empty(); });
  if (empty) {
    report.warning("/nodes",
                   "the scene places nothing to render (no shape or mesh in its first frame): the image will show "
                   "only the background");
    return;
  }
  const bool emissive = std::any_of(scene.materials().begin(), scene.materials().end(),
                                    [](const Material& m) { return glm::dot(m.emission, Vec3(1.0f)) > 0.0f; });
  const bool sky = scene.background.is_image() || glm::dot(scene.background.color(), Vec3(1.0f)) > 0.0f;
  if (scene.lights.empty() && glm::dot(scene.ambient, Vec3(1.0f)) <= 0.0f && !emissive && !(sky && path_traced)) {
    if (!sky)
      report.warning("",
                     "the scene has no light, no ambient and no emissive material: every surface will render black "
                     "(add a light to \"lights\", or an \"ambient\" colour)");
    else
      report.warning("",
                     "the scene has no light, no ambient and no emissive material: Whitted renders every surface "
                     "black; only the path tracer (--integrator path) is lit by the background");
  }
  for (size_t i = 0; i < scene.lights.size() && i < light_pointers.size(); ++i) {
    if (light_pointers[i].empty()) continue;
    const Light& light = scene.lights[i];
    if (std::any_of(geometry.begin(), geometry.end(), [&](const Aabb& b) { return light_can_reach(light, b); }))
      continue;
    const bool rect = std::holds_alternative<RectLight>(light);
    report.warning(light_pointers[i],
                   "this " + light_word(light) + " reaches no geometry, so it lights nothing" +
                       (rect ? ": it emits towards edge1 x edge2, and everything lies behind it (swap edge1 and "
                               "edge2 to turn it over, or set \"two_sided\")"
                             : ": every shape and mesh lies outside its cone"));
  }
}

void warn_camera_inside(const SceneGraph& g, const Pose& pose, Vec3 camera, const std::vector<std::string>& pointers,
                        Reporter& report) {
  for (size_t n = 0; n < g.nodes.size(); ++n) {
    const SceneNode& node = g.nodes[n];
    if (!node.shape) continue;
    for (size_t c = 0; c < std::max<size_t>(1, node.instancing.size()); ++c) {
      const Mat4 m = node.instancing.empty() ? pose.world[n] : pose.world[n] * node.instancing[c];
      if (!inside_shape(*node.shape, m, camera)) continue;
      report.warning(pointers[n],
                     "the camera starts inside this closed shape: every camera ray meets its inside first (move "
                     "the camera, or the shape)");
      return;  // one warning says it
    }
  }
}

}  // namespace rt
