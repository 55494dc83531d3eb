// Pinhole or thin-lens camera. Image rows run top to bottom; (x, y) are continuous pixel
// coordinates, so the centre of pixel (i, j) is (i + 0.5, j + 0.5). With an aperture (lens radius)
// > 0, rays start at a point of the lens disk and pass through the point that the pinhole ray meets
// on the plane of focus, focus_distance ahead along the view direction: depth of field.
#pragma once

#include "core/aabb.h"
#include "core/ray.h"

namespace rt {

struct Camera {
  Vec3 position{0.0f};
  Vec3 forward{0.0f, 0.0f, -1.0f};  // unit, towards the look-at point
  Vec3 right{1.0f, 0.0f, 0.0f};     // unit
  Vec3 up{0.0f, 1.0f, 0.0f};        // unit, perpendicular to forward and right
  float vertical_fov_degrees = 45.0f;
  float tan_half_fov = 0.41421356f;  // tan(vertical_fov_degrees / 2), computed once, not per ray
  float aperture = 0.0f;             // lens radius; 0 = pinhole
  float focus_distance = 1.0f;       // from the camera to the plane in focus, along forward

  // Caller guarantees target != position and up not parallel to (target - position).
  static Camera look_at(Vec3 position, Vec3 target, Vec3 up, float vertical_fov_degrees) {
    Camera c;
    c.position = position;
    c.forward = glm::normalize(target - position);
    c.right = glm::normalize(glm::cross(c.forward, up));
    c.up = glm::cross(c.right, c.forward);
    c.vertical_fov_degrees = vertical_fov_degrees;
    c.tan_half_fov = std::tan(radians(vertical_fov_degrees) * 0.5f);
    return c;
  }

  // A camera in front of and a little above `bounds` (towards +Z, Y up), looking at its centre,
  // just far enough back that all eight corners of the box are inside the image, plus 5 %.
  static Camera framing(const Aabb& bounds, float vertical_fov_degrees, float aspect) {
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

  // Primary ray through continuous pixel position (x, y) of a width x height image.
  Ray generate_ray(float x, float y, int width, int height) const {
    const float tan_half = tan_half_fov;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const float sx = (2.0f * x / static_cast<float>(width) - 1.0f) * tan_half * aspect;
    const float sy = (1.0f - 2.0f * y / static_cast<float>(height)) * tan_half;
    Ray r;
    r.origin = position;
    r.direction = glm::normalize(forward + sx * right + sy * up);
    return r;
  }

  // The angle one pixel subtends at the centre of a `height`-pixel image (ray-cone spread).
  float pixel_spread(int height) const { return 2.0f * tan_half_fov / static_cast<float>(height); }

  // The same ray through a thin lens: `lens` in [0, 1)^2 picks the point of the lens disk
  // (Shirley and Chiu's concentric mapping, which keeps strata compact). Aperture 0 returns the
  // pinhole ray exactly.
  Ray generate_ray(float x, float y, int width, int height, Vec2 lens) const {
    Ray r = generate_ray(x, y, width, height);
    if (aperture <= 0.0f) return r;
    const Vec3 focus = r.origin + r.direction * (focus_distance / glm::dot(r.direction, forward));
    const Vec2 disk = aperture * concentric_disk(lens);
    r.origin = position + disk.x * right + disk.y * up;
    r.direction = glm::normalize(focus - r.origin);
    return r;
  }

  // Uniform point of the unit disk from a point of the unit square.
  static Vec2 concentric_disk(Vec2 u) {
    const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f) return Vec2(0.0f);
    const bool wide = std::fabs(a) > std::fabs(b);
    const float radius = wide ? a : b;
    const float phi = wide ? (kPi / 4.0f) * (b / a) : (kPi / 2.0f) - (kPi / 4.0f) * (a / b);
    return radius * Vec2(std::cos(phi), std::sin(phi));
  }
};

}  // namespace rt
