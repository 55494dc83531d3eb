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

#include "core/aabb.h"
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
  bool sees(float x, float y, int width, int height) const;
  // Primary ray through continuous pixel position (x, y) of a width x height image.
  Ray generate_ray(float x, float y, int width, int height) const;
  // The same ray through a thin lens: `lens` in [0, 1)^2 picks the point of the lens disk
  // (Shirley and Chiu's concentric mapping, which keeps strata compact). Aperture 0, or a
  // projection other than perspective, returns the pinhole ray exactly.
  Ray generate_ray(float x, float y, int width, int height, Vec2 lens) const;

  // The ray cone of a camera ray (textures' mip level, docs/rendering.md): the angle one pixel
  // subtends (perspective: at the image centre; fisheye and equirectangular: everywhere, along
  // the image's width), and the cone's width where rays start (orthographic: one pixel's width).
  float pixel_spread(int width, int height) const;
  float pixel_footprint(int width, int height) const;

  // The camera of one eye of a stereo pair (eye -1 left, +1 right), an ordinary mono camera:
  // perspective and fisheye move by half the eye separation along `right` with parallel axes,
  // perspective also shifts its window so that the convergence plane has no parallax (off-axis,
  // never toe-in); equirectangular offsets each column's origin on the viewing circle (ODS).
  Camera eye_camera(int eye) const;

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
