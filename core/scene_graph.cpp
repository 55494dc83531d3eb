#include "core/scene_graph.h"

#include <algorithm>
#include <cmath>

#include "core/flatten_instances.h"

namespace rt {
namespace {

bool finite_box(const Aabb& box) { return is_finite(box.lo) && is_finite(box.hi); }

Vec3 point(const Mat4& m, Vec3 p) { return Vec3(m * Vec4(p, 1.0f)); }

Camera placed_camera(const Camera& c, const Mat4& m) {
  const Vec3 position = point(m, c.position);
  const Vec3 forward = Mat3(m) * c.forward, up = Mat3(m) * c.up;
  Camera out = c;
  // A node's scale or shear does not distort the view: only its position and directions count.
  if (glm::length(glm::cross(forward, up)) > 0.0f && is_finite(forward) && is_finite(up))
    out.aim(position, position + glm::normalize(forward), glm::normalize(up));
  return out;
}

}  // namespace

Light transform_light(const Light& light, const Mat4& m) {
  return std::visit(
      [&](auto l) -> Light {
        using T = decltype(l);
        if constexpr (std::is_same_v<T, PointLight>) {
          l.position = point(m, l.position);
        } else if constexpr (std::is_same_v<T, SpotLight>) {
          l.position = point(m, l.position);
          l.direction = glm::normalize(Mat3(m) * l.direction);
        } else if constexpr (std::is_same_v<T, DirectionalLight>) {
          l.direction = glm::normalize(Mat3(m) * l.direction);
        } else {
          l.corner = point(m, l.corner);
          l.edge1 = Mat3(m) * l.edge1;
          l.edge2 = Mat3(m) * l.edge2;
        }
        return l;
      },
      light);
}

Pose SceneGraph::pose_at(float seconds) const {
  std::vector<Trs> local(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) local[i] = nodes[i].trs;
  for (const Track& track : tracks)
    if (track.node < nodes.size()) apply_track(track, seconds, local[track.node]);
  std::vector<Mat4> world(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    const SceneNode& n = nodes[i];
    const Mat4 m = n.matrix ? *n.matrix : local[i].matrix();
    world[i] = n.parent >= 0 ? world[static_cast<size_t>(n.parent)] * m : m;
  }
  return Pose{seconds, std::move(world)};
}

Camera SceneGraph::camera_at(const Pose& pose) const {
  return camera.node >= 0 ? placed_camera(camera.camera, pose.world[static_cast<size_t>(camera.node)]) : camera.camera;
}

PrimitiveSet SceneGraph::place(const Pose& pose, std::vector<PlacementIssue>* issues) const {
  const std::vector<Mat4>& world = pose.world;
  const auto issue = [&](PlacementIssue::Kind kind, size_t node) {
    if (issues) issues->push_back(PlacementIssue{kind, static_cast<uint32_t>(node)});
  };
  PrimitiveSet top;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const SceneNode& node = nodes[i];
    if (!node.has_geometry()) continue;
    const size_t copies = std::max<size_t>(1, node.instancing.size());
    for (size_t c = 0; c < copies; ++c) {
      const Mat4 m = node.instancing.empty() ? world[i] : world[i] * node.instancing[c];
      const auto transform = make_transform(m);
      if (!transform) {
        issue(PlacementIssue::kSingular, i);
        continue;
      }
      if (node.shape) {
        const AnalyticShape shape{*node.shape, node.shape_material, *transform};
        if (finite_box(world_bounds(shape))) top.shapes.push_back(shape);
        else issue(PlacementIssue::kBeyondRange, i);
      }
      for (const NodeMesh& nm : node.meshes) {
        const MeshGeometry& g = assets->meshes[nm.mesh];
        if (g.bounds.empty()) continue;
        // Without a BVH (validate), the instance only says where the mesh is (warnings, framing).
        const MeshInstance inst =
            g.bvh.primitive_count() == 0
                ? MeshInstance{&g.bvh, *transform, transform_bounds(transform->to_world, g.bounds), nm.mesh,
                               nm.material}
                : place_mesh(g.bvh, *transform, nm.mesh, nm.material, assets->mask(nm.mesh, nm.material));
        if (finite_box(inst.bounds)) top.instances.push_back(inst);
        else issue(PlacementIssue::kBeyondRange, i);
      }
    }
  }
  for (const CsgTemplate& t : csgs) {
    CsgPlacement placed = place_csg(t, world, *assets);
    if (placed.singular_node) issue(PlacementIssue::kSingular, *placed.singular_node);
    if (placed.beyond_range_node) issue(PlacementIssue::kBeyondRange, *placed.beyond_range_node);
    if (placed.object) top.csgs.push_back(std::move(*placed.object));
  }
  return top;
}

Scene SceneGraph::at(const Pose& pose, PrimitiveSet placed, const BvhBuildOptions& options) const {
  const std::vector<Mat4>& world = pose.world;  // for the camera and lights on nodes
  Scene scene;
  scene.assets = assets;
  scene.background = background;
  scene.ambient = ambient;
  scene.camera = camera_at(pose);
  for (const LightPlacement& l : lights)
    scene.lights.push_back(l.node >= 0 ? transform_light(l.light, world[static_cast<size_t>(l.node)]) : l.light);
  flatten_instances(placed, assets->meshes);
  scene.bvh = Bvh(placed, options);
  scene.all_opaque = std::none_of(assets->materials.begin(), assets->materials.end(),
                                  [](const Material& m) { return m.transmissive(); });
  for (const Material& m : assets->materials) {
    scene.texcoords_read.push_back(m.reads_texcoords() ? 1 : 0);
    scene.uniform_phong.push_back(m.uniform_phong() ? 1 : 0);
  }
  for (const Light& l : scene.lights) {
    const RectLight* rect = std::get_if<RectLight>(&l);
    scene.rect_frames.push_back(RectFrame(rect ? *rect : RectLight{}));
  }
  scene.emitters = Emitters(scene.bvh, *assets);
  scene.light_selection =
      LightSelection(light_powers(scene.lights, scene.emitters, scene.background, scene.bvh.bounds()));
  return scene;
}

bool SceneGraph::ends_where_it_starts() const {
  if (!animated || timeline.last_frame <= timeline.first_frame) return false;
  const Pose first = pose(timeline.first_frame), last = pose(timeline.last_frame);
  for (size_t n = 0; n < first.world.size(); ++n)
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) {
        // Within rounding of the transform's own size (a 360-degree turn comes back to ~1e-7).
        const float a = first.world[n][c][r], b = last.world[n][c][r];
        if (!(std::fabs(a - b) <= 1e-5f * std::max(1.0f, std::max(std::fabs(a), std::fabs(b))))) return false;
      }
  const Camera a = camera_at(first), b = camera_at(last);
  return glm::length(a.position - b.position) <= 1e-5f * std::max(1.0f, glm::length(a.position)) &&
         glm::length(a.forward - b.forward) <= 1e-5f;
}

}  // namespace rt
