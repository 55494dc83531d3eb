// A ray inside a closed shape (core/accel/shape_interiors.h): which shapes get an interior, and
// Bvh::intersect_from_inside giving the walk's answer bit for bit, for rays leaving a shape's
// surface inwards as the integrator makes them, and for hints that are wrong. Bvh::intersect_leaving
// giving it for rays leaving outwards, on every instruction set.
#include <vector>

#include <catch2/catch.hpp>

#include "core/accel/bvh.h"
#include "core/ray.h"
#include "core/rng.h"

using namespace rt;

namespace {

AnalyticShape shape(ShapeKind kind, Vec3 translate, Vec3 rotate, Vec3 scale) {
  AnalyticShape s;
  s.kind = kind;
  s.transform = *make_transform(compose_trs(translate, rotate, scale));
  return s;
}

Vec3 random_unit(Rng& rng) {
  for (;;) {
    const Vec3 v(2.0f * rng.next_float() - 1.0f, 2.0f * rng.next_float() - 1.0f, 2.0f * rng.next_float() - 1.0f);
    const float l2 = glm::dot(v, v);
    if (l2 > 1e-4f && l2 <= 1.0f) return v / std::sqrt(l2);
  }
}

// Shape ids of the set below, in order after the triangles (none here).
enum Id : uint32_t {
  kFloor,
  kBall,    // resting on the floor: the floor its one neighbour
  kBlock,   // resting on the floor: its bottom face and the floor tie
  kTurned,  // a block turned and tilted, clear of everything
  kPillar,  // a cylinder standing on the floor
  kCone,    // a cone, apex down, off the floor
  kShell,   // a ball with a smaller one inside it
  kCore,    // that smaller ball
  kLeft,    // two balls that overlap
  kRight,
  kCrowded,  // a ball with four small ones against it: more neighbours than it tests
  kCrowd0,
  kCrowd1,
  kCrowd2,
  kCrowd3,
  kCount
};

PrimitiveSet test_shapes() {
  PrimitiveSet prims;
  auto& s = prims.shapes;
  s.push_back(shape(ShapeKind::kPlane, {0, 0, 0}, {0, 0, 0}, {12, 1, 12}));
  s.push_back(shape(ShapeKind::kSphere, {0, 1, 0}, {0, 0, 0}, {1, 1, 1}));
  s.push_back(shape(ShapeKind::kCube, {3, 0.75f, 0}, {0, 0, 0}, {0.75f, 0.75f, 0.75f}));
  s.push_back(shape(ShapeKind::kCube, {3, 3, 3}, {20, 35, 10}, {0.5f, 0.8f, 0.6f}));
  s.push_back(shape(ShapeKind::kCylinder, {-3, 0, 0}, {-90, 0, 0}, {0.5f, 0.5f, 2}));
  s.push_back(shape(ShapeKind::kCone, {0, 3.5f, 3}, {-90, 0, 0}, {0.6f, 0.6f, 1.5f}));
  s.push_back(shape(ShapeKind::kSphere, {0, 3, -4}, {0, 0, 0}, {1.5f, 1.5f, 1.5f}));
  s.push_back(shape(ShapeKind::kSphere, {0.3f, 3, -4}, {0, 0, 0}, {0.5f, 0.5f, 0.5f}));
  s.push_back(shape(ShapeKind::kSphere, {5, 3, -3}, {0, 0, 0}, {0.6f, 0.6f, 0.6f}));
  s.push_back(shape(ShapeKind::kSphere, {5.8f, 3, -3}, {0, 0, 0}, {0.6f, 0.6f, 0.6f}));
  s.push_back(shape(ShapeKind::kSphere, {-5, 3, -5}, {0, 0, 0}, {1, 1, 1}));
  for (int k = 0; k < 4; ++k)
    s.push_back(shape(ShapeKind::kSphere, {-5 + (k % 2 ? 1.1f : -1.1f), 3, -5 + (k / 2 ? 1.1f : -1.1f)}, {0, 0, 0},
                      {0.3f, 0.3f, 0.3f}));
  REQUIRE(s.size() == kCount);
  return prims;
}

struct Answer {
  bool found;
  Hit hit;
  float tmax;
};

// What a query gives for `ray`: whether it met something, the hit, and the ray's tmax after it.
template <class Query>
Answer answer(Ray ray, const Query& query) {
  Answer a;
  a.found = query(ray, a.hit);
  a.tmax = ray.tmax;
  return a;
}

Answer walked(const Bvh& bvh, const Ray& ray) {
  return answer(ray, [&](Ray& r, Hit& h) { return bvh.intersect(r, h); });
}
Answer from_inside(const Bvh& bvh, uint32_t inside, const Ray& ray) {
  return answer(ray, [&](Ray& r, Hit& h) { return bvh.intersect_from_inside(inside, r, h); });
}
Answer leaving(const Bvh& bvh, uint32_t from, const Ray& ray) {
  return answer(ray, [&](Ray& r, Hit& h) { return bvh.intersect_leaving(from, r, h); });
}

// A point on the surface of `s`, found as a ray from outside finds it, and its surface record;
// false when the ray missed.
bool surface_point(const AnalyticShape& s, Rng& rng, SurfaceInteraction& si) {
  const Vec3 centre = 0.5f * (world_bounds(s).lo + world_bounds(s).hi);
  const Vec3 from = centre + 6.0f * random_unit(rng);
  Ray probe(from, centre + 0.4f * random_unit(rng) * (world_bounds(s).hi - world_bounds(s).lo) * 0.5f - from);
  Hit hit;
  if (!intersect_shape(s, probe, hit)) return false;
  si = shape_surface(s, probe, hit, false);
  return true;
}

void require_same(const Answer& a, const Answer& b) {
  REQUIRE(a.found == b.found);
  REQUIRE(a.tmax == b.tmax);
  if (!a.found) return;
  REQUIRE(a.hit.t == b.hit.t);
  REQUIRE(a.hit.prim == b.hit.prim);
  REQUIRE(a.hit.part == b.hit.part);
}

}  // namespace

TEST_CASE("Closed shapes get an interior listing the shapes whose boxes reach theirs", "[shape_interiors]") {
  const Bvh bvh(test_shapes(), {});
  const std::vector<ShapeInterior>& in = bvh.interiors();
  REQUIRE(in.size() == kCount);
  CHECK_FALSE(in[kFloor].usable());  // a plane bounds nothing
  const auto others = [&](Id id) { return std::vector<uint32_t>(in[id].others, in[id].others + in[id].count); };
  REQUIRE(in[kBall].usable());
  CHECK(others(kBall) == std::vector<uint32_t>{kFloor});  // touching counts
  CHECK(others(kBlock) == std::vector<uint32_t>{kFloor});
  CHECK(others(kPillar) == std::vector<uint32_t>{kFloor});
  REQUIRE(in[kTurned].usable());
  CHECK(in[kTurned].count == 0);
  CHECK(in[kCone].count == 0);
  CHECK(others(kShell) == std::vector<uint32_t>{kCore});
  CHECK(others(kCore) == std::vector<uint32_t>{kShell});
  CHECK(others(kLeft) == std::vector<uint32_t>{kRight});
  CHECK_FALSE(in[kCrowded].usable());  // four against it: more than kMaxOthers
  REQUIRE(in[kCrowd0].usable());
  CHECK(others(kCrowd0) == std::vector<uint32_t>{kCrowded});

  // Triangles near a shape make its interior unusable: they are not tested there.
  TriangleMesh mesh;
  mesh.positions = {Vec3(-0.5f, 1.0f, 0.5f), Vec3(0.5f, 1.0f, 0.5f), Vec3(0.0f, 1.5f, 0.5f),
                    Vec3(20, 20, 20),        Vec3(21, 20, 20),       Vec3(20, 21, 20)};
  mesh.indices = {0, 1, 2, 3, 4, 5};
  const Bvh with_mesh(make_primitive_set({mesh}, {test_shapes().shapes[kBall], test_shapes().shapes[kTurned]}), {});
  REQUIRE(with_mesh.interiors().size() == 2);
  CHECK_FALSE(with_mesh.interiors()[0].usable());
  CHECK(with_mesh.interiors()[1].usable());

  // A set without closed shapes keeps none.
  PrimitiveSet planes;
  planes.shapes.push_back(test_shapes().shapes[kFloor]);
  CHECK(Bvh(planes, {}).interiors().empty());
}

TEST_CASE("A ray from inside a closed shape meets what the walk meets, bit for bit", "[shape_interiors]") {
  const PrimitiveSet prims = test_shapes();
  const Bvh bvh(prims, {});
  Rng rng(11);
  int inside_rays = 0, shortcuts = 0;
  for (uint32_t id = kBall; id < kCount; ++id) {
    const AnalyticShape& s = prims.shapes[id];
    for (int i = 0; i < 3000; ++i) {
      SurfaceInteraction si;
      if (!surface_point(s, rng, si)) continue;
      // Rays leaving it inwards (refractions in, reflections within) and outwards, each as the
      // integrator makes them: from the offset origin.
      for (int j = 0; j < 4; ++j) {
        Vec3 d = random_unit(rng);
        const bool inwards = j < 3;
        if ((glm::dot(d, si.geometric_normal) < 0.0f) != inwards) d = -d;
        const Ray ray(offset_ray_origin(si.position, si.position_error, si.geometric_normal, d), d);
        const Answer walk = walked(bvh, ray);
        require_same(from_inside(bvh, id, ray), walk);
        if (inwards) {
          ++inside_rays;
          // Whether the walk was skipped: the query's own conditions.
          const ShapeInterior& interior = bvh.interiors()[id];
          Hit own;
          if (interior.usable() && interior.box.contains(ray.origin) && intersect_shape(s, ray, own) &&
              interior.box.contains(ray.at(own.t)))
            ++shortcuts;
        }
      }
    }
  }
  INFO(inside_rays << " rays inwards, " << shortcuts << " answered without the walk");
  CHECK(inside_rays > 20000);
  CHECK(shortcuts > inside_rays / 2);

  // Wrong hints give the walk's answer: rays from anywhere, named as inside any id (triangles',
  // kNoPrimitive, past the end).
  for (int i = 0; i < 20000; ++i) {
    const Ray ray(Vec3(-7.0f, -1.0f, -7.0f) + 14.0f * Vec3(rng.next_float(), 0.5f * rng.next_float(), rng.next_float()),
                  random_unit(rng));
    const uint32_t hint = i % 7 == 0 ? kNoPrimitive : rng.next_u32() % (kCount + 2);
    require_same(from_inside(bvh, hint, ray), walked(bvh, ray));
  }
  // A ray that cannot be walked (NaN) is a miss either way.
  Ray nan_ray(Vec3(0.0f, 1.0f, 0.0f), Vec3(std::nanf(""), 0.0f, 1.0f));
  require_same(from_inside(bvh, kBall, nan_ray), walked(bvh, nan_ray));
}

TEST_CASE("A ray leaving a shape outwards meets what the walk meets without testing the shape", "[shape_interiors]") {
  const PrimitiveSet prims = test_shapes();
  for (const Isa isa : kAllIsas) {
    if (!isa_supported(isa)) continue;
    INFO(isa_name(isa));
    const Bvh bvh(prims, BvhBuildOptions{1, isa});
    Rng rng(23);
    int outward = 0, met_other = 0;
    for (uint32_t id = kFloor; id < kCount; ++id) {
      for (int i = 0; i < 2000; ++i) {
        SurfaceInteraction si;
        if (!surface_point(prims.shapes[id], rng, si)) continue;
        // Outwards as the integrator makes them: on the side the probe came from (either side of
        // the floor), from the offset origin; grazing ones among them.
        const Vec3 n = si.front_face ? si.geometric_normal : -si.geometric_normal;
        for (int j = 0; j < 3; ++j) {
          Vec3 d = random_unit(rng);
          if (j == 2) d = glm::normalize(d - glm::dot(d, n) * n + 1e-3f * n);  // nearly along the surface
          if (glm::dot(d, n) <= 0.0f) d = -d;
          if (!(glm::dot(d, n) > 0.0f)) continue;
          const Ray ray(offset_ray_origin(si.position, si.position_error, n, d), d);
          const Answer walk = walked(bvh, ray);
          REQUIRE(!(walk.found && walk.hit.prim == id));  // the walk never met the shape again
          require_same(leaving(bvh, id, ray), walk);
          ++outward;
          if (walk.found) ++met_other;
        }
      }
    }
    INFO(outward << " rays outwards, " << met_other << " meeting another shape");
    CHECK(outward > 50000);
    CHECK(met_other > outward / 10);
    // Any other id is the walk: triangles', kNoPrimitive, past the end.
    for (int i = 0; i < 2000; ++i) {
      const Ray ray(
          Vec3(-7.0f, 0.5f, -7.0f) + 14.0f * Vec3(rng.next_float(), 0.5f * rng.next_float(), rng.next_float()),
          random_unit(rng));
      const uint32_t other = i % 2 == 0 ? kNoPrimitive : kCount + rng.next_u32() % 5;
      require_same(leaving(bvh, other, ray), walked(bvh, ray));
    }
    // The shape is not tested: a ray from outside through the ball, named as leaving it, passes
    // through to the floor.
    Ray through(Vec3(0.0f, 5.0f, 0.0f), Vec3(0.0f, -1.0f, 0.0f));
    const Answer past = leaving(bvh, kBall, through);
    REQUIRE(past.found);
    CHECK(past.hit.prim == kFloor);
  }
}
