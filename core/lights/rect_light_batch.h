// Whitted's samples of one rect light from one shading point, kPacketSize at a time, laid out lane
// by lane (one array per quantity) so that the compiler works a batch out in vector registers: a
// square root and four divisions per sample, which one by one left the core waiting on each
// (soft_shadows.json: 59% of its time in direct lighting, most of it there).
//
// Each lane performs the very operations of rect_point followed by Whitted's rule (attenuation x
// cos_light, core/lights/rect_light.h), in the same order: the same floats as one sample at a time.
#pragma once

#include <cmath>

#include "core/accel/bvh.h"
#include "core/lights/light.h"

namespace rt {

struct RectLightBatch {
  alignas(32) float dx[kPacketSize], dy[kPacketSize], dz[kPacketSize];  // unit, towards the light
  alignas(32) float distance[kPacketSize];
  // attenuation(distance) x cos_light: the colour's factor; 0 where the point sits on the light,
  // behind a one-sided light, or edge-on. (The radiance is `color` times it.)
  alignas(32) float scale[kPacketSize];

  Vec3 direction(int j) const { return Vec3(dx[j], dy[j], dz[j]); }
};

// The samples at (u[0][j], u[1][j]) of the light's edges from `point`, every lane (unused lanes
// are worked out too and ignored: a fixed count keeps the loop in vector registers).
inline void rect_light_batch(const RectLight& light, const RectFrame& frame, Vec3 point,
                             const float (&u)[2][kPacketSize], RectLightBatch& out) {
  const Vec3 c = light.corner, e1 = light.edge1, e2 = light.edge2, n = frame.unit_normal;
  const Attenuation att = light.attenuation;
  const bool two_sided = light.two_sided;
  for (int j = 0; j < kPacketSize; ++j) {
    // light.point(u) - point, as glm orders it: (corner + u.x edge1) + u.y edge2.
    const float tx = c.x + u[0][j] * e1.x + u[1][j] * e2.x - point.x;
    const float ty = c.y + u[0][j] * e1.y + u[1][j] * e2.y - point.y;
    const float tz = c.z + u[0][j] * e1.z + u[1][j] * e2.z - point.z;
    const float d = std::sqrt(tx * tx + ty * ty + tz * tz);
    const bool off_light = d > 0.0f;
    const float x = tx / d, y = ty / d, z = tz / d;
    const float facing = -(x * n.x + y * n.y + z * n.z);
    const float cos_light = two_sided ? std::fabs(facing) : (0.0f < facing ? facing : 0.0f);
    const float a = 1.0f / (att.c0 + d * (att.c1 + d * att.c2));
    out.dx[j] = off_light ? x : 0.0f;
    out.dy[j] = off_light ? y : 1.0f;
    out.dz[j] = off_light ? z : 0.0f;
    out.distance[j] = d;
    out.scale[j] = off_light ? a * cos_light : 0.0f;
  }
}

}  // namespace rt
