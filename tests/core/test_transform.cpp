#include <bit>
#include <random>

#include <catch2/catch.hpp>

#include "tests/support/geometry.h"

#include "core/camera.h"
#include "core/transform.h"

using namespace rt;
using rt::test::check_vec;
using rt::test::make_ray;

TEST_CASE("compose_trs: scale, then rotate X, Y, Z, then translate", "[transform]") {
  const Mat4 m = compose_trs({10, 0, 0}, {90, 0, 0}, {2, 1, 1});
  const Transform t = *make_transform(m);
  check_vec(t.point_to_world({1, 0, 0}), {12, 0, 0});  // scaled to 2, rotation about X leaves it
  check_vec(t.point_to_world({0, 1, 0}), {10, 0, 1});  // +Y turns to +Z under +90 degrees about X
  // Order of rotations: X first, then Y. (0,1,0) -> X90 -> (0,0,1) -> Y90 -> (1,0,0).
  const Transform xy = *make_transform(compose_trs({0, 0, 0}, {90, 90, 0}, {1, 1, 1}));
  check_vec(xy.point_to_world({0, 1, 0}), {1, 0, 0});
}

namespace {

bool same_bits(Vec3 a, Vec3 b) {
  for (int i = 0; i < 3; ++i)
    if (std::bit_cast<uint32_t>(a[i]) != std::bit_cast<uint32_t>(b[i])) return false;
  return true;
}

}  // namespace

TEST_CASE("transform: the four-lane products are glm's to the bit, the error bound the row-by-row formula's",
          "[transform]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-50.0f, 50.0f);
  for (int i = 0; i < 20000; ++i) {
    const Mat4 m = compose_trs(Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)) * 7.0f,
                               Vec3(0.01f + std::fabs(u(rng)), 0.2f + std::fabs(u(rng)) / 9.0f, 3.0f));
    // Zeros and negative zeros too: a point on a plane (y = 0) and a face at z = -0.
    const Vec3 p(u(rng), i % 3 == 0 ? 0.0f : u(rng) / 100.0f, i % 5 == 0 ? -0.0f : u(rng) * 10.0f);
    const Vec3 p_error = i % 2 == 0 ? Vec3(0.0f) : glm::abs(p) * 3e-7f;
    INFO("case " << i);
    CHECK(same_bits(affine_point(m, p), Vec3(m * Vec4(p, 1.0f))));
    CHECK(same_bits(linear_vector(m, p), Mat3(m) * p));
    Vec3 rows;
    for (int r = 0; r < 3; ++r) {  // glm is column-major: m[column][row]
      const float magnitude =
          std::fabs(m[0][r] * p.x) + std::fabs(m[1][r] * p.y) + std::fabs(m[2][r] * p.z) + std::fabs(m[3][r]);
      const float carried =
          std::fabs(m[0][r]) * p_error.x + std::fabs(m[1][r]) * p_error.y + std::fabs(m[2][r]) * p_error.z;
      rows[r] = float_gamma(3) * magnitude + (1.0f + float_gamma(3)) * carried;
    }
    CHECK(same_bits(transformed_point_error(m, p, p_error), rows));
    // An exact point's bound without the carried term is the same floats.
    if (p_error == Vec3(0.0f)) CHECK(same_bits(transformed_point_error(m, p), rows));
  }
}

TEST_CASE("transform: inverse round trip and normals via the inverse transpose", "[transform]") {
  const Transform t = *make_transform(compose_trs({1, 2, 3}, {30, 45, 60}, {2, 0.5f, 3}));
  const Vec3 p(0.3f, -0.7f, 1.1f);
  check_vec(t.point_to_object(t.point_to_world(p)), p);
  // A tangent of the plane z = 0 stays perpendicular to the transformed normal.
  const Vec3 n = t.normal_to_world_unit({0, 0, 1});
  CHECK(glm::dot(n, t.vector_to_world({1, 0, 0})) == Approx(0.0f).margin(1e-5));
  CHECK(glm::dot(n, t.vector_to_world({0, 1, 0})) == Approx(0.0f).margin(1e-5));
  CHECK(glm::length(n) == Approx(1.0f));
}

TEST_CASE("transform: parent * child composition matches applying both", "[transform]") {
  const Mat4 parent = compose_trs({0, 1, 0}, {0, 90, 0}, {2, 2, 2});
  const Mat4 child = compose_trs({1, 0, 0}, {0, 0, 0}, {1, 1, 1});
  const Transform world = *make_transform(parent * child);
  // Child origin: (1,0,0) in parent space -> scaled (2,0,0) -> rotated 90 about Y (0,0,-2) -> (0,1,-2).
  check_vec(world.point_to_world({0, 0, 0}), {0, 1, -2});
}

TEST_CASE("make_transform rejects singular and non-finite matrices", "[transform]") {
  CHECK_FALSE(make_transform(compose_trs({0, 0, 0}, {0, 0, 0}, {1, 0, 1})).has_value());
  Mat4 nan(1.0f);
  nan[3][0] = std::nanf("");
  CHECK_FALSE(make_transform(nan).has_value());
  CHECK(make_transform(compose_trs({0, 0, 0}, {0, 0, 0}, {1e-3f, 1e-3f, 1e-3f})).has_value());  // tiny, not singular
  CHECK(make_transform(compose_trs({0, 0, 0}, {0, 0, 0}, {-1, 1, 1})).has_value());             // mirroring is fine
}

TEST_CASE("transform_bounds: a rotated unit box", "[transform]") {
  const Aabb b = transform_bounds(compose_trs({0, 0, 0}, {0, 45, 0}, {1, 1, 1}), Aabb{Vec3(-1), Vec3(1)});
  CHECK(b.hi.x == Approx(std::sqrt(2.0f)));
  CHECK(b.hi.y == Approx(1.0f));
  CHECK(b.lo.z == Approx(-std::sqrt(2.0f)));
}

TEST_CASE("camera: centre ray looks at the target, corners span the field of view", "[camera]") {
  const Camera c = Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90.0f);
  check_vec(c.generate_ray(50, 50, 100, 100).direction, {0, 0, -1});
  check_vec(c.generate_ray(50, 0, 100, 100).direction, glm::normalize(Vec3(0, 1, -1)));  // top edge: +45 degrees
  check_vec(c.generate_ray(100, 50, 100, 100).direction, glm::normalize(Vec3(1, 0, -1)));
}

TEST_CASE("camera framing keeps every corner of the box in view", "[camera]") {
  const Aabb box{Vec3(-1, 0, -2), Vec3(3, 1, 0)};
  const Camera c = Camera::framing(box, 40.0f, 16.0f / 9.0f);
  const float tan_v = std::tan(radians(20.0f)), tan_h = tan_v * 16.0f / 9.0f;
  for (int k = 0; k < 8; ++k) {
    const Vec3 p(k & 1 ? box.hi.x : box.lo.x, k & 2 ? box.hi.y : box.lo.y, k & 4 ? box.hi.z : box.lo.z);
    const Vec3 d = p - c.position;
    const float depth = glm::dot(d, c.forward);
    CHECK(depth > 0.0f);
    CHECK(std::fabs(glm::dot(d, c.right)) <= depth * tan_h * 1.0001f);
    CHECK(std::fabs(glm::dot(d, c.up)) <= depth * tan_v * 1.0001f);
  }
}
