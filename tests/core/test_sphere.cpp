#include <catch2/catch.hpp>

#include "tests/support/geometry.h"

#include "core/rng.h"
#include "core/shapes/analytic_shape.h"
#include "core/shapes/sphere.h"

using namespace rt;
using rt::test::check_vec;
using rt::test::make_ray;

TEST_CASE("sphere: hit from outside gives the near root and outward normal", "[shapes][sphere]") {
  Hit h;
  REQUIRE(intersect_sphere(make_ray({0, 0, 5}, {0, 0, -1}), h));
  CHECK(h.t == Approx(4.0f));
  const SurfacePatch s = sphere_patch({0, 0, 1}, h.part);
  CHECK(s.normal.z == Approx(1.0f));
  CHECK(s.uv.x == Approx(0.0f).margin(1e-6));  // +Z is u = 0
  CHECK(s.uv.y == Approx(0.5f));               // on the equator
}

TEST_CASE("sphere: unnormalised direction keeps t in world units of the ray parameter", "[shapes][sphere]") {
  Hit h;
  REQUIRE(intersect_sphere(make_ray({0, 0, 5}, {0, 0, -2}), h));
  CHECK(h.t == Approx(2.0f));
}

TEST_CASE("sphere: from inside, the far root", "[shapes][sphere]") {
  Hit h;
  REQUIRE(intersect_sphere(make_ray({0, 0, 0.5f}, {1, 0, 0}), h));
  CHECK(h.t == Approx(std::sqrt(1.0f - 0.25f)));
}

TEST_CASE("sphere: misses, tangents and the ray interval", "[shapes][sphere]") {
  Hit h;
  CHECK_FALSE(intersect_sphere(make_ray({0, 1.001f, 5}, {0, 0, -1}), h));
  REQUIRE(intersect_sphere(make_ray({0, 1, 5}, {0, 0, -1}), h));  // tangent: a single touching point
  CHECK(h.t == Approx(5.0f));
  CHECK_FALSE(intersect_sphere(make_ray({0, 0, 5}, {0, 0, 1}), h));  // pointing away
  Ray short_ray = make_ray({0, 0, 5}, {0, 0, -1});
  short_ray.tmax = 3.9f;
  CHECK_FALSE(intersect_sphere(short_ray, h));
}

TEST_CASE("sphere: far from the origin, no cancellation", "[shapes][sphere]") {
  Hit h;
  REQUIRE(intersect_sphere(make_ray({0, 0, 1e4f}, {0, 0, -1}), h));
  CHECK(h.t == Approx(1e4f - 1.0f).epsilon(1e-6));
}

TEST_CASE("sphere: uv and tangent frame at the north pole and on the +X meridian", "[shapes][sphere]") {
  const SurfacePatch px = sphere_patch({1, 0, 0}, 0);
  CHECK(px.uv.x == Approx(0.25f));  // a quarter turn from +Z towards +X
  CHECK(glm::dot(px.dpdu, px.normal) == Approx(0.0f).margin(1e-6));
  CHECK(glm::dot(px.dpdv, px.normal) == Approx(0.0f).margin(1e-6));
  CHECK(px.dpdv.y < 0.0f);  // v grows towards the south pole
  const SurfacePatch pole = sphere_patch({0, 1, 0}, 0);
  CHECK(pole.uv.y == Approx(0.0f).margin(1e-6));
}

TEST_CASE("sphere under non-uniform scale: world normal is the inverse transpose", "[shapes][sphere][transform]") {
  AnalyticShape s;
  s.kind = ShapeKind::kSphere;
  s.transform = *make_transform(compose_trs({0, 0, 0}, {0, 0, 0}, {2, 1, 1}));  // ellipsoid x^2/4 + y^2 + z^2 = 1
  Ray r = make_ray({5, 5, 0}, glm::normalize(Vec3(-1, -1, 0)));
  Hit h;
  REQUIRE(intersect_shape(s, r, h));
  const SurfaceInteraction si = shape_surface(s, r, h);
  // Gradient of the implicit function at the hit: (x/2, 2y, 2z) up to scale.
  const Vec3 p = si.position;
  CHECK(p.x * p.x / 4 + p.y * p.y + p.z * p.z == Approx(1.0f).margin(1e-4));
  const Vec3 expected = glm::normalize(Vec3(p.x / 4, p.y, p.z));
  CHECK(si.geometric_normal.x == Approx(expected.x).margin(1e-5));
  CHECK(si.geometric_normal.y == Approx(expected.y).margin(1e-5));
  CHECK(si.front_face);
}

TEST_CASE("sphere: the world normal, made from the point as the ray found it, is the exact normal's direction",
          "[shapes][sphere][transform]") {
  // shape_surface takes the object normal's direction from the hit point before it is put back
  // on the sphere (the same direction) and normalises it once, in world space: within a few
  // float roundings of the exact normal along the point's direction, worked out here in double.
  AnalyticShape s;
  s.kind = ShapeKind::kSphere;
  s.transform = *make_transform(compose_trs({3.0f, -2.0f, 1.0f}, {30.0f, -45.0f, 20.0f}, {2.0f, 0.75f, 1.25f}));
  Rng rng(7);
  const auto next = [&] { return 2.0f * rng.next_float() - 1.0f; };
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const float reach = i % 2 == 0 ? 3.0f : 300.0f;
    const Vec3 origin = s.transform.point_to_world(Vec3(next(), next(), next()) * reach);
    const Vec3 target = s.transform.point_to_world(Vec3(next(), next(), next()) * 0.9f);
    Ray r = make_ray(origin, target - origin);
    Hit h;
    if (!intersect_shape(s, r, h)) continue;
    ++hits;
    const SurfaceInteraction si = shape_surface(s, r, h, i % 3 == 0);
    const glm::dvec3 found(to_object_ray(s, r).at(h.t));  // as shape_surface finds it
    const glm::dvec3 exact = glm::normalize(glm::dmat3(s.transform.normal_to_world) * glm::normalize(found));
    CHECK(glm::length(glm::dvec3(si.geometric_normal) - exact) < 5e-7);
    // And the point put back on the surface lies along the same direction.
    const glm::dvec3 back(s.transform.point_to_object(si.position));
    CHECK(glm::length(glm::normalize(back) - glm::normalize(found)) < 2e-6);
    CHECK(std::abs(glm::length(glm::dvec3(si.geometric_normal)) - 1.0) < 3e-7);
  }
  CHECK(hits > 10000);
}

TEST_CASE("sphere: both crossings from one quadratic are the two intersect_sphere calls, to the bit",
          "[shapes][sphere][csg]") {
  // Lines through, grazing, missing and starting inside, from near and far, as CSG asks them
  // (tmin -infinity): the first crossing, then the next past the float after it.
  Rng rng(12345);
  const auto next = [&] { return 2.0f * rng.next_float() - 1.0f; };
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const float reach = i % 3 == 0 ? 1.0f : (i % 3 == 1 ? 4.0f : 1000.0f);
    Ray ray;
    ray.origin = Vec3(next(), next(), next()) * reach;
    // Aimed at a point near the sphere's rim now and then, so that some lines graze it.
    const Vec3 aim = i % 5 == 0 ? glm::normalize(Vec3(next(), next(), next())) * (1.0f + 1e-6f * next())
                                : Vec3(next(), next(), next());
    ray.direction = aim - ray.origin;
    ray.tmin = -kInfinity;
    ray.tmax = kInfinity;
    Hit a1, b1, a2, b2;
    bool two_calls = intersect_sphere(ray, a1);
    if (two_calls) {
      Ray rest = ray;
      rest.tmin = std::nextafter(a1.t, kInfinity);
      two_calls = intersect_sphere(rest, b1);
    }
    const bool one_call = intersect_sphere_twice(ray, a2, b2);
    REQUIRE(one_call == two_calls);
    if (!one_call) continue;
    ++hits;
    CHECK(a2.t == a1.t);
    CHECK(b2.t == b1.t);
    CHECK(a2.part == a1.part);
    CHECK(b2.part == b1.part);
  }
  CHECK(hits > 5000);
}
