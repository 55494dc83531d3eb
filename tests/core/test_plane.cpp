#include <catch2/catch.hpp>

#include "tests/support/geometry.h"

#include "core/shapes/plane.h"

using namespace rt;
using rt::test::check_vec;
using rt::test::make_ray;

TEST_CASE("plane: hit from above and from below, normal +Y", "[shapes][plane]") {
  Hit h;
  REQUIRE(intersect_plane(make_ray({0.5f, 2, -0.5f}, {0, -1, 0}), h));
  CHECK(h.t == Approx(2.0f));
  REQUIRE(intersect_plane(make_ray({0.5f, -3, -0.5f}, {0, 1, 0}), h));
  CHECK(h.t == Approx(3.0f));
  const SurfacePatch s = plane_patch({0.5f, 0, -0.5f}, 0);
  CHECK(s.normal == Vec3(0, 1, 0));
  CHECK(s.uv.x == Approx(0.75f));
  CHECK(s.uv.y == Approx(0.25f));
  CHECK(glm::dot(glm::cross(s.dpdu, s.dpdv), s.normal) < 0.0f);  // u right, v down seen from above
}

TEST_CASE("plane: finite extent, parallel rays, behind the origin", "[shapes][plane]") {
  Hit h;
  CHECK_FALSE(intersect_plane(make_ray({1.5f, 1, 0}, {0, -1, 0}), h));  // outside |x| <= 1
  CHECK_FALSE(intersect_plane(make_ray({0, 0, -5}, {0, 0, 1}), h));     // in the plane: parallel
  CHECK_FALSE(intersect_plane(make_ray({0, 1, 0}, {0, 1, 0}), h));      // pointing away
}
