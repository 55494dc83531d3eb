#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "tests/support/geometry.h"

#include "core/shapes/analytic_shape.h"
#include "core/shapes/cone.h"
#include "core/shapes/cylinder.h"

using namespace rt;
using rt::test::check_vec;
using rt::test::make_ray;

TEST_CASE("cylinder: through a cap only (along the axis, inside the radius)", "[shapes][cylinder]") {
  Hit h;
  REQUIRE(intersect_cylinder(make_ray({0.3f, 0.2f, 5}, {0, 0, -1}), h));
  CHECK(h.t == Approx(4.0f));
  CHECK(h.part == kCylinderTop);
  check_vec(cylinder_patch({0.3f, 0.2f, 1}, h.part).normal, {0, 0, 1});
}

TEST_CASE("cylinder: enters through the side, leaves through a cap", "[shapes][cylinder]") {
  Hit h;
  REQUIRE(intersect_cylinder(make_ray({-3, 0, 0.2f}, {1, 0, 0.25f}), h));
  CHECK(h.t == Approx(2.0f));
  CHECK(h.part == kCylinderSide);
  check_vec(cylinder_patch({-1, 0, 0.7f}, h.part).normal, {-1, 0, 0});
  // The same line from beyond the side hit: the top cap at z = 1 (t = 3.2 from the original origin).
  Ray r = make_ray({-3, 0, 0.2f}, {1, 0, 0.25f});
  r.tmin = 2.5f;
  REQUIRE(intersect_cylinder(r, h));
  CHECK(h.t == Approx(3.2f));
  CHECK(h.part == kCylinderTop);
}

TEST_CASE("cylinder: enters through a cap, leaves through the side", "[shapes][cylinder]") {
  Hit h;
  REQUIRE(intersect_cylinder(make_ray({0, 0, 2}, {0.5f, 0, -1}), h));
  CHECK(h.t == Approx(1.0f));
  CHECK(h.part == kCylinderTop);
}

TEST_CASE("cylinder: tangent to the side touches at one point", "[shapes][cylinder]") {
  Hit h;
  REQUIRE(intersect_cylinder(make_ray({-2, 1, 0.5f}, {1, 0, 0}), h));
  CHECK(h.t == Approx(2.0f));
  CHECK(h.part == kCylinderSide);
  check_vec(cylinder_patch({0, 1, 0.5f}, h.part).normal, {0, 1, 0});
  CHECK_FALSE(intersect_cylinder(make_ray({-2, 1.0001f, 0.5f}, {1, 0, 0}), h));
}

TEST_CASE("cylinder: parallel to the axis hits a cap or nothing", "[shapes][cylinder]") {
  Hit h;
  REQUIRE(intersect_cylinder(make_ray({0.5f, 0, -2}, {0, 0, 1}), h));
  CHECK(h.t == Approx(2.0f));
  CHECK(h.part == kCylinderBase);
  check_vec(cylinder_patch({0.5f, 0, 0}, h.part).normal, {0, 0, -1});
  CHECK_FALSE(intersect_cylinder(make_ray({1.5f, 0, -2}, {0, 0, 1}), h));
}

TEST_CASE("cylinder: starting inside hits the side or a cap from within", "[shapes][cylinder]") {
  Hit h;
  REQUIRE(intersect_cylinder(make_ray({0, 0, 0.5f}, {1, 0, 0}), h));
  CHECK(h.t == Approx(1.0f));
  CHECK(h.part == kCylinderSide);
  REQUIRE(intersect_cylinder(make_ray({0, 0, 0.5f}, {0, 0, 1}), h));
  CHECK(h.t == Approx(0.5f));
  CHECK(h.part == kCylinderTop);
}

TEST_CASE("cylinder: misses above, beside and pointing away", "[shapes][cylinder]") {
  Hit h;
  CHECK_FALSE(intersect_cylinder(make_ray({-3, 0, 2}, {1, 0, 0}), h));
  CHECK_FALSE(intersect_cylinder(make_ray({-3, 2, 0.5f}, {1, 0, 0}), h));
  CHECK_FALSE(intersect_cylinder(make_ray({-3, 0, 0.5f}, {-1, 0, 0}), h));
}

TEST_CASE("cylinder under non-uniform scale and rotation: exact world normal", "[shapes][cylinder][transform]") {
  AnalyticShape s;
  s.kind = ShapeKind::kCylinder;
  // An elliptic cylinder, x radius 2, y radius 1, standing up along world +Y.
  s.transform = *make_transform(compose_trs({0, 0, 0}, {-90, 0, 0}, {2, 1, 3}));
  const Ray r = make_ray({6, 1, 3}, glm::normalize(Vec3(-1, 0, -0.5f)));
  Hit h;
  REQUIRE(intersect_shape(s, r, h));
  const SurfaceInteraction si = shape_surface(s, r, h);
  const Vec3 p = si.position;
  // Rotating -90 about X maps object z to world y and object y to world -z: x^2/4 + z^2 = 1.
  CHECK(p.x * p.x / 4 + p.z * p.z == Approx(1.0f).margin(1e-4));
  check_vec(si.geometric_normal, glm::normalize(Vec3(p.x / 4, 0, p.z)));
  CHECK(p.y == Approx(1.0f).margin(1e-5));
}

TEST_CASE("cylinder and cone: the side's normal points from the axis through the point, to float precision",
          "[shapes][cylinder][cone]") {
  // Made from the point itself (radial_towards); the cosine and sine of its atan2 angle, wrapped
  // to [0, 2 pi), were up to 5.4e-7 off; this is within 1.1e-7 (one float step at 1 is 1.2e-7).
  uint32_t state = 7u;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return 2.0f * static_cast<float>(state >> 8) / 16777216.0f - 1.0f;
  };
  double worst_cylinder = 0.0, worst_cone = 0.0;
  for (int i = 0; i < 100000; ++i) {
    Vec3 p(next(), next(), 0.5f * (next() + 1.0f));
    const float r = std::sqrt(p.x * p.x + p.y * p.y);
    if (!(r > 1e-3f)) continue;
    const double x = p.x, y = p.y, length = std::sqrt(x * x + y * y);
    const Vec3 side = object_space_normal(ShapeKind::kCylinder, p, kCylinderSide);
    worst_cylinder = std::max(worst_cylinder, std::hypot(side.x - x / length, side.y - y / length, double{side.z}));
    // On the cone's side the radius is z: the normal is (x / z, y / z, -1) / sqrt(2).
    const Vec3 lean = object_space_normal(ShapeKind::kCone, p, kConeSide);
    const double s = 1.0 / std::sqrt(2.0);
    worst_cone = std::max(worst_cone, std::hypot(lean.x - s * x / length, lean.y - s * y / length, lean.z + s));
  }
  CHECK(worst_cylinder < 1.5e-7);
  CHECK(worst_cone < 2.5e-7);
  // On the axis (a cone's apex) a normal still: +X's lean.
  CHECK(object_space_normal(ShapeKind::kCylinder, Vec3(0.0f, 0.0f, 0.5f), kCylinderSide) == Vec3(1.0f, 0.0f, 0.0f));
  const Vec3 apex = object_space_normal(ShapeKind::kCone, Vec3(0.0f), kConeSide);
  CHECK(apex.x == Approx(std::sqrt(0.5f)));
  CHECK(apex.z == Approx(-std::sqrt(0.5f)));
}
