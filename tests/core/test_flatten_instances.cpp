// Flattened mesh instances (core/flatten_instances.h): the top level holds their triangles in
// world space, and every query names a hit on one as the instance's, with the triangle's index in
// its mesh, as walking the instance does. The two differ only by rounding: the triangles are
// moved to the world instead of the rays to object space.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <tuple>
#include <vector>

#include <catch2/catch.hpp>

#include "core/accel/bvh.h"
#include "core/accel/bvh_traversal.h"
#include "core/flatten_instances.h"
#include "core/rng.h"

using namespace rt;

namespace {

Vec3 random_in(Rng& rng, float lo, float hi) {
  return Vec3(lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float());
}

// Three meshes of the same 600 small triangles, each placed once (turned and scaled; mirrored;
// behind an alpha cutout that keeps every triangle), beside a sphere.
struct FlatScene {
  std::vector<MeshGeometry> meshes = std::vector<MeshGeometry>(3);
  AlphaCutout cutout;
  PrimitiveSet top;
};

void build(FlatScene& s) {
  Rng rng(3);
  TriangleMesh mesh;
  for (int i = 0; i < 600; ++i) {
    const Vec3 c = random_in(rng, -3.0f, 3.0f);
    for (int k = 0; k < 3; ++k) {
      mesh.indices.push_back(static_cast<uint32_t>(mesh.positions.size()));
      mesh.positions.push_back(c + 0.4f * random_in(rng, -1, 1));
    }
  }
  for (MeshGeometry& g : s.meshes) {
    g.mesh = mesh;
    g.bvh = Bvh(make_triangle_set(mesh), BvhBuildOptions{1, Isa::kSse});
    g.bounds = g.bvh.bounds();
  }
  s.cutout.mesh = &s.meshes[2].mesh;
  s.cutout.masked = true;  // no vertex alpha: every triangle kept
  s.top.instances.push_back(
      place_mesh(s.meshes[0].bvh, *make_transform(compose_trs(Vec3(5, 0, 0), Vec3(10, 30, 0), Vec3(1.3f))), 0, 0));
  s.top.instances.push_back(
      place_mesh(s.meshes[1].bvh, *make_transform(compose_trs(Vec3(-5, 1, 0), Vec3(0), Vec3(-1, 1, 1))), 1, 0));
  s.top.instances.push_back(
      place_mesh(s.meshes[2].bvh, *make_transform(compose_trs(Vec3(0, -5, 2), Vec3(0), Vec3(1))), 2, 0, &s.cutout));
  AnalyticShape sphere;
  sphere.kind = ShapeKind::kSphere;
  sphere.transform = *make_transform(compose_trs(Vec3(0, 4, 0), Vec3(0), Vec3(1.5f)));
  s.top.shapes.push_back(sphere);
}

Ray random_ray(Rng& rng) {
  const Vec3 o = random_in(rng, -12.0f, 12.0f);
  Vec3 d = random_in(rng, -6.0f, 6.0f) - o;
  if (glm::length(d) < 1e-3f) d = Vec3(0, 1, 0);
  return Ray{o, d, 1e-4f, kInfinity};
}

// A hit's primitive by its kind, its place among its kind and the part met: the ids of shapes and
// instances move up by the flattened triangles that precede them.
std::tuple<PrimitiveKind, size_t, uint32_t> named(const Bvh& bvh, const Hit& h) {
  switch (bvh.kind(h.prim)) {
    case PrimitiveKind::kInstance:
      return {PrimitiveKind::kInstance, static_cast<size_t>(&bvh.instance(h.prim) - bvh.instances().data()), h.part};
    case PrimitiveKind::kShape:
      return {PrimitiveKind::kShape, static_cast<size_t>(&bvh.shape(h.prim) - bvh.shapes().data()), h.part};
    default: return {bvh.kind(h.prim), h.prim, h.part};
  }
}

bool same_hit(const Hit& a, const Hit& b) {
  return std::memcmp(&a.t, &b.t, sizeof a.t) == 0 && std::memcmp(&a.b1, &b.b1, sizeof a.b1) == 0 &&
         std::memcmp(&a.b2, &b.b2, sizeof a.b2) == 0 && a.prim == b.prim && a.part == b.part;
}

}  // namespace

TEST_CASE("flatten_instances: the placements without a cutout become world-space triangles, named by owner",
          "[bvh][flatten]") {
  FlatScene s;
  build(s);
  flatten_instances(s.top, s.meshes);
  CHECK(s.top.instances[0].flattened);
  CHECK(s.top.instances[1].flattened);
  CHECK_FALSE(s.top.instances[2].flattened);  // its cutout reads the mesh's own ids
  REQUIRE(s.top.triangles.size() == 1200);
  REQUIRE(s.top.owners.size() == 1200);
  CHECK(s.top.owners[0].instance == 0);
  CHECK(s.top.owners[1199].instance == 1);
  CHECK(s.top.owners[1199].triangle == 599);
  // The second placement's last triangle, moved to the world by hand.
  const TriangleMesh& mesh = s.meshes[1].mesh;
  const Vec3 v = s.top.instances[1].transform.point_to_world(mesh.positions[mesh.indices[3 * 599]]);
  CHECK(s.top.triangles[1199].v0 == v);
  const Bvh bvh(s.top, BvhBuildOptions{2, best_isa()});
  CHECK(bvh.check_structure().empty());
  CHECK(bvh.instances().size() == 3);  // still listed: surfaces and materials are read through them
}

TEST_CASE(
    "flatten_instances: a mesh placed twice, a placement past the budget or one reaching infinity stays an instance",
    "[bvh][flatten]") {
  FlatScene s;
  build(s);
  flatten_instances(s.top, s.meshes, 1000);  // room for one placement of 600
  CHECK(s.top.instances[0].flattened);
  CHECK_FALSE(s.top.instances[1].flattened);
  CHECK(s.top.triangles.size() == 600);

  FlatScene twice;
  build(twice);
  twice.top.instances[1].mesh = 0;  // the first mesh placed again: stored and walked once
  twice.top.instances[1].bvh = &twice.meshes[0].bvh;
  flatten_instances(twice.top, twice.meshes);
  CHECK_FALSE(twice.top.instances[0].flattened);
  CHECK_FALSE(twice.top.instances[1].flattened);
  CHECK(twice.top.triangles.empty());

  // A triangle 6 wide, scaled by 1e38: its vertices and box stay below the float limit, its
  // world-space edge does not. Its own walk, in object space, stays.
  std::vector<MeshGeometry> wide(1);
  wide[0].mesh.positions = {Vec3(-3, 0, 0), Vec3(3, 0, 0), Vec3(0, 3, 0)};
  wide[0].mesh.indices = {0, 1, 2};
  wide[0].bvh = Bvh(make_triangle_set(wide[0].mesh), BvhBuildOptions{1, Isa::kSse});
  PrimitiveSet far;
  far.instances.push_back(place_mesh(wide[0].bvh, *make_transform(compose_trs(Vec3(0), Vec3(0), Vec3(1e38f))), 0, 0));
  REQUIRE(is_finite(far.instances[0].bounds.hi));
  flatten_instances(far, wide);
  CHECK_FALSE(far.instances[0].flattened);
  CHECK(far.triangles.empty());
}

TEST_CASE("flatten_instances: every query finds what walking the instances finds, named alike", "[bvh][flatten]") {
  FlatScene walked_scene, flat_scene;
  build(walked_scene);
  build(flat_scene);
  flatten_instances(flat_scene.top, flat_scene.meshes);
  for (const Isa isa : kAllIsas) {
    if (!isa_supported(isa)) continue;
    INFO(isa_name(isa));
    const Bvh walked(walked_scene.top, BvhBuildOptions{2, isa}), flat(flat_scene.top, BvhBuildOptions{2, isa});
    Rng rng(17);
    int hits = 0, instance_hits = 0, other = 0, blocked_apart = 0, packet_apart = 0, crossings_apart = 0;
    const int rays = 20000;
    for (int i = 0; i < rays; ++i) {
      const Ray r = random_ray(rng);
      Ray a = r, b = r;
      Hit ha, hb;
      const bool got_a = walked.intersect(a, ha), got_b = flat.intersect(b, hb);
      if (got_a) ++hits;
      if (got_b && flat.kind(hb.prim) == PrimitiveKind::kInstance) ++instance_hits;
      // The same primitive and triangle, the distance within rounding; or a ray that grazes an
      // edge, where rounding decides which of two triangles it meets.
      if (got_a != got_b ||
          (got_a && (named(walked, ha) != named(flat, hb) || std::fabs(ha.t - hb.t) > 1e-4f * std::max(1.0f, ha.t))))
        ++other;
      if (walked.occluded(r) != flat.occluded(r)) ++blocked_apart;
      // Each crossing, by name: the same set.
      std::set<std::tuple<PrimitiveKind, size_t, uint32_t>> ca, cb;
      walked.for_each_hit(r, [&](const Hit& h) { return ca.insert(named(walked, h)), false; });
      flat.for_each_hit(r, [&](const Hit& h) { return cb.insert(named(flat, h)), false; });
      if (ca != cb) ++crossings_apart;
    }
    // Packets of neighbouring rays: each ray gets its own single-ray hit, bit for bit.
    for (int p = 0; p < 3000; ++p) {
      const Ray centre = random_ray(rng);
      Ray packet[kPacketSize], alone[kPacketSize];
      Hit got[kPacketSize];
      for (int k = 0; k < kPacketSize; ++k) {
        packet[k] = centre;
        packet[k].direction += 0.05f * random_in(rng, -1.0f, 1.0f);
        alone[k] = packet[k];
      }
      const unsigned mask = flat.intersect_packet(packet, got, kPacketSize);
      for (int k = 0; k < kPacketSize; ++k) {
        Hit h;
        const bool single = flat.intersect(alone[k], h);
        if (single != bool(mask >> k & 1u) || (single && !same_hit(h, got[k]))) ++packet_apart;
      }
    }
    CHECK(hits > rays / 4);
    CHECK(instance_hits > rays / 8);  // named as the instances', never as a loose triangle
    // None of these rays, on this machine; a ray that grazes an edge may fall to either side.
    CHECK(other <= rays / 1000);
    CHECK(blocked_apart <= rays / 1000);
    CHECK(crossings_apart <= rays / 500);
    CHECK(packet_apart == 0);
  }
}
