// A packet's eight rays against one analytic shape at once, in the packet walks' leaves
// (core/accel/bvh_kernels_impl.h). The single-ray test (intersect_shape) first looks for a
// crossing inside the ray's interval in object space; that look is done here for all lanes, with
// the same float and double operations in the same order as Transform's (core/transform.h, glm's
// column sums) and the shapes' own (core/shapes/sphere.cpp, plane.cpp, cube.cpp, cylinder.cpp,
// cone.cpp, quadratic.h), so that lane by lane it finds the same crossing at the same t and part. A lane
// where it finds none needs no single-ray test, and one whose crossing lies beyond the origin's
// rounding gets that crossing as its hit (or its blocker) without it; only the others take the
// single-ray test. Every answer stays the single ray's (tests/core/test_bvh_shape_packets.cpp and
// the packet tests of test_bvh_isa.cpp).
#pragma once

#include <limits>
#include <optional>
#include <utility>

#include "core/accel/bvh_packet.h"
#include "core/float_error.h"
#include "core/shapes/analytic_shape.h"
#include "core/shapes/cone.h"
#include "core/shapes/cylinder.h"

namespace rt {
namespace RTCLI_ISA_NS {

#if defined(__AVX__)

typedef double Double4 __attribute__((vector_size(32)));
typedef int64_t Mask4d __attribute__((vector_size(32)));

// A packet's rays as lanes: origins, directions and intervals.
struct RayLanes {
  Float8 origin[3], direction[3], tmin, tmax;

  RayLanes(const PacketRays& r) {
    for (int a = 0; a < 3; ++a) {
      origin[a] = r.lanes([a](const Ray& ray) { return ray.origin[a]; });
      direction[a] = r.lanes([a](const Ray& ray) { return ray.direction[a]; });
    }
    tmin = r.lanes([](const Ray& ray) { return ray.tmin; });
    tmax = r.lanes([](const Ray& ray) { return ray.tmax; });
  }
};

// A packet's rays as lanes, gathered when a leaf's shape first needs them.
class LazyRayLanes {
 public:
  LazyRayLanes(const Ray* rays, int count) : packet_(rays, count) {}
  const RayLanes& get() {
    if (!lanes_) lanes_.emplace(packet_);
    return *lanes_;
  }
  // The intervals again, after hits narrowed them.
  void narrow() {
    if (lanes_) lanes_->tmax = packet_.lanes([](const Ray& r) { return r.tmax; });
  }

 private:
  PacketRays packet_;
  std::optional<RayLanes> lanes_;
};

// Lanes 4h to 4h + 3 of v, widened to double.
RT_SIMD_INLINE Double4 wide(Float8 v, int h) {
  const Float4 part = h == 0 ? __builtin_shufflevector(v, v, 0, 1, 2, 3) : __builtin_shufflevector(v, v, 4, 5, 6, 7);
  return __builtin_convertvector(part, Double4);
}
RT_SIMD_INLINE Double4 splat4d(double x) { return Double4{x, x, x, x}; }
RT_SIMD_INLINE unsigned movemask4d(Mask4d m) {
  return static_cast<unsigned>(__builtin_ia32_movmskpd256(reinterpret_cast<Double4>(m)));
}

// The rays in the shape's object space: transformed_ray's origin (to_object * (p, 1), glm's
// (m0 x + m1 y) + (m2 z + m3 1)) and direction (Mat3(to_object) * d, summed left to right).
struct ObjectLanes {
  Float8 o[3], d[3];

  RT_SIMD_INLINE ObjectLanes(const Mat4& m, const RayLanes& r) {
    for (int i = 0; i < 3; ++i) {
      const Float8 m0 = splat8(m[0][i]), m1 = splat8(m[1][i]), m2 = splat8(m[2][i]), m3 = splat8(m[3][i]);
      o[i] = (m0 * r.origin[0] + m1 * r.origin[1]) + (m2 * r.origin[2] + m3 * splat8(1.0f));
      d[i] = (m0 * r.direction[0] + m1 * r.direction[1]) + m2 * r.direction[2];
    }
  }
};

// Where the single-ray test first finds a shape crossed: bit i of `lanes` set where it finds a
// crossing inside lane i's interval, and t[i] and part[i] the hit's t (a float) and part it then
// reports.
struct LaneCrossings {
  unsigned lanes = 0;
  Float8 t{};
  Mask8 part{};
};

// Four lanes' crossings in double.
struct HalfCrossings {
  Mask4d found;
  Double4 t;
  Mask4d part{};
};

RT_SIMD_INLINE LaneCrossings join(HalfCrossings lo, HalfCrossings hi) {
  const Float4 t_lo = __builtin_convertvector(lo.t, Float4), t_hi = __builtin_convertvector(hi.t, Float4);
  const Int4 part_lo = __builtin_convertvector(lo.part, Int4), part_hi = __builtin_convertvector(hi.part, Int4);
  return {movemask4d(lo.found) | movemask4d(hi.found) << 4, __builtin_shufflevector(t_lo, t_hi, 0, 1, 2, 3, 4, 5, 6, 7),
          __builtin_shufflevector(part_lo, part_hi, 0, 1, 2, 3, 4, 5, 6, 7)};
}

// solve_quadratic (core/shapes/quadratic.h), four lanes: where it finds roots, t0 <= t1.
RT_SIMD_INLINE Mask4d solve_quadratic_half(Double4 a, Double4 b, Double4 c, Double4& t0, Double4& t1) {
  const Double4 disc = b * b - splat4d(4.0) * a * c;
  const Double4 root = __builtin_ia32_sqrtpd256(disc);
  const Double4 q = b < splat4d(0.0) ? splat4d(-0.5) * (b - root) : splat4d(-0.5) * (b + root);
  const Mask4d linear = a == splat4d(0.0), q_zero = q == splat4d(0.0);
  const Double4 line_t = -c / b;
  const Double4 u = q_zero ? splat4d(0.0) : q / a, v = q_zero ? splat4d(0.0) : c / q;
  const Mask4d swap = u > v;
  t0 = linear ? line_t : swap ? v : u;
  t1 = linear ? line_t : swap ? u : v;
  return linear ? b != splat4d(0.0) : ~(disc < splat4d(0.0));
}

// intersect_sphere's roots (sphere_roots) and the nearer of them inside the interval
// (nearer_root).
RT_SIMD_INLINE HalfCrossings sphere_half(const ObjectLanes& r, const RayLanes& ray, int h) {
  const Double4 ox = wide(r.o[0], h), oy = wide(r.o[1], h), oz = wide(r.o[2], h);
  const Double4 dx = wide(r.d[0], h), dy = wide(r.d[1], h), dz = wide(r.d[2], h);
  const Double4 a = dx * dx + dy * dy + dz * dz;
  const Double4 b = splat4d(2.0) * (ox * dx + oy * dy + oz * dz);
  const Double4 c = (ox * ox + oy * oy + oz * oz) - splat4d(1.0);
  Double4 lo, hi;
  const Mask4d solved = solve_quadratic_half(a, b, c, lo, hi);
  const Double4 tmin = wide(ray.tmin, h), tmax = wide(ray.tmax, h);
  const Mask4d lo_in = (lo > tmin) & (lo < tmax), hi_in = (hi > tmin) & (hi < tmax);
  return {solved & (lo_in | hi_in), lo_in ? lo : hi};
}

// intersect_cube's slabs: entering at t_near, else leaving at t_far; the face (part) 2 axis + 1
// where the ray crosses it towards + (entering) or - (leaving).
RT_SIMD_INLINE HalfCrossings cube_half(const ObjectLanes& r, const RayLanes& ray, int h) {
  Double4 t_near = splat4d(-HUGE_VAL), t_far = splat4d(HUGE_VAL);
  Mask4d outside = Mask4d{}, any_axis = Mask4d{};
  Mask4d near_face = Mask4d{}, far_face = Mask4d{};
  for (int a = 0; a < 3; ++a) {
    const Double4 o = wide(r.o[a], h), d = wide(r.d[a], h);
    const Mask4d parallel = d == splat4d(0.0);
    outside |= parallel & ((o < splat4d(-1.0)) | (o > splat4d(1.0)));
    const Double4 t0 = (splat4d(-1.0) - o) / d, t1 = (splat4d(1.0) - o) / d;
    const Mask4d swap = t0 > t1;
    const Double4 lo = swap ? t1 : t0, hi = swap ? t0 : t1;
    const Mask4d nearer = ~parallel & (lo > t_near), farther = ~parallel & (hi < t_far);
    const Mask4d towards_plus = d > splat4d(0.0);  // all bits set: -1
    t_near = nearer ? lo : t_near;
    t_far = farther ? hi : t_far;
    near_face = nearer ? Mask4d{} + int64_t{2 * a} - towards_plus : near_face;
    far_face = farther ? Mask4d{} + int64_t{2 * a + 1} + towards_plus : far_face;
    any_axis |= nearer;
  }
  const Double4 tmin = wide(ray.tmin, h), tmax = wide(ray.tmax, h);
  const Mask4d near_in = (t_near > tmin) & (t_near < tmax), far_in = (t_far > tmin) & (t_far < tmax);
  return {~outside & any_axis & ~(t_near > t_far) & (near_in | far_in), near_in ? t_near : t_far,
          near_in ? near_face : far_face};
}

// The nearest of a cylinder's or cone's crossings: the side's roots t0, t1 where `solved`
// (side_root_in_height: z within [0, 1]) and the caps (intersect_unit_disc at z_cap[k], part
// cap_part[k]), as intersect_cylinder and intersect_cone take them: the side's smaller root that
// counts, then each cap where nearer.
template <int Caps>
RT_SIMD_INLINE HalfCrossings side_and_caps(const ObjectLanes& r, const RayLanes& ray, int h, Mask4d solved, Double4 t0,
                                           Double4 t1, uint32_t side_part, const float (&z_cap)[Caps],
                                           const uint32_t (&cap_part)[Caps]) {
  const Double4 ox = wide(r.o[0], h), oy = wide(r.o[1], h), oz = wide(r.o[2], h);
  const Double4 dx = wide(r.d[0], h), dy = wide(r.d[1], h), dz = wide(r.d[2], h);
  const Double4 tmin = wide(ray.tmin, h), tmax = wide(ray.tmax, h);
  const auto in_interval = [&](Double4 t) { return (t > tmin) & (t < tmax); };
  HalfCrossings best{Mask4d{}, splat4d(HUGE_VAL), Mask4d{} + int64_t{side_part}};
  const auto take = [&](Mask4d found, Double4 t, uint32_t part) {
    const Mask4d nearer = found & (t < best.t);
    best.t = nearer ? t : best.t;
    best.part = nearer ? Mask4d{} + int64_t{part} : best.part;
    best.found |= found;
  };
  for (const Double4 t : {t0, t1}) {
    const Double4 z = oz + t * dz;
    take(solved & in_interval(t) & (z >= splat4d(0.0)) & (z <= splat4d(1.0)), t, side_part);
  }
  for (int k = 0; k < Caps; ++k) {
    const Double4 t = (splat4d(z_cap[k]) - oz) / dz;
    const Double4 x = ox + t * dx, y = oy + t * dy;
    take((dz != splat4d(0.0)) & in_interval(t) & (x * x + y * y <= splat4d(1.0)), t, cap_part[k]);
  }
  return best;
}

// intersect_cylinder: its side (where a > 0) and two caps.
RT_SIMD_INLINE HalfCrossings cylinder_half(const ObjectLanes& r, const RayLanes& ray, int h) {
  const Double4 ox = wide(r.o[0], h), oy = wide(r.o[1], h);
  const Double4 dx = wide(r.d[0], h), dy = wide(r.d[1], h);
  const Double4 a = dx * dx + dy * dy;
  Double4 t0, t1;
  const Mask4d solved = (a > splat4d(0.0)) & solve_quadratic_half(a, splat4d(2.0) * (ox * dx + oy * dy),
                                                                  ox * ox + oy * oy - splat4d(1.0), t0, t1);
  static constexpr float kCaps[] = {0.0f, 1.0f};
  static constexpr uint32_t kParts[] = {kCylinderBase, kCylinderTop};
  return side_and_caps(r, ray, h, solved, t0, t1, kCylinderSide, kCaps, kParts);
}

// intersect_cone: its side (the nappe z >= 0) and base.
RT_SIMD_INLINE HalfCrossings cone_half(const ObjectLanes& r, const RayLanes& ray, int h) {
  const Double4 ox = wide(r.o[0], h), oy = wide(r.o[1], h), oz = wide(r.o[2], h);
  const Double4 dx = wide(r.d[0], h), dy = wide(r.d[1], h), dz = wide(r.d[2], h);
  Double4 t0, t1;
  const Mask4d solved = solve_quadratic_half(dx * dx + dy * dy - dz * dz, splat4d(2.0) * (ox * dx + oy * dy - oz * dz),
                                             ox * ox + oy * oy - oz * oz, t0, t1);
  static constexpr float kCaps[] = {1.0f};
  static constexpr uint32_t kParts[] = {kConeBase};
  return side_and_caps(r, ray, h, solved, t0, t1, kConeSide, kCaps, kParts);
}

// intersect_plane: the plane y = 0 within |x|, |z| <= 1, in float.
RT_SIMD_INLINE LaneCrossings plane_lanes(const ObjectLanes& r, const RayLanes& ray) {
  const Float8 t = -r.o[1] / r.d[1];
  const Float8 x = r.o[0] + t * r.d[0], z = r.o[2] + t * r.d[2];
  const Float8 one = splat8(1.0f);
  const Mask8 found = (r.d[1] != splat8(0.0f)) & (t > ray.tmin) & (t < ray.tmax) & ~(abs8(x) > one) & ~(abs8(z) > one);
  return {movemask8(found), t, Mask8{}};
}

// The crossings the single-ray test of `shape` first finds, for the lanes of `lanes`.
RT_SIMD_INLINE LaneCrossings shape_crossings(const AnalyticShape& shape, const ObjectLanes& r, const RayLanes& ray,
                                             unsigned lanes) {
  // A kind without a case here: every lane, at a t (NaN) that leaves each to the single-ray test.
  LaneCrossings c{0xffu, splat8(std::numeric_limits<float>::quiet_NaN()), Mask8{}};
  switch (shape.kind) {
    case ShapeKind::kSphere: c = join(sphere_half(r, ray, 0), sphere_half(r, ray, 1)); break;
    case ShapeKind::kCube: c = join(cube_half(r, ray, 0), cube_half(r, ray, 1)); break;
    case ShapeKind::kCylinder: c = join(cylinder_half(r, ray, 0), cylinder_half(r, ray, 1)); break;
    case ShapeKind::kPlane: c = plane_lanes(r, ray); break;
    case ShapeKind::kCone: c = join(cone_half(r, ray, 0), cone_half(r, ray, 1)); break;
  }
  c.lanes &= lanes;
  return c;
}

// origin_rounding (core/transform.h) lane by lane: transformed_point_error's bound on the
// object-space origin (its input error zero), along the object-space direction.
RT_SIMD_INLINE Float8 origin_rounding_lanes(const Mat4& m, const RayLanes& ray, const ObjectLanes& r) {
  const Float8 zero = splat8(0.0f);
  Float8 e[3];
  for (int i = 0; i < 3; ++i) {
    const Float8 magnitude = abs8(splat8(m[0][i]) * ray.origin[0]) + abs8(splat8(m[1][i]) * ray.origin[1]) +
                             abs8(splat8(m[2][i]) * ray.origin[2]) + splat8(std::fabs(m[3][i]));
    const Float8 carried =
        splat8(std::fabs(m[0][i])) * zero + splat8(std::fabs(m[1][i])) * zero + splat8(std::fabs(m[2][i])) * zero;
    e[i] = splat8(float_gamma(3)) * magnitude + splat8(1.0f + float_gamma(3)) * carried;
  }
  const Float8 length2 = r.d[0] * r.d[0] + r.d[1] * r.d[1] + r.d[2] * r.d[2];
  const Float8 along = (abs8(r.d[0]) * e[0] + abs8(r.d[1]) * e[1] + abs8(r.d[2]) * e[2]) / length2;
  return length2 > zero ? along : zero;
}

// The lanes of `lanes` where the single-ray test of `shape` certainly reports the crossing in
// `c` (its t and part), and in `unsure` those still to be asked of that test. intersect_shape
// takes its first crossing when it lies beyond the origin's rounding; one short of it needs that
// test's second look (rare: a ray that leaves the shape's own surface).
RT_SIMD_INLINE unsigned shape_hits(const AnalyticShape& shape, const RayLanes& ray, unsigned lanes, LaneCrossings& c,
                                   unsigned& unsure) {
  const ObjectLanes r(shape.transform.to_object, ray);
  c = shape_crossings(shape, r, ray, lanes);
  if (c.lanes == 0) {
    unsure = 0;
    return 0;
  }
  const Float8 floor = ray.tmin + origin_rounding_lanes(shape.transform.to_object, ray, r);
  const unsigned sure = c.lanes & movemask8(c.t > floor);
  unsure = c.lanes & ~sure;
  return sure;
}

#endif

}  // namespace RTCLI_ISA_NS
}  // namespace rt
