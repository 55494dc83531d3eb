#include "core/render/camera_ray_batch.h"

#include <cstring>

#include "core/avx2_clones.h"
#include "core/simd.h"

namespace rt {

RT_AVX2_CLONES
void perspective_ray_batch(const Camera& camera, const float* x, const float* y, int count, int width, int height,
                           Ray* out) {
  Float8 px = splat8(0.0f), py = splat8(0.0f);  // unused lanes: any finite point
  for (int j = 0; j < count; ++j) {
    px[j] = x[j];
    py[j] = y[j];
  }
  // generate_ray's scalars, once.
  const float fw = static_cast<float>(width), fh = static_cast<float>(height);
  const float aspect = fw / fh;
  const float tan_half = camera.tan_half_fov;
  const float larger = 2.0f * tan_half * std::max(aspect, 1.0f);
  const float shift_x = camera.shift.x * larger, shift_y = camera.shift.y * larger;
  const Float8 sx = (2.0f * px / fw - 1.0f) * tan_half * aspect + shift_x + camera.window_offset;
  const Float8 sy = (1.0f - 2.0f * py / fh) * tan_half + shift_y;
  // forward + sx right + sy up, then glm::normalize: v * (1 / sqrt(dot(v, v))), dot summed x, y, z.
  const Vec3 f = camera.forward, r = camera.right, u = camera.up;
  const Float8 dx = f.x + sx * r.x + sy * u.x;
  const Float8 dy = f.y + sx * r.y + sy * u.y;
  const Float8 dz = f.z + sx * r.z + sy * u.z;
  const Float8 inv = 1.0f / sqrt8(dx * dx + dy * dy + dz * dz);
  // Through arrays, field by field: a Ray built from the lanes went through the stack and back
  // in wide loads of narrow stores, which stalled.
  alignas(32) float nx[kCameraRayBatch], ny[kCameraRayBatch], nz[kCameraRayBatch];
  const Float8 vx = dx * inv, vy = dy * inv, vz = dz * inv;
  std::memcpy(nx, &vx, sizeof vx);
  std::memcpy(ny, &vy, sizeof vy);
  std::memcpy(nz, &vz, sizeof vz);
  for (int j = 0; j < count; ++j) {
    Ray& ray = out[j];
    ray.origin = camera.position;
    ray.direction.x = nx[j];
    ray.direction.y = ny[j];
    ray.direction.z = nz[j];
    ray.tmin = 0.0f;
    ray.tmax = kInfinity;
  }
}

}  // namespace rt
