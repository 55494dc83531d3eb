// Whitted's samples of one rect light from one shading point, kPacketSize at a time, in vector
// registers (GCC/Clang vector extensions, core/simd.h): a square root and four divisions per
// sample, which one by one left the core waiting on each (soft_shadows.json: 59% of its time in
// direct lighting, most of it there).
//
// Each lane performs the very operations of rect_point followed by Whitted's rule (attenuation x
// cos_light, core/lights/rect_light.h), in the same order: the same floats as one sample at a time.
#pragma once

#include "core/accel/bvh.h"
#include "core/lights/light.h"
#include "core/simd.h"

namespace rt {

static_assert(kPacketSize == 8, "a batch is one Float8");

struct RectLightBatch {
  alignas(32) float dx[kPacketSize], dy[kPacketSize], dz[kPacketSize];  // unit, towards the light
  alignas(32) float distance[kPacketSize];
  // attenuation(distance) x cos_light: the colour's factor; 0 where the point sits on the light,
  // behind a one-sided light, or edge-on. (The radiance is `color` times it.)
  alignas(32) float scale[kPacketSize];

  Vec3 direction(int j) const { return Vec3(dx[j], dy[j], dz[j]); }
};

// The samples at (u[0][j], u[1][j]) of the light's edges from `point`, every lane (unused lanes
// are worked out too and ignored). Compiled for the baseline and for AVX2 (GCC's target_clones,
// core/lights/rect_light_batch.cpp): one 8-lane register a step instead of two, the same floats
// (IEEE arithmetic, no contraction).
void rect_light_batch(const RectLight& light, const RectFrame& frame, Vec3 point, const float (&u)[2][kPacketSize],
                      RectLightBatch& out);

// Which samples of a batch can light a point, ShadowRays::make's tests lane by lane on the same
// floats (core/render/direct_lighting.cpp): in `light`, those in front of the shading normal `n`
// and, unless the point is lifted off a smooth mesh, of the geometric normal `ng`, whose radiance
// color x scale has a channel above 0; in `behind`, those whose direction leaves ng's back.
struct SampleSides {
  unsigned light = 0, behind = 0;
};
SampleSides sample_sides(const RectLightBatch& drawn, Vec3 color, Vec3 n, Vec3 ng, bool lifted);

}  // namespace rt
