#include "io/assemble/model_framing.h"

#include <algorithm>

#include "core/camera.h"
#include "io/json/reader.h"

namespace rt {
namespace {

// Poses a model's default camera frames at most, spread over its animation.
constexpr int kFramingPoses = 240;

}  // namespace

bool frame_model(SceneGraph& g, const PrimitiveSet& placed, float aspect, bool keep_camera,
                 const std::optional<CameraPlacement>& file_camera, std::string& error) {
  Aabb bounds;
  for (uint32_t id = 0; id < placed.size(); ++id) bounds.extend(placed.bounds(id));
  if (g.animated) {
    // Every frame of the timeline, or kFramingPoses spread over a long one.
    const int frames = g.timeline.frame_count();
    const int poses = std::min(frames, kFramingPoses);
    for (int k = 1; k < poses; ++k) {
      const int frame =
          g.timeline.first_frame + static_cast<int>(static_cast<int64_t>(k) * (frames - 1) / std::max(1, poses - 1));
      const PrimitiveSet at = g.place(g.pose(frame));
      for (uint32_t id = 0; id < at.size(); ++id) bounds.extend(at.bounds(id));
    }
  }
  if (bounds.empty()) bounds = Aabb{Vec3(-1.0f), Vec3(1.0f)};  // nothing to see: still a camera and a light
  const Camera framing = Camera::framing(bounds, 40.0f, aspect);
  // The light goes beside the camera in use, where it was, so that the side the camera sees is lit.
  if (!keep_camera) g.camera = file_camera ? *file_camera : CameraPlacement{"", framing, -1};
  const Camera camera = g.camera_at(g.pose(g.timeline.first_frame));
  const float reach = glm::length(camera.position - bounds.centre());
  PointLight light;
  light.position = camera.position + reach * (0.5f * camera.right + 0.6f * camera.up);
  if (!is_finite(framing.position) || !is_finite(light.position) || !(reach > 0.0f)) {
    error = "expected a model small enough to frame in single precision, found one whose extent (from " +
            format_number(bounds.lo.x) + " to " + format_number(bounds.hi.x) + " in x) puts the camera at infinity";
    return false;
  }
  if (g.lights.empty()) g.lights = {LightPlacement{light, -1}};
  // Stereo (--stereo) converges on the model, which a glTF camera has no look-at point to say.
  g.camera.camera.stereo.convergence = reach;
  return true;
}

}  // namespace rt
