// The BVH kernels of every instruction set this CPU runs find exactly what the baseline's find:
// the same primitive, distance and barycentrics, bit for bit, and the same occlusion answers.
#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

#include <catch2/catch.hpp>

#include "core/accel/bvh.h"
#include "core/accel/bvh_traversal.h"
#include "core/accel/primitives.h"
#include "core/mesh.h"
#include "core/rng.h"

using namespace rt;

namespace {

Vec3 random_in(Rng& rng, float lo, float hi) {
  return Vec3(lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float());
}

// Triangles of mixed sizes (leaves of quads and of single triangles), every analytic kind, and
// two placed instances of a mesh BVH, one behind a single-sided alpha cutout that drops every
// third triangle (its vertex alpha). Every 25th triangle, in the mesh and at the top, comes twice
// under two ids: a ray meets both at exactly the same distance, and the lower id must win
// whichever order the walk takes.
struct IsaScene {
  TriangleMesh mesh;
  Bvh mesh_bvh;
  AlphaCutout cutout;
  PrimitiveSet top;
};

void build(IsaScene& s, Isa isa) {
  Rng rng(7);
  for (uint32_t i = 0; i < 2000; ++i) {
    const Vec3 c = random_in(rng, -4.0f, 4.0f);
    const float size = i % 7 == 0 ? 1.5f : 0.3f;
    for (int k = 0; k < 3; ++k) {
      s.mesh.indices.push_back(static_cast<uint32_t>(s.mesh.positions.size()));
      s.mesh.positions.push_back(c + size * random_in(rng, -1, 1));
      s.mesh.colors.push_back(Vec4(1.0f, 1.0f, 1.0f, i % 3 == 0 ? 0.0f : 1.0f));
    }
    if (i % 25 == 0)
      for (int k = 3; k > 0; --k) s.mesh.indices.push_back(s.mesh.indices[s.mesh.indices.size() - 3]);
  }
  s.mesh_bvh = Bvh(make_triangle_set(s.mesh), BvhBuildOptions{1, isa});
  s.cutout.mesh = &s.mesh;
  s.cutout.masked = true;
  s.cutout.single_sided = true;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 c = random_in(rng, -10.0f, 10.0f);
    const float size = i % 10 == 0 ? 3.0f : 0.4f;
    s.top.triangles.push_back(PackedTriangle::from_vertices(
        c + size * random_in(rng, -1, 1), c + size * random_in(rng, -1, 1), c + size * random_in(rng, -1, 1)));
    if (i % 25 == 0) s.top.triangles.push_back(s.top.triangles.back());
  }
  const ShapeKind kinds[] = {ShapeKind::kSphere, ShapeKind::kCube, ShapeKind::kPlane, ShapeKind::kCylinder,
                             ShapeKind::kCone};
  for (int i = 0; i < 40; ++i) {
    AnalyticShape shape;
    shape.kind = kinds[i % 5];
    const Vec3 scale = Vec3(0.3f) + 1.5f * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
    shape.transform = *make_transform(compose_trs(random_in(rng, -10, 10), random_in(rng, -180, 180), scale));
    s.top.shapes.push_back(shape);
  }
  s.top.instances.push_back(
      place_mesh(s.mesh_bvh, *make_transform(compose_trs(Vec3(6, 0, 0), Vec3(0, 30, 0), Vec3(1))), 0, 0));
  s.top.instances.push_back(place_mesh(
      s.mesh_bvh, *make_transform(compose_trs(Vec3(-6, 1, 0), Vec3(20, 0, 0), Vec3(0.7f))), 0, 0, &s.cutout));
}

bool same_hit(const Hit& a, const Hit& b) {
  return std::memcmp(&a.t, &b.t, sizeof a.t) == 0 && std::memcmp(&a.b1, &b.b1, sizeof a.b1) == 0 &&
         std::memcmp(&a.b2, &b.b2, sizeof a.b2) == 0 && a.prim == b.prim && a.part == b.part;
}

// Packet p of a sequence: 1 to 8 rays (count), half the packets coherent (one origin, towards a
// square of side 2 * spread around a target within +-target_range), half rays from anywhere; a
// third of the rays end at tmax_lo + tmax_span * u, the rest never.
void make_packet(Rng& rng, int p, int count, float target_range, float spread, float tmax_lo, float tmax_span,
                 Ray* packet) {
  const Vec3 origin = random_in(rng, -14.0f, 14.0f), target = random_in(rng, -target_range, target_range);
  for (int i = 0; i < count; ++i) {
    Ray& r = packet[i];
    r.origin = p % 2 ? origin : random_in(rng, -14.0f, 14.0f);
    r.direction = (p % 2 ? target + random_in(rng, -spread, spread) : random_in(rng, -3.0f, 3.0f)) - r.origin;
    if (glm::length(r.direction) < 1e-3f) r.direction = Vec3(0.0f, 1.0f, 0.0f);
    r.tmin = 1e-4f;
    r.tmax = i % 3 == 0 ? tmax_lo + tmax_span * rng.next_float() : kInfinity;
  }
}

}  // namespace

TEST_CASE("BVH kernels: every instruction set this CPU runs gives the baseline's hits, bit for bit", "[bvh][isa]") {
  CHECK(isa_supported(Isa::kSse));
  CHECK(isa_supported(best_isa()));
  CHECK(parse_isa("avx2") == Isa::kAvx2);
  CHECK_FALSE(parse_isa("auto"));
  IsaScene base_scene;
  build(base_scene, Isa::kSse);
  const Bvh base(base_scene.top, BvhBuildOptions{1, Isa::kSse});
  REQUIRE(base.isa() == Isa::kSse);
  for (const Isa isa : kAllIsas) {
    if (isa == Isa::kSse) continue;
    if (!isa_supported(isa)) {
      WARN("this CPU does not run " << isa_name(isa) << ": its kernels are built but not tested here");
      continue;
    }
    INFO(isa_name(isa));
    IsaScene scene;
    build(scene, isa);
    const Bvh bvh(scene.top, BvhBuildOptions{2, isa});
    REQUIRE(bvh.isa() == isa);
    REQUIRE(bvh.nodes().size() == base.nodes().size());
    Rng rng(99);
    int hits = 0, blocked = 0, differences = 0;
    for (int i = 0; i < 40000; ++i) {
      // Rays from all around, many of them aimed through the middle, short and long.
      const Vec3 o = random_in(rng, -14.0f, 14.0f);
      const Vec3 d = i % 2 ? random_in(rng, -1.0f, 1.0f) : random_in(rng, -3.0f, 3.0f) - o;
      if (glm::length(d) < 1e-3f) continue;
      const float tmax = i % 3 == 0 ? 0.5f + 20.0f * rng.next_float() : kInfinity;
      Ray a{o, d, 1e-4f, tmax}, b = a;
      const Ray s = a;
      Hit ha, hb;
      const bool got_a = base.intersect(a, ha), got_b = bvh.intersect(b, hb);
      hits += got_b ? 1 : 0;
      if (got_a != got_b || (got_a && !same_hit(ha, hb))) ++differences;
      const bool occ_a = base.occluded(s), occ_b = bvh.occluded(s);
      blocked += occ_b ? 1 : 0;
      if (occ_a != occ_b) ++differences;
    }
    CHECK(differences == 0);
    CHECK(hits > 10000);  // the rays do meet the scene, on all paths
    CHECK(blocked > 10000);
  }
}

TEST_CASE("BVH kernels: a packet of rays gets each ray's own occlusion answer, on every instruction set",
          "[bvh][isa]") {
  for (const Isa isa : kAllIsas) {
    if (!isa_supported(isa)) continue;  // the case above warns
    INFO(isa_name(isa));
    IsaScene scene;
    build(scene, isa);
    const Bvh bvh(scene.top, BvhBuildOptions{2, isa});
    Rng rng(7);
    int rays = 0, blocked = 0, differences = 0;
    for (int p = 0; p < 6000; ++p) {
      // The coherent half as a point's shadow rays to an area light.
      const int count = 1 + p % kPacketSize;
      Ray packet[kPacketSize];
      make_packet(rng, p, count, 4.0f, 0.5f, 0.2f, 1.0f, packet);
      const unsigned mask = bvh.occluded_packet(packet, count);
      for (int i = 0; i < count; ++i) {
        const bool alone = bvh.occluded(packet[i]);
        ++rays;
        blocked += alone ? 1 : 0;
        if (alone != bool(mask >> i & 1u)) ++differences;
      }
      if (mask >> count) ++differences;  // no bit beyond the packet
    }
    CHECK(differences == 0);
    CHECK(blocked > rays / 5);
    CHECK(blocked < rays - rays / 20);
  }
}

TEST_CASE("BVH kernels: a packet of rays gets each ray's own closest hit, on every instruction set, ties included",
          "[bvh][isa]") {
  IsaScene base_scene;
  build(base_scene, Isa::kSse);
  const Bvh base(base_scene.top, BvhBuildOptions{1, Isa::kSse});
  for (const Isa isa : kAllIsas) {
    if (!isa_supported(isa)) continue;  // the first case warns
    INFO(isa_name(isa));
    IsaScene scene;
    build(scene, isa);
    const Bvh bvh(scene.top, BvhBuildOptions{2, isa});
    Rng rng(11);
    int rays = 0, hits = 0, twins = 0, differences = 0;
    for (int p = 0; p < 6000; ++p) {
      // The coherent half as neighbouring camera rays.
      const int count = 1 + p % kPacketSize;
      Ray packet[kPacketSize];
      make_packet(rng, p, count, 6.0f, 1.0f, 1.0f, 20.0f, packet);
      Ray walked[kPacketSize];
      std::copy(packet, packet + count, walked);
      Hit got[kPacketSize];
      const unsigned mask = bvh.intersect_packet(walked, got, count);
      if (mask >> count) ++differences;  // no bit beyond the packet
      for (int i = 0; i < count; ++i) {
        Ray alone = packet[i], baseline = packet[i];
        Hit h, hb;
        const bool hit = bvh.intersect(alone, h);
        base.intersect(baseline, hb);
        ++rays;
        if (!hit) {
          if (mask >> i & 1u) ++differences;
          continue;
        }
        ++hits;
        // A twin's hit: the same triangle under the next id, which must lose.
        const bool twin =
            bvh.kind(h.prim) == PrimitiveKind::kTriangle && h.prim + 1 < bvh.triangle_count() &&
            std::memcmp(&scene.top.triangles[h.prim], &scene.top.triangles[h.prim + 1], sizeof(PackedTriangle)) == 0;
        twins += twin ? 1 : 0;
        const bool lost =
            bvh.kind(h.prim) == PrimitiveKind::kTriangle && h.prim > 0 &&
            std::memcmp(&scene.top.triangles[h.prim], &scene.top.triangles[h.prim - 1], sizeof(PackedTriangle)) == 0;
        if (lost) ++differences;  // the twin with the higher id won
        if (!(mask >> i & 1u) || !same_hit(h, got[i]) || !same_hit(h, hb) || walked[i].tmax != alone.tmax)
          ++differences;
      }
    }
    CHECK(differences == 0);
    CHECK(hits > rays / 4);
    CHECK(twins > 20);  // exact ties were met
  }
}

TEST_CASE(
    "BVH kernels: NaN and infinite rays miss in every kernel, single, packet and any-hit, on every instruction set",
    "[bvh][isa]") {
  // What a stereo camera with convergence 1e-45 made (issue 36): an infinite window offset, rays
  // that are not finite, and a packet walk that entered every unused child slot and wrote past its
  // fixed stack. Each kernel must answer such a ray with a miss, and the finite rays of the same
  // packet with their own answers.
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = kInfinity;
  const Ray bad[] = {
      Ray{Vec3(nan, 0, 0), Vec3(0, 0, -1), 0.0f, kInfinity},  Ray{Vec3(0, 0, 20), Vec3(nan, 0, -1), 0.0f, kInfinity},
      Ray{Vec3(inf, 0, 0), Vec3(-1, 0, 0), 0.0f, kInfinity},  Ray{Vec3(0, 0, 20), Vec3(inf, 1, -1), 0.0f, kInfinity},
      Ray{Vec3(0, 0, 20), Vec3(0, 0, -inf), 0.0f, kInfinity}, Ray{Vec3(0, 0, 20), Vec3(0, 0, -1), nan, kInfinity},
      Ray{Vec3(0, 0, 20), Vec3(0, 0, -1), 0.0f, nan},         Ray{Vec3(-inf, -inf, -inf), Vec3(inf), 0.0f, kInfinity},
  };
  constexpr int kBad = static_cast<int>(sizeof bad / sizeof bad[0]);
  static_assert(kBad == kPacketSize);
  const Ray good{Vec3(0.1f, 0.2f, 20.0f), Vec3(0.01f, 0.02f, -1.0f), 1e-4f, kInfinity};
  for (const Isa isa : kAllIsas) {
    if (!isa_supported(isa)) continue;  // the first case warns
    INFO(isa_name(isa));
    IsaScene scene;
    build(scene, isa);
    const Bvh bvh(scene.top, BvhBuildOptions{2, isa});
    Ray g = good;
    Hit good_hit;
    REQUIRE(bvh.intersect(g, good_hit));  // the finite ray does meet the scene
    int answered = 0;
    for (int i = 0; i < kBad; ++i) {
      INFO("ray " << i);
      Ray r = bad[i];
      Hit h;
      CHECK_FALSE(bvh.intersect(r, h));
      CHECK_FALSE(scene.mesh_bvh.intersect(r, h, scene.cutout));
      CHECK_FALSE(bvh.occluded(bad[i]));
      int crossings = 0;
      bvh.for_each_hit(bad[i], [&](const Hit&) { return ++crossings, false; });
      auto visitor = [&](const Hit&) { return ++crossings, false; };
      bvh.visit_hits(bad[i], visitor);
      CHECK(crossings == 0);
      ++answered;
    }
    CHECK(answered == kBad);
    // Packets: all bad, and bad lanes among good ones (every other lane), at every packet size.
    for (int count = 1; count <= kPacketSize; ++count) {
      INFO("packet of " << count);
      Ray all_bad[kPacketSize], mixed[kPacketSize];
      for (int i = 0; i < count; ++i) {
        all_bad[i] = bad[i];
        mixed[i] = i % 2 ? bad[i] : good;
      }
      Hit hits[kPacketSize];
      CHECK(bvh.occluded_packet(all_bad, count) == 0u);
      CHECK(bvh.intersect_packet(all_bad, hits, count) == 0u);
      unsigned good_lanes = 0;
      for (int i = 0; i < count; i += 2) good_lanes |= 1u << i;
      CHECK(bvh.occluded_packet(mixed, count) == good_lanes);
      const unsigned found = bvh.intersect_packet(mixed, hits, count);
      CHECK(found == good_lanes);
      for (int i = 0; i < count; i += 2) CHECK(same_hit(hits[i], good_hit));
    }
  }
}
