#include "core/lights/rect_light_batch.h"

#include <cstring>

#include "core/avx2_clones.h"

namespace rt {

RT_AVX2_CLONES
void rect_light_batch(const RectLight& light, const RectFrame& frame, Vec3 point, const float (&u)[2][kPacketSize],
                      RectLightBatch& out) {
  const Vec3 c = light.corner, e1 = light.edge1, e2 = light.edge2, n = frame.unit_normal;
  const Float8 s = load8(u[0]), t = load8(u[1]);
  // light.point(u) - point, as glm orders it: (corner + u.x edge1) + u.y edge2.
  const Float8 tx = splat8(c.x) + s * e1.x + t * e2.x - point.x;
  const Float8 ty = splat8(c.y) + s * e1.y + t * e2.y - point.y;
  const Float8 tz = splat8(c.z) + s * e1.z + t * e2.z - point.z;
  const Float8 d = sqrt8(tx * tx + ty * ty + tz * tz);
  const Mask8 off_light = d > 0.0f;
  const Float8 x = tx / d, y = ty / d, z = tz / d;
  const Float8 facing = -(x * n.x + y * n.y + z * n.z);
  const Float8 cos_light = light.two_sided ? abs8(facing) : (facing > 0.0f ? facing : splat8(0.0f));
  const Attenuation& att = light.attenuation;
  const Float8 a = 1.0f / (att.c0 + d * (att.c1 + d * att.c2));
  const Float8 zero = splat8(0.0f);
  const Float8 dx = off_light ? x : zero, dy = off_light ? y : splat8(1.0f), dz = off_light ? z : zero;
  const Float8 scale = off_light ? a * cos_light : zero;
  std::memcpy(out.dx, &dx, sizeof dx);
  std::memcpy(out.dy, &dy, sizeof dy);
  std::memcpy(out.dz, &dz, sizeof dz);
  std::memcpy(out.distance, &d, sizeof d);
  std::memcpy(out.scale, &scale, sizeof scale);
}

RT_AVX2_CLONES
SampleSides sample_sides(const RectLightBatch& drawn, Vec3 color, Vec3 n, Vec3 ng, bool lifted) {
  const Float8 dx = load8(drawn.dx), dy = load8(drawn.dy), dz = load8(drawn.dz), scale = load8(drawn.scale);
  // glm::dot's order: x, then y, then z.
  const Float8 n_dot_l = n.x * dx + n.y * dy + n.z * dz;
  const Float8 l_dot_ng = dx * ng.x + dy * ng.y + dz * ng.z;
  // max_component(color * scale), std::max's way (a < b ? b : a), also for a NaN.
  const Float8 r = color.x * scale, g = color.y * scale, b = color.z * scale;
  const Float8 gb = g < b ? b : g;
  const Float8 brightest = r < gb ? gb : r;
  // make's "x <= 0: no ray", negated: a NaN passes, as it passes there.
  Mask8 light = ~(n_dot_l <= 0.0f) & ~(brightest <= 0.0f);
  if (!lifted) light &= ~(l_dot_ng <= 0.0f);
  return SampleSides{movemask8(light), movemask8(l_dot_ng < 0.0f)};
}

}  // namespace rt
