// The packet walks test a leaf's analytic shapes for all of a packet's rays at once
// (core/accel/shape_lanes.h) and leave to the single-ray test only the rays that may cross them.
// Each ray must still get exactly its own answer, where that answer is decided at the edge: rays
// that leave a shape's own surface (its origin's rounding decides), rays along an axis (a
// direction component of exactly 0: the slabs' and the plane's parallel cases), grazing rays,
// and intervals that end right at a crossing.
#include <cstring>

#include <catch2/catch.hpp>

#include "core/accel/bvh.h"
#include "core/accel/primitives.h"
#include "core/rng.h"
#include "core/shapes/analytic_shape.h"

using namespace rt;

namespace {

Vec3 random_in(Rng& rng, float lo, float hi) {
  return Vec3(lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float());
}

// Many small shapes of every kind close together (leaves of several shapes), half of them
// rotated and stretched, half axis-aligned, over a floor plane.
PrimitiveSet shape_set() {
  PrimitiveSet set;
  Rng rng(5);
  const ShapeKind kinds[] = {ShapeKind::kSphere, ShapeKind::kCube, ShapeKind::kPlane, ShapeKind::kCylinder,
                             ShapeKind::kCone};
  for (int i = 0; i < 300; ++i) {
    AnalyticShape shape;
    shape.kind = kinds[i % 5];
    const Vec3 scale = Vec3(0.2f) + 0.8f * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
    const Vec3 rotate = i % 2 ? random_in(rng, -180, 180) : Vec3(0.0f);
    shape.transform = *make_transform(compose_trs(random_in(rng, -4, 4), rotate, scale));
    set.shapes.push_back(shape);
  }
  AnalyticShape floor;
  floor.kind = ShapeKind::kPlane;
  floor.transform = *make_transform(compose_trs(Vec3(0, -4.5f, 0), Vec3(0.0f), Vec3(10.0f)));
  set.shapes.push_back(floor);
  return set;
}

// A direction with some components exactly 0, one time in three.
Vec3 direction(Rng& rng, int p) {
  Vec3 d = random_in(rng, -1.0f, 1.0f);
  if (p % 3 == 0) d[p % 9 / 3] = 0.0f;
  if (p % 9 == 0) d[(p / 9) % 3] = 0.0f;
  if (glm::length(d) < 1e-3f) d = Vec3(0.0f, 0.0f, 1.0f);
  return d;
}

bool same_hit(const Hit& a, const Hit& b) {
  return std::memcmp(&a.t, &b.t, sizeof a.t) == 0 && a.prim == b.prim && a.part == b.part;
}

}  // namespace

TEST_CASE("BVH packets: rays leaving shapes' surfaces, along axes and grazing get their own answers", "[bvh][isa]") {
  const PrimitiveSet set = shape_set();
  for (const Isa isa : kAllIsas) {
    if (!isa_supported(isa)) continue;  // test_bvh_isa.cpp warns
    INFO(isa_name(isa));
    const Bvh bvh(set, BvhBuildOptions{1, isa});
    Rng rng(17);
    int rays = 0, blocked = 0, hits = 0, on_surface = 0, differences = 0;
    for (int p = 0; p < 20000; ++p) {
      const int count = 2 + p % (kPacketSize - 1);
      Ray packet[kPacketSize];
      // A packet from one point: a shape's surface where a ray from outside met one (t and
      // origin as the renderer's shadow rays have them: from the hit point, tmin 0), else a point
      // anywhere; towards a small patch (coherent) or all around.
      Vec3 origin = random_in(rng, -6.0f, 6.0f);
      Ray probe{random_in(rng, -8.0f, 8.0f), random_in(rng, -1.0f, 1.0f), 0.0f, kInfinity};
      Hit h;
      if (p % 2 == 0 && bvh.intersect(probe, h)) {
        origin = probe.origin + h.t * probe.direction;
        ++on_surface;
      }
      const Vec3 target = random_in(rng, -5.0f, 5.0f);
      for (int i = 0; i < count; ++i) {
        Ray& r = packet[i];
        r.origin = origin;
        r.direction = p % 4 < 2 ? direction(rng, p) : target + 0.3f * direction(rng, p + i) - origin;
        if (glm::length(r.direction) < 1e-3f) r.direction = Vec3(1.0f, 0.0f, 0.0f);
        r.tmin = p % 5 == 0 ? 1e-4f : 0.0f;
        r.tmax = i % 3 == 0 ? 0.5f + 4.0f * rng.next_float() : kInfinity;
      }
      const unsigned mask = bvh.occluded_packet(packet, count);
      Ray walked[kPacketSize];
      std::copy(packet, packet + count, walked);
      Hit got[kPacketSize];
      const unsigned found = bvh.intersect_packet(walked, got, count);
      for (int i = 0; i < count; ++i) {
        ++rays;
        const bool alone = bvh.occluded(packet[i]);
        blocked += alone ? 1 : 0;
        if (alone != bool(mask >> i & 1u)) ++differences;
        Ray single = packet[i];
        Hit hit;
        const bool hit_alone = bvh.intersect(single, hit);
        hits += hit_alone ? 1 : 0;
        if (hit_alone != bool(found >> i & 1u) ||
            (hit_alone && (!same_hit(hit, got[i]) || walked[i].tmax != single.tmax)))
          ++differences;
      }
      if (mask >> count || found >> count) ++differences;  // no bit beyond the packet
    }
    CHECK(differences == 0);
    CHECK(on_surface > 4000);
    CHECK(blocked > rays / 4);
    CHECK(blocked < rays - rays / 10);
    CHECK(hits >= blocked);
  }
}

TEST_CASE("BVH packets: a shape crossed at a double t just short of the interval's end, whose float is that end",
          "[bvh][isa]") {
  // From z = 3 along (0, 0, -3) the unit sphere's near root is 2/3 in double, which rounds up to
  // the float 2/3: with that float as tmax, the single ray finds the crossing (2/3 < tmax in
  // double) and reports t = tmax. The packet must not take the equal float for "beyond the end".
  PrimitiveSet set;
  AnalyticShape sphere;
  sphere.kind = ShapeKind::kSphere;
  sphere.transform = *make_transform(Mat4(1.0f));
  set.shapes.push_back(sphere);
  const float end = static_cast<float>(2.0 / 3.0);
  REQUIRE(static_cast<double>(end) > 2.0 / 3.0);
  for (const Isa isa : kAllIsas) {
    if (!isa_supported(isa)) continue;
    INFO(isa_name(isa));
    const Bvh bvh(set, BvhBuildOptions{1, isa});
    Ray packet[kPacketSize];
    for (Ray& r : packet) r = Ray{Vec3(0.0f, 0.0f, 3.0f), Vec3(0.0f, 0.0f, -3.0f), 0.0f, end};
    Ray single = packet[0];
    Hit alone;
    REQUIRE(bvh.intersect(single, alone));
    CHECK(alone.t == end);
    Hit got[kPacketSize];
    CHECK(bvh.intersect_packet(packet, got, kPacketSize) == (1u << kPacketSize) - 1u);
    for (int i = 0; i < kPacketSize; ++i) CHECK(same_hit(alone, got[i]));
  }
}
