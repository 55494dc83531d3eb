// Four triangles of a BVH leaf laid out lane by lane, so that one ray is tested against all four
// at once: Moller-Trumbore (core/shapes/triangle.h) on four lanes, each lane's arithmetic in the
// same order as the one-triangle routine, so that every lane gives exactly its t, b1 and b2.
#pragma once

#include <cstdint>

#include "core/ray.h"
#include "core/shapes/triangle.h"
#include "core/simd.h"

namespace rt {

struct alignas(64) TriangleQuad {
  // Per axis, one lane per triangle. An unused lane has zero edges: det = 0, never hit.
  float v0[3][4], e1[3][4], e2[3][4];
  uint32_t id[4];  // each lane's primitive id (~0 for an unused lane)
};

// A ray splat across four lanes once per ray.
struct QuadRay {
  Float4 o[3], d[3];
  RT_SIMD_INLINE explicit QuadRay(const Ray& r) {
    for (int a = 0; a < 3; ++a) {
      o[a] = splat4(r.origin[a]);
      d[a] = splat4(r.direction[a]);
    }
  }
};

// Bit i set when triangle i is hit inside (tmin, tmax); its t, b1 and b2 are lane i of the outputs.
RT_SIMD_INLINE unsigned intersect_quad(const TriangleQuad& q, const QuadRay& r, float tmin, float tmax, Float4& t,
                                       Float4& b1, Float4& b2) {
  const Float4 e1x = load4(q.e1[0]), e1y = load4(q.e1[1]), e1z = load4(q.e1[2]);
  const Float4 e2x = load4(q.e2[0]), e2y = load4(q.e2[1]), e2z = load4(q.e2[2]);
  // p = cross(d, e2); det = dot(e1, p), as glm computes them.
  const Float4 px = r.d[1] * e2z - e2y * r.d[2], py = r.d[2] * e2x - e2z * r.d[0], pz = r.d[0] * e2y - e2x * r.d[1];
  const Float4 det = e1x * px + e1y * py + e1z * pz;
  const Float4 inv_det = splat4(1.0f) / det;
  const Float4 sx = r.o[0] - load4(q.v0[0]), sy = r.o[1] - load4(q.v0[1]), sz = r.o[2] - load4(q.v0[2]);
  b1 = (sx * px + sy * py + sz * pz) * inv_det;
  // q = cross(s, e1)
  const Float4 qx = sy * e1z - e1y * sz, qy = sz * e1x - e1z * sx, qz = sx * e1y - e1x * sy;
  b2 = (r.d[0] * qx + r.d[1] * qy + r.d[2] * qz) * inv_det;
  t = (e2x * qx + e2y * qy + e2z * qz) * inv_det;
  const Float4 zero = splat4(0.0f);
  const Mask4 inside =
      (det != zero) & (b1 >= zero) & (b2 >= zero) & (b1 + b2 <= splat4(1.0f)) & (t > splat4(tmin)) & (t < splat4(tmax));
  return movemask4(inside);
}

// The hit record of lane `lane` of an intersect_quad result: the triangle's id as prim.
RT_SIMD_INLINE Hit quad_lane_hit(const TriangleQuad& q, int lane, Float4 t, Float4 b1, Float4 b2) {
  Hit hit;
  hit.t = t[lane];
  hit.b1 = b1[lane];
  hit.b2 = b2[lane];
  hit.part = 0;
  hit.prim = q.id[lane];
  return hit;
}

// Lane `lane` of `quad` set to `tri`, primitive `id`.
inline void set_quad_lane(TriangleQuad& quad, int lane, const PackedTriangle& tri, uint32_t id = ~0u) {
  quad.id[lane] = id;
  for (int a = 0; a < 3; ++a) {
    quad.v0[a][lane] = tri.v0[a];
    quad.e1[a][lane] = tri.e1[a];
    quad.e2[a][lane] = tri.e2[a];
  }
}

// Lane `lane` of `quad` as a triangle (the copy set_quad_lane made, bit for bit).
inline PackedTriangle quad_lane(const TriangleQuad& quad, int lane) {
  PackedTriangle tri;
  for (int a = 0; a < 3; ++a) {
    tri.v0[a] = quad.v0[a][lane];
    tri.e1[a] = quad.e1[a][lane];
    tri.e2[a] = quad.e2[a][lane];
  }
  return tri;
}

}  // namespace rt
