// The camera: where it is, which way it looks, and how image positions become rays. Image rows
// run top to bottom; (x, y) are continuous pixel coordinates, so the centre of pixel (i, j) is
// (i + 0.5, j + 0.5). Four projections (docs/scene-format.md, "camera"):
//  - perspective: a pinhole, or with an aperture (lens radius) > 0 a thin lens whose rays pass
//    through the point the pinhole ray meets on the plane of focus (depth of field);
//  - orthographic: parallel rays along the view direction from a window `ortho_width` wide;
//  - fisheye: equidistant (the angle from the view direction grows linearly with the distance
//    from the image centre), `fisheye_fov` across the circle inscribed in the image;
//  - equirectangular: the full sphere, longitude across and latitude down a 2:1 image, the view
//    direction at the centre and `up` at the top.
// A stereo camera renders as two eyes (eye_camera), each an ordinary camera of its own.
#pragma once

#include <algorithm>

#include "core/aabb.h"
#include "core/direction_sampling.h"
#include "core/ray.h"
#include "core/stereo.h"

namespace rt {

enum class CameraProjection : uint8_t { kPerspective, kOrthographic, kFisheye, kEquirectangular };

struct Camera {
  Vec3 position{0.0f};
  Vec3 forward{0.0f, 0.0f, -1.0f};  // unit, towards the look-at point
  Vec3 right{1.0f, 0.0f, 0.0f};     // unit
  Vec3 up{0.0f, 1.0f, 0.0f};        // unit, perpendicular to forward and right
  float vertical_fov_degrees = 45.0f;
  float tan_half_fov = 0.41421356f;  // tan(vertical_fov_degrees / 2), computed once, not per ray
  float aperture = 0.0f;             // lens radius; 0 = pinhole (perspective only)
  float focus_distance = 1.0f;       // from the camera to the plane in focus, along forward
  CameraProjection projection = CameraProjection::kPerspective;
  float ortho_width = 2.0f;  // orthographic: the window's width in scene units
  float fisheye_fov = kPi;   // fisheye: radians across the image circle, up to 2 pi
  // Perspective and orthographic: the window moved across the image plane, in units of the
  // image's larger side (Blender's shift_x, shift_y); x to the right, y up.
  Vec2 shift{0.0f};
  // Set by eye_camera() only: the window's offset at unit distance (perspective: off-axis
  // stereo), and the eye's offset on the viewing circle (equirectangular: omni-directional
  // stereo), negative for the left eye.
  float window_offset = 0.0f;
  float ods_offset = 0.0f;
  StereoSettings stereo;  // mode kNone: one image

  // Caller guarantees target != position and up not parallel to (target - position).
  static Camera look_at(Vec3 position, Vec3 target, Vec3 up, float vertical_fov_degrees) {
    Camera c;
    c.aim(position, target, up);
    c.set_fov(vertical_fov_degrees);
    return c;
  }
  // Moves and turns the camera, keeping everything else (projection, lens, stereo).
  void aim(Vec3 from, Vec3 target, Vec3 up_hint) {
    position = from;
    forward = glm::normalize(target - from);
    right = glm::normalize(glm::cross(forward, up_hint));
    up = glm::cross(right, forward);
  }
  void set_fov(float degrees) {
    vertical_fov_degrees = degrees;
    tan_half_fov = std::tan(radians(degrees) * 0.5f);
  }

  // A camera in front of and a little above `bounds` (towards +Z, Y up), looking at its centre,
  // just far enough back that all eight corners of the box are inside the image, plus 5 %.
  static Camera framing(const Aabb& bounds, float vertical_fov_degrees, float aspect);

  // Whether the image position sees anything: false outside a fisheye's circle (left black).
  bool sees(float x, float y, int width, int height) const {
    return projection != CameraProjection::kFisheye || inside_fisheye_circle(x, y, width, height);
  }
  // Primary ray through continuous pixel position (x, y) of a width x height image. The
  // perspective case, by far the most common, is inline: a camera ray costs no call. Its
  // operations are repeated eight lanes at a time by core/render/camera_ray_batch.cpp: change
  // both (tests/render/test_camera_ray_batch.cpp holds them to the same bits).
  Ray generate_ray(float x, float y, int width, int height) const {
    if (projection != CameraProjection::kPerspective) return generate_other_ray(x, y, width, height);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    // At unit distance the window is 2 tan_half * aspect wide; shift is in units of its larger side.
    const float larger = 2.0f * tan_half_fov * std::max(aspect, 1.0f);
    const float sx =
        (2.0f * x / static_cast<float>(width) - 1.0f) * tan_half_fov * aspect + shift.x * larger + window_offset;
    const float sy = (1.0f - 2.0f * y / static_cast<float>(height)) * tan_half_fov + shift.y * larger;
    Ray r;
    r.origin = position;
    r.direction = glm::normalize(forward + sx * right + sy * up);
    return r;
  }
  // Whether generate_ray reads its lens sample: a thin lens, not a pinhole.
  bool has_lens() const { return aperture > 0.0f && projection == CameraProjection::kPerspective; }
  // The same ray through a thin lens: `lens` in [0, 1)^2 picks the point of the lens disk
  // (Shirley and Chiu's concentric mapping, which keeps strata compact). Aperture 0, or a
  // projection other than perspective, returns the pinhole ray exactly.
  Ray generate_ray(float x, float y, int width, int height, Vec2 lens) const {
    Ray r = generate_ray(x, y, width, height);
    if (!has_lens()) return r;
    const Vec3 focus = r.origin + r.direction * (focus_distance / glm::dot(r.direction, forward));
    const Vec2 disk = aperture * concentric_disk(lens);
    r.origin = position + disk.x * right + disk.y * up;
    r.direction = glm::normalize(focus - r.origin);
    return r;
  }

  // The ray cone of a camera ray (textures' mip level, docs/rendering.md): the angle one pixel
  // subtends (perspective: at the image centre; fisheye and equirectangular: everywhere, along
  // the image's width), and the cone's width where rays start (orthographic: one pixel's width).
  float pixel_spread(int width, int height) const {
    switch (projection) {
      case CameraProjection::kPerspective: return 2.0f * tan_half_fov / static_cast<float>(height);
      case CameraProjection::kOrthographic: return 0.0f;
      case CameraProjection::kFisheye: return fisheye_fov / static_cast<float>(std::min(width, height));
      case CameraProjection::kEquirectangular: return 2.0f * kPi / static_cast<float>(width);
    }
    return 0.0f;
  }
  float pixel_footprint(int width, int /*height*/) const {
    return projection == CameraProjection::kOrthographic ? ortho_width / static_cast<float>(width) : 0.0f;
  }

  // The camera of one eye of a stereo pair (eye -1 left, +1 right), an ordinary mono camera:
  // perspective and fisheye move by half the eye separation along `right` with parallel axes,
  // perspective also shifts its window so that the convergence plane has no parallax (off-axis,
  // never toe-in); equirectangular offsets each column's origin on the viewing circle (ODS).
  Camera eye_camera(int eye) const;

 private:
  bool inside_fisheye_circle(float x, float y, int width, int height) const;
  Ray generate_other_ray(float x, float y, int width, int height) const;  // every projection but perspective
};

}  // namespace rt
