#include <catch2/catch.hpp>

#include "tests/support/geometry.h"

#include "core/shapes/cone.h"

using namespace rt;
using rt::test::check_vec;
using rt::test::make_ray;

namespace {
const float kHalf = std::sqrt(0.5f);
}  // namespace

TEST_CASE("cone: through the base cap only", "[shapes][cone]") {
  Hit h;
  REQUIRE(intersect_cone(make_ray({0.2f, 0.1f, 3}, {0, 0, -1}), h));
  CHECK(h.t == Approx(2.0f));
  CHECK(h.part == kConeBase);
  check_vec(cone_patch({0.2f, 0.1f, 1}, h.part).normal, {0, 0, 1});
}

TEST_CASE("cone: side hit has the 45-degree outward normal", "[shapes][cone]") {
  Hit h;
  REQUIRE(intersect_cone(make_ray({-3, 0, 0.5f}, {1, 0, 0}), h));
  CHECK(h.t == Approx(2.5f));
  CHECK(h.part == kConeSide);
  check_vec(cone_patch({-0.5f, 0, 0.5f}, h.part).normal, {-kHalf, 0, -kHalf});
}

TEST_CASE("cone: enters through the side, leaves through the base", "[shapes][cone]") {
  Ray r = make_ray({-3, 0, 0.7f}, {1, 0, 0.1f});
  Hit h;
  REQUIRE(intersect_cone(r, h));
  CHECK(h.part == kConeSide);
  const Vec3 p = r.at(h.t);
  CHECK(p.x * p.x + p.y * p.y == Approx(p.z * p.z).margin(1e-5));
  r.tmin = h.t + 1e-3f;
  REQUIRE(intersect_cone(r, h));
  CHECK(h.part == kConeBase);
  CHECK(h.t == Approx(3.0f));
}

TEST_CASE("cone: tangent to the side touches at one point", "[shapes][cone]") {
  Hit h;
  REQUIRE(intersect_cone(make_ray({-2, 0.5f, 0.5f}, {1, 0, 0}), h));
  CHECK(h.t == Approx(2.0f));
  check_vec(cone_patch({0, 0.5f, 0.5f}, h.part).normal, {0, kHalf, -kHalf});
  CHECK_FALSE(intersect_cone(make_ray({-2, 0.5001f, 0.5f}, {1, 0, 0}), h));
}

TEST_CASE("cone: parallel to the axis hits the side, not the mirrored nappe", "[shapes][cone]") {
  Hit h;
  REQUIRE(intersect_cone(make_ray({0.5f, 0, -1}, {0, 0, 1}), h));
  CHECK(h.t == Approx(1.5f));  // z = 0.5; the root at z = -0.5 belongs to the nappe that is not part of the cone
  CHECK(h.part == kConeSide);
  CHECK_FALSE(intersect_cone(make_ray({1.5f, 0, -1}, {0, 0, 1}), h));
}

TEST_CASE("cone: parallel to a generating line (the quadratic degenerates to linear)", "[shapes][cone]") {
  Hit h;
  REQUIRE(intersect_cone(make_ray({-1, 0, 0.5f}, {1, 0, 1}), h));
  CHECK(h.t == Approx(0.25f));
  CHECK(h.part == kConeSide);
}

TEST_CASE("cone: starting inside", "[shapes][cone]") {
  Hit h;
  REQUIRE(intersect_cone(make_ray({0, 0, 0.5f}, {1, 0, 0}), h));
  CHECK(h.t == Approx(0.5f));
  check_vec(cone_patch({0.5f, 0, 0.5f}, h.part).normal, {kHalf, 0, -kHalf});
  REQUIRE(intersect_cone(make_ray({0, 0, 0.5f}, {0, 0, 1}), h));
  CHECK(h.t == Approx(0.5f));
  CHECK(h.part == kConeBase);
}

TEST_CASE("cone: misses, including a ray through the mirrored nappe below the apex", "[shapes][cone]") {
  Hit h;
  CHECK_FALSE(intersect_cone(make_ray({-3, 0, -0.5f}, {1, 0, 0}), h));
  CHECK_FALSE(intersect_cone(make_ray({-3, 0, 1.5f}, {1, 0, 0}), h));
  CHECK_FALSE(intersect_cone(make_ray({-3, 0.9f, 0.5f}, {1, 0, 0}), h));
}

TEST_CASE("cone: the apex is on the surface", "[shapes][cone]") {
  Hit h;
  REQUIRE(intersect_cone(make_ray({0, 0, -1}, {0, 0, 1}), h));
  CHECK(h.t == Approx(1.0f));
}
