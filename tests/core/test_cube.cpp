#include <catch2/catch.hpp>

#include "tests/support/geometry.h"

#include "core/shapes/cube.h"

using namespace rt;
using rt::test::check_vec;
using rt::test::make_ray;

TEST_CASE("cube: each face from outside, with its outward normal and face id", "[shapes][cube]") {
  const Vec3 dirs[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  for (int face = 0; face < 6; ++face) {
    const Vec3 d = dirs[face];
    Hit h;
    REQUIRE(intersect_cube(make_ray(-3.0f * d + Vec3(0.2f, -0.3f, 0.1f) * (Vec3(1) - glm::abs(d)), d), h));
    CHECK(h.t == Approx(2.0f));
    CHECK(h.part == static_cast<uint32_t>(face));
    const SurfacePatch s = cube_patch(Vec3(0), h.part);
    CHECK(s.normal == -d);
    CHECK(glm::dot(glm::cross(s.dpdu, s.dpdv), s.normal) < 0.0f);  // u right, v down seen from outside
  }
}

TEST_CASE("cube: from inside, the exit face", "[shapes][cube]") {
  Hit h;
  REQUIRE(intersect_cube(make_ray({0, 0, 0}, {0, 0, 1}), h));
  CHECK(h.t == Approx(1.0f));
  CHECK(h.part == 4u);  // +Z face, normal still outward
}

TEST_CASE("cube: misses, grazing rays, axis-parallel rays", "[shapes][cube]") {
  Hit h;
  CHECK_FALSE(intersect_cube(make_ray({0, 1.5f, 5}, {0, 0, -1}), h));
  CHECK_FALSE(intersect_cube(make_ray({3, 3, 0}, {1, 1, 0}), h));                          // pointing away
  CHECK_FALSE(intersect_cube(make_ray({-5, 0, 0}, glm::normalize(Vec3(1, 0.5f, 0))), h));  // passes above
  REQUIRE(intersect_cube(make_ray({-5, 0.5f, 0.5f}, {1, 0, 0}), h));  // parallel to two slabs, inside them
  CHECK(h.t == Approx(4.0f));
}
