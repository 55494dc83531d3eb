#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "core/accel/brute_force.h"
#include "core/accel/bvh.h"
#include "core/accel/bvh_traversal.h"
#include "core/rng.h"

using namespace rt;

namespace {

Vec3 random_in(Rng& rng, float lo, float hi) {
  return Vec3(lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float());
}

Vec3 random_direction(Rng& rng) {
  for (;;) {
    const Vec3 v = random_in(rng, -1.0f, 1.0f);
    const float l = glm::length(v);
    if (l > 1e-3f && l <= 1.0f) return v / l;
  }
}

// Thousands of triangles of mixed sizes plus every analytic kind, rotated and scaled.
PrimitiveSet random_scene(uint64_t seed) {
  Rng rng(seed);
  PrimitiveSet prims;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 c = random_in(rng, -10.0f, 10.0f);
    const float size = i % 10 == 0 ? 3.0f : 0.4f;
    prims.triangles.push_back(PackedTriangle::from_vertices(
        c + size * random_in(rng, -1, 1), c + size * random_in(rng, -1, 1), c + size * random_in(rng, -1, 1)));
  }
  const ShapeKind kinds[] = {ShapeKind::kSphere, ShapeKind::kCube, ShapeKind::kPlane, ShapeKind::kCylinder,
                             ShapeKind::kCone};
  for (int i = 0; i < 60; ++i) {
    AnalyticShape s;
    s.kind = kinds[i % 5];
    const Vec3 scale = Vec3(0.3f) + 1.5f * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
    s.transform = *make_transform(compose_trs(random_in(rng, -10, 10), random_in(rng, -180, 180), scale));
    prims.shapes.push_back(s);
  }
  return prims;
}

}  // namespace

TEST_CASE("BVH closest hits equal brute force on thousands of random rays", "[bvh]") {
  const PrimitiveSet prims = random_scene(42);
  for (unsigned threads : {1u, 2u}) {
    const Bvh bvh(prims, BvhBuildOptions{threads});
    REQUIRE(bvh.check_structure() == "");
    const BruteForce brute(prims);
    Rng rng(7);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
      Ray a;
      a.origin = random_in(rng, -14, 14);
      a.direction = random_direction(rng);
      Ray b = a;
      Hit ha, hb;
      const bool found_a = bvh.intersect(a, ha);
      const bool found_b = brute.intersect(b, hb);
      REQUIRE(found_a == found_b);
      if (!found_a) continue;
      ++hits;
      REQUIRE(ha.prim == hb.prim);
      REQUIRE(ha.t == hb.t);
      REQUIRE(ha.part == hb.part);
    }
    CHECK(hits > 5000);  // the test would prove little if most rays missed
  }
}

TEST_CASE("BVH occlusion equals brute force, with finite segments", "[bvh]") {
  const PrimitiveSet prims = random_scene(5);
  const Bvh bvh(prims, BvhBuildOptions{1});
  const BruteForce brute(prims);
  Rng rng(11);
  int blocked = 0;
  for (int i = 0; i < 20000; ++i) {
    Ray r;
    r.origin = random_in(rng, -12, 12);
    const Vec3 to = random_in(rng, -12, 12);
    r.direction = glm::normalize(to - r.origin);
    r.tmax = glm::length(to - r.origin);
    const bool occluded = bvh.occluded(r);
    REQUIRE(occluded == brute.occluded(r));
    blocked += occluded;
  }
  CHECK(blocked > 2000);
  CHECK(blocked < 18000);
}

TEST_CASE("BVH any-hit visitor sees every crossing brute force sees, and can stop early", "[bvh]") {
  const PrimitiveSet prims = random_scene(9);
  const Bvh bvh(prims, BvhBuildOptions{1});
  const BruteForce brute(prims);
  Rng rng(13);
  size_t crossings = 0, shapes_crossed_twice = 0;
  for (int i = 0; i < 5000; ++i) {
    Ray r;
    r.origin = random_in(rng, -12, 12);
    r.direction = random_direction(rng);
    r.tmax = 30.0f;
    std::vector<std::pair<uint32_t, float>> a, b;
    bvh.for_each_hit(r, [&](const Hit& h) { return a.emplace_back(h.prim, h.t), false; });
    brute.for_each_hit(r, [&](const Hit& h) { return b.emplace_back(h.prim, h.t), false; });
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    REQUIRE(a == b);
    for (size_t k = 0; k + 1 < a.size(); ++k) {
      REQUIRE(a[k].second > r.tmin);
      REQUIRE(a[k].second < r.tmax);
      const bool same_shape = a[k].first == a[k + 1].first;
      REQUIRE((!same_shape || a[k].second < a[k + 1].second));  // each crossing once
      shapes_crossed_twice += same_shape;
      REQUIRE((k + 2 >= a.size() || a[k].first != a[k + 2].first));  // convex: at most twice
    }
    crossings += a.size();
    // Stopping at the first crossing visits exactly one.
    int visits = 0;
    const bool stopped = bvh.for_each_hit(r, [&](const Hit&) { return ++visits, true; });
    REQUIRE(stopped == !a.empty());
    REQUIRE(visits == (a.empty() ? 0 : 1));
  }
  CHECK(crossings > 5000);
  CHECK(shapes_crossed_twice > 200);  // a ray through a sphere or cube is seen entering and leaving
}

TEST_CASE("BVH is the same for any build thread count", "[bvh]") {
  // Enough primitives that subtrees go to spare threads (past 4096 in a node) and that the root
  // bins on them (past 65,536): triangles alone (a mesh's BVH: quad leaves), and with shapes (a
  // scene's top level: slots).
  Rng rng(8);
  PrimitiveSet triangles;
  for (int i = 0; i < 70000; ++i) {
    const Vec3 c = random_in(rng, -10.0f, 10.0f);
    triangles.triangles.push_back(
        PackedTriangle::from_vertices(c, c + random_in(rng, 0, 0.3f), c + random_in(rng, 0, 0.3f)));
  }
  PrimitiveSet mixed = random_scene(3);
  mixed.triangles.insert(mixed.triangles.end(), triangles.triangles.begin(), triangles.triangles.end());
  for (const PrimitiveSet* prims : {&triangles, &mixed}) {
    const Bvh one(*prims, BvhBuildOptions{1}), four(*prims, BvhBuildOptions{4});
    CHECK(four.check_structure() == "");
    REQUIRE(one.nodes().size() == four.nodes().size());
    for (size_t i = 0; i < one.nodes().size(); ++i)
      REQUIRE(std::memcmp(&one.nodes()[i], &four.nodes()[i], sizeof(BvhNode)) == 0);
    REQUIRE(one.quads().size() == four.quads().size());
    REQUIRE(one.slots().size() == four.slots().size());
    for (size_t i = 0; i < one.quads().size(); ++i)
      REQUIRE(std::memcmp(&one.quads()[i], &four.quads()[i], sizeof(TriangleQuad)) == 0);
    for (size_t i = 0; i < one.slots().size(); ++i)
      REQUIRE(std::memcmp(&one.slots()[i], &four.slots()[i], sizeof(Bvh::Slot)) == 0);
  }
  // The mesh's leaves are quads, the scene's slots.
  CHECK(Bvh(triangles, {}).quads().size() > 10000);
  CHECK(Bvh(mixed, {}).slots().size() == mixed.size());
}

TEST_CASE("BVH edge cases: empty, a single primitive, many identical primitives", "[bvh]") {
  Ray r;
  r.origin = Vec3(0.2f, 0.2f, 5);
  r.direction = Vec3(0, 0, -1);
  Hit h;
  {
    const Bvh empty(PrimitiveSet{}, {});
    Ray copy = r;
    CHECK_FALSE(empty.intersect(copy, h));
    CHECK_FALSE(empty.occluded(r));
  }
  PrimitiveSet one;
  one.triangles.push_back(PackedTriangle::from_vertices({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  {
    const Bvh bvh(one, {});
    Ray copy = r;
    REQUIRE(bvh.intersect(copy, h));
    CHECK(h.t == Approx(5.0f));
    CHECK(copy.tmax == h.t);
  }
  PrimitiveSet same;  // coincident centroids: no SAH split exists, median splits must terminate
  for (int i = 0; i < 1000; ++i) same.triangles.push_back(one.triangles[0]);
  const Bvh bvh(same, {});
  CHECK(bvh.check_structure() == "");
  // Median splits away from the origin: their boxes once grew to include it (found by fuzzing).
  PrimitiveSet far;
  for (int i = 0; i < 100; ++i)
    far.triangles.push_back(
        PackedTriangle::from_vertices({5, 5, 5}, {6, 5, 5}, {5, 6, 5 + 0.01f * static_cast<float>(i % 2)}));
  const Bvh far_bvh(far, {});
  CHECK(far_bvh.check_structure() == "");
  for (const BvhNode& node : far_bvh.nodes())
    for (int slot = 0; slot < kBvhWidth; ++slot)
      if (child_used(node, slot)) CHECK(node.bounds[0][slot] == 5.0f);
  CHECK(bvh.stats().max_depth < Bvh::kMaxDepth);
  Ray copy = r;
  CHECK(bvh.intersect(copy, h));
}

TEST_CASE("BVH quality: far fewer node visits than primitives", "[bvh]") {
  const PrimitiveSet prims = random_scene(9);
  const Bvh bvh(prims, {});
  const BvhStats s = bvh.stats();
  CHECK(s.leaves > 0);
  CHECK(s.nodes < prims.size());
  CHECK(s.max_depth < 20);
  CHECK(s.sah_cost < 0.1 * prims.size());  // a linear list would cost prims.size()
}

// Coordinates near the float limit: centroid sums, extents and surface areas overflow in single
// precision. The build must still give a sound tree (it once indexed its bins with INT_MIN).
TEST_CASE("BVH over finite boxes at the edge of the float range", "[bvh]") {
  constexpr float kFar = 2e38f, kMax = std::numeric_limits<float>::max(), kHalf = kMax / 2;
  PrimitiveSet prims;
  AnalyticShape sphere;
  sphere.transform = *make_transform(compose_trs(Vec3(kFar, 0, 0), Vec3(0), Vec3(1)));
  prims.shapes.push_back(sphere);
  for (const float x : {0.0f, 3.0f}) {
    AnalyticShape cube;
    cube.kind = ShapeKind::kCube;
    cube.transform = *make_transform(compose_trs(Vec3(x, 0, 0), Vec3(0), Vec3(1)));
    prims.shapes.push_back(cube);
  }
  // Triangles spanning the whole range (edges stay finite up to half the float limit), and some
  // at both extremes.
  prims.triangles.push_back(PackedTriangle::from_vertices({-kHalf, -kHalf, -kHalf}, {kHalf, 0, 0}, {0, kHalf, kHalf}));
  for (int i = 0; i < 100; ++i) {
    const float x = (i % 2 ? kMax : -kMax) * (1.0f - 1e-6f * static_cast<float>(i));
    prims.triangles.push_back(PackedTriangle::from_vertices({x, 0, 0}, {x, 1, 0}, {x, 0, 1}));
  }
  for (unsigned threads : {1u, 2u}) {
    const Bvh bvh(prims, BvhBuildOptions{threads});
    CHECK(bvh.check_structure() == "");
    Ray r;
    r.origin = Vec3(0.5f, 0.5f, 10.0f);
    r.direction = Vec3(0, 0, -1);
    Hit hit;
    REQUIRE(bvh.intersect(r, hit));
    CHECK(hit.t == Approx(9.0f));  // the cube at the origin, not the huge triangle behind it
  }
}

TEST_CASE("BVH refuses primitives whose bounds are not finite", "[bvh]") {
  PrimitiveSet prims;
  const float inf = std::numeric_limits<float>::infinity();
  prims.triangles.push_back(PackedTriangle::from_vertices({0, 0, 0}, {inf, 0, 0}, {0, 1, 0}));
  CHECK_THROWS_AS(Bvh(prims, {}), std::invalid_argument);
  prims.triangles[0] = PackedTriangle::from_vertices({0, 0, 0}, {std::nanf(""), 0, 0}, {0, 1, 0});
  CHECK_THROWS_AS(Bvh(prims, {}), std::invalid_argument);
  prims.triangles[0] = PackedTriangle::from_vertices({-3e38f, 0, 0}, {3e38f, 0, 0}, {0, 1, 0});  // edge overflows
  CHECK_THROWS_AS(Bvh(prims, {}), std::invalid_argument);
}

TEST_CASE("BVH structure check notices a broken tree", "[bvh]") {
  const PrimitiveSet prims = random_scene(4);
  const Bvh bvh(prims, {});
  REQUIRE(bvh.check_structure() == "");
  Bvh broken = bvh;
  auto& node = const_cast<BvhNode&>(broken.nodes()[0]);
  node.bounds[1][0] = node.bounds[0][0];  // shrink child 0 to a slab in x: its primitives stick out
  CHECK_FALSE(broken.check_structure().empty());
}

// The Cornell box's five walls (flat boxes around everything) and two blocks: counted as one
// triangle's test each, the SAH kept all seven in one leaf, and every ray tested every one. A
// top-level primitive costs two node visits (bvh_build.cpp): the walls go to leaves of their own.
TEST_CASE("BVH splits a box's walls into leaves of their own", "[bvh]") {
  PrimitiveSet prims;
  const auto add = [&](ShapeKind kind, Vec3 translate, Vec3 rotate, Vec3 scale) {
    AnalyticShape s;
    s.kind = kind;
    s.transform = *make_transform(compose_trs(translate, rotate, scale));
    prims.shapes.push_back(s);
  };
  add(ShapeKind::kPlane, {2.78f, 0.0f, 2.796f}, {0, 0, 0}, {2.78f, 1, 2.796f});           // floor
  add(ShapeKind::kPlane, {2.78f, 5.488f, 2.796f}, {180, 0, 0}, {2.78f, 1, 2.796f});       // ceiling
  add(ShapeKind::kPlane, {2.78f, 2.744f, 5.592f}, {-90, 0, 0}, {2.78f, 1, 2.744f});       // back
  add(ShapeKind::kPlane, {5.56f, 2.744f, 2.796f}, {0, 0, 90}, {2.744f, 1, 2.796f});       // left
  add(ShapeKind::kPlane, {0.0f, 2.744f, 2.796f}, {0, 0, -90}, {2.744f, 1, 2.796f});       // right
  add(ShapeKind::kCube, {1.855f, 0.825f, 1.69f}, {0, -17, 0}, {0.835f, 0.825f, 0.835f});  // short block
  add(ShapeKind::kCube, {3.685f, 1.65f, 3.5125f}, {0, 17.2f, 0}, {0.83f, 1.65f, 0.83f});  // tall block
  const Bvh bvh(prims, {});
  CHECK(bvh.check_structure() == "");
  const BvhStats s = bvh.stats();
  INFO("leaves " << s.leaves << ", SAH cost " << s.sah_cost);
  CHECK(s.leaves >= 5);
  CHECK(s.sah_cost < 2.0 * 7);  // the one leaf's cost: every ray testing all seven
  // The closest hits are brute force's, whatever the tree: rays from the air above the blocks
  // (one starting inside a block that stands on the floor can leave it where the floor is, a tie
  // the two settle differently).
  Rng rng(7);
  const BruteForce brute(prims);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p = random_in(rng, 0.0f, 1.0f);
    Ray a(Vec3(0.1f, 3.4f, 0.1f) + p * Vec3(5.4f, 2.0f, 5.4f), random_direction(rng));
    Ray b = a;
    Hit ha, hb;
    REQUIRE(bvh.intersect(a, ha) == brute.intersect(b, hb));
    CHECK(ha.prim == hb.prim);
    CHECK(ha.t == hb.t);
  }
}
