// Phong's reflectance (materials/phong.h) for a batch of light directions at one point, in vector
// registers: the rect light's samples (core/lights/rect_light_batch.h) come eight at a time, and
// one by one their dot products and the reflected direction left soft_shadows.json a fifth of its
// time in direct lighting (docs/benchmark.md, "Round two, a twelfth session"). Each lane performs
// phong_reflectance's operations in its order: the same floats, lane by lane.
#pragma once

#include "core/accel/bvh.h"
#include "core/math.h"

namespace rt {

// The factor that multiplies light j's radiance, one array per channel.
struct PhongBatch {
  alignas(32) float r[kPacketSize], g[kPacketSize], b[kPacketSize];

  Vec3 operator[](int j) const { return Vec3(r[j], g[j], b[j]); }
};

// phong_reflectance(kd, ks, shininess, n, l_j, v) for the unit directions l_j = (dx[j], dy[j],
// dz[j]), for each lane j whose bit is set in `lanes` (the others are left undefined: their
// highlights' powers are not worked out).
void phong_batch(Vec3 kd, Vec3 ks, float shininess, Vec3 n, Vec3 v, const float* dx, const float* dy, const float* dz,
                 unsigned lanes, PhongBatch& out);

// sum += (color x scale[j]) x batch[j], lane after lane for the lanes set in `lanes`: the floats
// of Vec3 arithmetic one sample at a time, the products worked out in vector registers.
void add_lit(const PhongBatch& batch, Vec3 color, const float* scale, unsigned lanes, Vec3& sum);

}  // namespace rt
