#include "core/camera.h"

#include <algorithm>

namespace rt {
namespace {

float aspect_of(int width, int height) { return static_cast<float>(width) / static_cast<float>(height); }

// (x, y) as offsets from the image centre in [-1, 1] across the width, and down -> up.
Vec2 centred(float x, float y, int width, int height) {
  return Vec2(2.0f * x / static_cast<float>(width) - 1.0f, 1.0f - 2.0f * y / static_cast<float>(height));
}

}  // namespace

Camera Camera::framing(const Aabb& bounds, float vertical_fov_degrees, float aspect) {
  const Vec3 centre = bounds.centre();
  const Vec3 back = glm::normalize(Vec3(0.0f, 0.35f, 1.0f));  // from the centre towards the camera
  const Camera axes = look_at(centre + back, centre, Vec3(0.0f, 1.0f, 0.0f), vertical_fov_degrees);
  const float tan_v = std::tan(radians(vertical_fov_degrees) * 0.5f), tan_h = tan_v * aspect;
  float distance = 1e-6f;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c = Vec3(corner & 1 ? bounds.hi.x : bounds.lo.x, corner & 2 ? bounds.hi.y : bounds.lo.y,
                        corner & 4 ? bounds.hi.z : bounds.lo.z) -
                   centre;
    // The corner is at depth distance + c.forward; it must satisfy |c.right| <= depth * tan_h.
    const float depth_offset = glm::dot(c, axes.forward);
    distance = std::max({distance, std::fabs(glm::dot(c, axes.right)) / tan_h - depth_offset,
                         std::fabs(glm::dot(c, axes.up)) / tan_v - depth_offset});
  }
  return look_at(centre + 1.05f * distance * back, centre, Vec3(0.0f, 1.0f, 0.0f), vertical_fov_degrees);
}

bool Camera::inside_fisheye_circle(float x, float y, int width, int height) const {
  const Vec2 p = Vec2(x - 0.5f * static_cast<float>(width), 0.5f * static_cast<float>(height) - y);
  const float radius = 0.5f * static_cast<float>(std::min(width, height));
  return glm::dot(p, p) <= radius * radius;
}

Ray Camera::generate_other_ray(float x, float y, int width, int height) const {
  const float aspect = aspect_of(width, height);
  const Vec2 c = centred(x, y, width, height);
  Ray r;
  r.origin = position;
  switch (projection) {
    case CameraProjection::kPerspective: return generate_ray(x, y, width, height);
    case CameraProjection::kOrthographic: {
      const float half_w = 0.5f * ortho_width, half_h = half_w / aspect;
      const float larger = 2.0f * std::max(half_w, half_h);
      r.origin = position + (c.x * half_w + shift.x * larger) * right + (c.y * half_h + shift.y * larger) * up;
      r.direction = forward;
      break;
    }
    case CameraProjection::kFisheye: {
      // Equidistant: the angle from the axis is proportional to the distance from the centre.
      const float radius = 0.5f * static_cast<float>(std::min(width, height));
      const Vec2 p = Vec2(x - 0.5f * static_cast<float>(width), 0.5f * static_cast<float>(height) - y) / radius;
      const float r_image = glm::length(p);
      const float theta = r_image * 0.5f * fisheye_fov;
      const Vec2 across = r_image > 0.0f ? p / r_image : Vec2(0.0f);
      r.direction = glm::normalize(std::cos(theta) * forward + std::sin(theta) * (across.x * right + across.y * up));
      break;
    }
    case CameraProjection::kEquirectangular: {
      const float longitude = c.x * kPi;        // 0 at the centre, +-pi at the edges
      const float latitude = c.y * 0.5f * kPi;  // +pi/2 at the top
      const float cos_lat = std::cos(latitude);
      const Vec3 level = std::sin(longitude) * right + std::cos(longitude) * forward;
      r.direction = glm::normalize(cos_lat * level + std::sin(latitude) * up);
      if (ods_offset != 0.0f) {
        // Omni-directional stereo: the eye sits on the viewing circle, at right angles to the
        // column's direction, its offset fading to none towards the poles.
        const float altitude = std::fabs(latitude);
        float offset = ods_offset;
        if (altitude >= stereo.pole_merge_to) {
          offset = 0.0f;
        } else if (altitude > stereo.pole_merge_from) {
          const float f = (altitude - stereo.pole_merge_from) / (stereo.pole_merge_to - stereo.pole_merge_from);
          offset *= std::cos(f * 0.5f * kPi);
        }
        const Vec3 tangent = std::cos(longitude) * right - std::sin(longitude) * forward;
        r.origin = position + offset * tangent;
        // Both eyes' rays meet at the convergence distance C along the column's direction (as
        // Cycles): towards C d - offset t, scaled by 1 / C so that a far C cannot overflow.
        if (offset != 0.0f) r.direction = glm::normalize(r.direction - (offset / stereo.convergence) * tangent);
      }
      break;
    }
  }
  return r;
}

Camera Camera::eye_camera(int eye) const {
  Camera c = *this;
  c.stereo.mode = StereoMode::kNone;
  const float half = 0.5f * stereo.eye_separation * static_cast<float>(eye);
  switch (projection) {
    case CameraProjection::kEquirectangular: c.ods_offset = half; break;
    case CameraProjection::kPerspective:
      c.position = position + half * right;
      // A point on the axis at the convergence distance is at -half / convergence from this
      // eye's axis, at unit distance: the window moves there, so both eyes see it at the centre.
      c.window_offset = window_offset - half / stereo.convergence;
      break;
    case CameraProjection::kFisheye:
    case CameraProjection::kOrthographic: c.position = position + half * right; break;
  }
  return c;
}

}  // namespace rt
