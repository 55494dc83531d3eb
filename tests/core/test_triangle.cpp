#include <catch2/catch.hpp>

#include "tests/support/geometry.h"

#include "core/mesh.h"
#include "core/shapes/triangle.h"

using namespace rt;
using rt::test::check_vec;
using rt::test::make_ray;

namespace {
const PackedTriangle kTri = PackedTriangle::from_vertices({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
}  // namespace

TEST_CASE("triangle: barycentrics and distance of a hit", "[shapes][triangle]") {
  Hit h;
  REQUIRE(intersect_triangle(kTri, make_ray({0.25f, 0.5f, 2}, {0, 0, -1}), h));
  CHECK(h.t == Approx(2.0f));
  CHECK(h.b1 == Approx(0.25f));
  CHECK(h.b2 == Approx(0.5f));
}

TEST_CASE("triangle: both faces are hit; misses outside edges, parallel and behind", "[shapes][triangle]") {
  Hit h;
  CHECK(intersect_triangle(kTri, make_ray({0.2f, 0.2f, -1}, {0, 0, 1}), h));
  CHECK_FALSE(intersect_triangle(kTri, make_ray({0.6f, 0.6f, 1}, {0, 0, -1}), h));  // beyond the hypotenuse
  CHECK_FALSE(intersect_triangle(kTri, make_ray({-0.1f, 0.2f, 1}, {0, 0, -1}), h));
  CHECK_FALSE(intersect_triangle(kTri, make_ray({0.2f, 0.2f, 0}, {1, 0, 0}), h));  // in the plane
  CHECK_FALSE(intersect_triangle(kTri, make_ray({0.2f, 0.2f, 1}, {0, 0, 1}), h));  // pointing away
}

TEST_CASE("mesh surface: interpolated normal, uv and tangent frame from uvs", "[shapes][mesh]") {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  m.normals = {{0, 0, 1}, glm::normalize(Vec3(1, 0, 1)), glm::normalize(Vec3(0, 1, 1))};
  m.uvs = {{0, 0}, {1, 0}, {0, 1}};
  m.indices = {0, 1, 2};
  Ray r = make_ray({0.5f, 0.5f, 1}, {0, 0, -1});
  Hit h;
  h.t = 1;
  h.b1 = 0.25f;
  h.b2 = 0.25f;
  const SurfaceInteraction si = mesh_surface(m, 0, r, h);
  CHECK(si.position.x == Approx(0.5f));
  CHECK(si.position.y == Approx(0.5f));
  CHECK(si.geometric_normal.z == Approx(1.0f));
  CHECK(si.shading_normal.x > 0.0f);
  CHECK(si.shading_normal.y > 0.0f);
  CHECK(glm::length(si.shading_normal) == Approx(1.0f));
  CHECK(si.texcoord[0].uv.x == Approx(0.25f));
  CHECK(si.texcoord[0].uv.y == Approx(0.25f));
  CHECK(si.texcoord[0].dpdu.x == Approx(2.0f));  // u runs along +X over 2 units
  CHECK(si.texcoord[0].dpdv.y == Approx(2.0f));
  CHECK(si.front_face);
}

TEST_CASE("mesh transform: a mirroring transform keeps normals outward", "[shapes][mesh][transform]") {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};  // counter-clockwise seen from +Z: normal +Z
  m.indices = {0, 1, 2};
  const TriangleMesh mirrored = transformed(m, *make_transform(compose_trs({0, 0, 0}, {0, 0, 0}, {1, 1, -1})));
  Hit h;
  h.b1 = h.b2 = 0.2f;
  const SurfaceInteraction si = mesh_surface(mirrored, 0, make_ray({0.2f, 0.2f, -1}, {0, 0, 1}), h);
  CHECK(si.geometric_normal.z == Approx(-1.0f));  // the mirror image of a +Z-facing triangle faces -Z
}
