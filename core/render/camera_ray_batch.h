// A packet's pinhole camera rays at once, in vector registers (core/simd.h): each lane the
// very operations of Camera::generate_ray for a perspective camera without a lens, in the same
// order, so the same floats as one ray at a time. One at a time, a ray's four divisions and its
// square root left the core waiting on each (camera-ray set-up was a tenth of reflection.json's
// time at four rays a pixel).
#pragma once

#include "core/camera.h"

namespace rt {

// Lanes of one batch: one 8-lane vector.
inline constexpr int kCameraRayBatch = 8;

// Whether perspective_ray_batch makes this camera's rays: a perspective pinhole.
inline bool batches_camera_rays(const Camera& camera) {
  return camera.projection == CameraProjection::kPerspective && !camera.has_lens();
}

// out[j] = camera.generate_ray(x[j], y[j], width, height) for j < count (at most
// kCameraRayBatch), for a camera that batches_camera_rays.
void perspective_ray_batch(const Camera& camera, const float* x, const float* y, int count, int width, int height,
                           Ray* out);

}  // namespace rt
