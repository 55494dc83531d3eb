#include <catch2/catch.hpp>

#include "tests/support/geometry.h"

#include "core/accel/triangle_quad.h"
#include "core/mesh.h"
#include "core/rng.h"
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

TEST_CASE("triangle: both faces are hit, misses outside edges, parallel and behind", "[shapes][triangle]") {
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
  const SurfaceInteraction si = mesh_surface(m, 0, r, h, Transform{});
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
  const SurfaceInteraction si = mesh_surface(mirrored, 0, make_ray({0.2f, 0.2f, -1}, {0, 0, 1}), h, Transform{});
  CHECK(si.geometric_normal.z == Approx(-1.0f));  // the mirror image of a +Z-facing triangle faces -Z
}

TEST_CASE("mesh instance: a mirroring placement keeps normals outward and flips tangent handedness",
          "[shapes][mesh][transform]") {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.tangents = {{1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, 1}};
  m.indices = {0, 1, 2};
  Hit h;
  h.b1 = h.b2 = 0.2f;
  const Transform mirror = *make_transform(compose_trs({0, 0, 5}, {0, 0, 0}, {2, 1, -1}));
  // Placed: the world ray meets the instance at world z = 5 (object z = 0).
  const SurfaceInteraction si = mesh_surface(m, 0, make_ray({0.4f, 0.2f, 10}, {0, 0, -1}), h, mirror);
  CHECK(si.position.x == Approx(0.4f));  // object (0.2, 0.2, 0) scaled by 2 in x, moved to z = 5
  CHECK(si.position.z == Approx(5.0f));
  CHECK(si.geometric_normal.z == Approx(-1.0f));  // the same answer as the copied, rewound mesh above
  CHECK(si.shading_normal.z == Approx(-1.0f));
  CHECK(si.tangent.x == Approx(1.0f));
  CHECK(si.tangent.w == -1.0f);                  // bitangent = cross(n, t) * w keeps pointing along +Y
  CHECK(si.texcoord[0].dpdu.x == Approx(2.0f));  // default uvs (0,0) (1,0) (1,1): u along the scaled edge
  CHECK(si.object_position.x == Approx(0.2f));
  CHECK_FALSE(si.front_face);  // arriving from +Z onto a face that now looks down -Z
  const Vec3 bitangent = glm::cross(si.shading_normal, Vec3(si.tangent)) * si.tangent.w;
  CHECK(bitangent.y == Approx(1.0f));
}

TEST_CASE("triangle quads: each lane gives exactly what the one-triangle routine gives", "[triangle][bvh]") {
  rt::Rng rng(42);
  const auto coord = [&] { return 4.0f * rng.next_float() - 2.0f; };
  int hits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    rt::PackedTriangle tris[4];
    rt::TriangleQuad quad{};
    const int used = 1 + trial % 4;  // the lanes left over must never hit
    for (int lane = 0; lane < used; ++lane) {
      tris[lane] =
          rt::PackedTriangle::from_vertices(rt::Vec3(coord(), coord(), coord()), rt::Vec3(coord(), coord(), coord()),
                                            rt::Vec3(coord(), coord(), coord()));
      rt::set_quad_lane(quad, lane, tris[lane]);
    }
    rt::Ray ray;
    ray.origin = rt::Vec3(coord(), coord(), 5.0f);
    ray.direction = rt::Vec3(0.3f * coord(), 0.3f * coord(), -1.0f);
    ray.tmin = 0.0f;
    ray.tmax = 4.0f + 4.0f * rng.next_float();
    rt::Float4 t, b1, b2;
    const unsigned mask = rt::intersect_quad(quad, rt::QuadRay(ray), ray.tmin, ray.tmax, t, b1, b2);
    for (int lane = 0; lane < 4; ++lane) {
      rt::Hit hit;
      const bool scalar = lane < used && rt::intersect_triangle(tris[lane], ray, hit);
      REQUIRE(((mask >> lane) & 1u) == (scalar ? 1u : 0u));
      if (!scalar) continue;
      ++hits;
      CHECK(t[lane] == hit.t);  // bit for bit: the same operations in the same order
      CHECK(b1[lane] == hit.b1);
      CHECK(b2[lane] == hit.b2);
    }
  }
  CHECK(hits > 1000);
}
