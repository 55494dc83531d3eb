// The optics of secondary rays with real numbers: reflect, refract (Snell), Schlick's Fresnel
// term, total internal reflection, and the proposal's glossy sampling square.
#include <array>
#include <cmath>

#include <catch2/catch.hpp>

#include "core/rng.h"
#include "core/sampling.h"
#include "materials/glossy.h"
#include "materials/optics.h"
#include "tests/support/geometry.h"

using namespace rt;
using rt::test::check_vec;

TEST_CASE("reflect: r = d - 2 (d.n) n against hand-computed vectors", "[optics]") {
  check_vec(reflect(glm::normalize(Vec3(1, -1, 0)), Vec3(0, 1, 0)), Vec3(std::sqrt(0.5f), std::sqrt(0.5f), 0));
  // d = (0.6, -0.8, 0), n = (0, 1, 0): r = (0.6, 0.8, 0).
  check_vec(reflect(Vec3(0.6f, -0.8f, 0), Vec3(0, 1, 0)), Vec3(0.6f, 0.8f, 0));
  // Tilted normal n = (0.6, 0.8, 0), d = (0, -1, 0): d.n = -0.8, r = d + 1.6 n = (0.96, 0.28, 0).
  check_vec(reflect(Vec3(0, -1, 0), Vec3(0.6f, 0.8f, 0)), Vec3(0.96f, 0.28f, 0));
}

TEST_CASE("refract: Snell's law into and out of glass", "[optics]") {
  const Vec3 n(0, 1, 0);
  // 45 degrees from air into n = 1.5: sin(theta_t) = sin(45)/1.5 = 0.47140.
  const Vec3 d = glm::normalize(Vec3(1, -1, 0));
  Vec3 t;
  REQUIRE(refract(d, n, 1.0f / 1.5f, t));
  CHECK(t.x == Approx(0.4714045).epsilon(1e-5));
  CHECK(t.y == Approx(-std::sqrt(1.0 - 0.4714045 * 0.4714045)).epsilon(1e-5));
  CHECK(t.z == 0.0f);
  // Back out through a parallel face: the original direction again.
  Vec3 out;
  REQUIRE(refract(t, n, 1.5f, out));
  check_vec(out, d);
  // Normal incidence is not bent, at any index.
  REQUIRE(refract(Vec3(0, -1, 0), n, 1.0f / 2.4f, t));
  check_vec(t, Vec3(0, -1, 0), 1e-7);
  // Equal indices: straight on.
  REQUIRE(refract(d, n, 1.0f, t));
  check_vec(t, d, 1e-6);
}

TEST_CASE("refract: unit without normalising, by Snell's law, at any angle and index", "[optics]") {
  // refract() leaves its vector as Snell's formula makes it: |t|^2 = eta^2 sin^2_i + cos^2_t = 1
  // for unit d and n. The Whitted integrator takes every ray below a hit to be unit (its length 1).
  Rng rng(2026);
  const auto unit = [&] {
    return glm::normalize(
        Vec3(2.0f * rng.next_float() - 1.0f, 2.0f * rng.next_float() - 1.0f, 2.0f * rng.next_float() - 1.0f));
  };
  int refracted = 0;
  for (int i = 0; i < 20000; ++i) {
    const float eta = std::array{1.0f / 1.5f, 1.5f, 1.0f / 2.4f, 2.4f, 1.0f / 1.33f, 1.33f}[i % 6];
    const Vec3 n = unit();
    Vec3 d = unit();
    if (glm::dot(d, n) > 0.0f) d = -d;  // arriving on n's side
    Vec3 t;
    if (!refract(d, n, eta, t)) continue;
    ++refracted;
    const glm::dvec3 td(t);
    // Within 16 units in the last place of 1: eta x d rounds at up to 2.4 (1.0e-6 seen).
    CHECK(std::abs(glm::length(td) - 1.0) < 2e-6);
    // Snell: sin_t = eta sin_i, and t stays in the plane of d and n, on the far side.
    CHECK(glm::length(glm::cross(td, glm::dvec3(n))) ==
          Approx(eta * glm::length(glm::cross(glm::dvec3(d), glm::dvec3(n)))).margin(2e-6));
    CHECK(std::abs(glm::dot(td, glm::cross(glm::dvec3(d), glm::dvec3(n)))) < 2e-6);
    CHECK(glm::dot(t, n) < 0.0f);
  }
  CHECK(refracted > 10000);  // the rest reflect totally (eta > 1)
}

TEST_CASE("total internal reflection exactly beyond the critical angle asin(1/n)", "[optics]") {
  const float ior = 1.5f;
  const double critical = std::asin(1.0 / ior);  // 41.81 degrees
  const Vec3 n(0, 1, 0);                         // the side the ray comes from (inside the glass)
  const auto at = [](double angle) {
    return Vec3(static_cast<float>(std::sin(angle)), -static_cast<float>(std::cos(angle)), 0.0f);
  };
  Vec3 t;
  CHECK(refract(at(critical - 1e-3), n, ior, t));
  CHECK_FALSE(refract(at(critical + 1e-3), n, ior, t));
  CHECK(schlick_reflectance(static_cast<float>(std::cos(critical + 1e-3)), ior, 1.0f) == 1.0f);
  CHECK(schlick_reflectance(static_cast<float>(std::cos(critical - 1e-3)), ior, 1.0f) < 1.0f);
}

TEST_CASE("Schlick: 0.04 at normal incidence for n = 1.5, 1 at grazing", "[optics]") {
  CHECK(schlick_reflectance(1.0f, 1.0f, 1.5f) == Approx(0.04));
  CHECK(schlick_reflectance(1.0f, 1.5f, 1.0f) == Approx(0.04));  // symmetric at normal incidence
  CHECK(schlick_reflectance(0.0f, 1.0f, 1.5f) == Approx(1.0));
  CHECK(schlick_reflectance(1e-4f, 1.0f, 1.5f) > 0.99f);
  // 60 degrees from air: R = 0.04 + 0.96 * 0.5^5 = 0.07.
  CHECK(schlick_reflectance(0.5f, 1.0f, 1.5f) == Approx(0.07));
  // Diamond: R0 = (1.4 / 3.4)^2 = 0.16955.
  CHECK(schlick_reflectance(1.0f, 1.0f, 2.4f) == Approx(0.1695502).epsilon(1e-5));
  // Leaving glass the cosine is the transmitted one: at 30 degrees inside, cos_t = sqrt(1 - 2.25/4).
  const double cos_t = std::sqrt(1.0 - 2.25 * 0.25);
  CHECK(schlick_reflectance(static_cast<float>(std::cos(kPi / 6)), 1.5f, 1.0f) ==
        Approx(0.04 + 0.96 * std::pow(1.0 - cos_t, 5.0)).epsilon(1e-5));
  // No interface: nothing reflected, even at grazing.
  CHECK(schlick_reflectance(0.01f, 1.33f, 1.33f) == 0.0f);
}

TEST_CASE("Hughes-Moller basis is orthonormal and perpendicular to r", "[optics][glossy]") {
  Rng rng(5);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 r = glm::normalize(Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
    Vec3 u, v;
    hughes_moller_basis(r, u, v);
    CHECK(glm::length(u) == Approx(1.0f).epsilon(1e-5));
    CHECK(glm::length(v) == Approx(1.0f).epsilon(1e-5));
    CHECK(std::fabs(glm::dot(u, r)) < 1e-5f);
    CHECK(std::fabs(glm::dot(v, r)) < 1e-5f);
    CHECK(std::fabs(glm::dot(u, v)) < 1e-5f);
  }
  Vec3 u, v;
  hughes_moller_basis(Vec3(0, 0, 1), u, v);  // smallest component x is dropped: u = (-1, 0, 0)... up to sign
  CHECK(std::fabs(u.z) < 1e-7f);
}

TEST_CASE("glossy grid: sqrt(n) x sqrt(n) strata, one sample in each", "[glossy]") {
  CHECK(StratifiedGrid(16).rows == 4);
  CHECK(StratifiedGrid(16).cols == 4);
  CHECK(StratifiedGrid(8).rows == 2);
  CHECK(StratifiedGrid(8).cols == 4);
  CHECK(StratifiedGrid(1).rows == 1);
  CHECK(StratifiedGrid(1).cols == 1);
  const StratifiedGrid g(9);
  int seen[3][3] = {};
  for (int i = 0; i < 9; ++i) {
    const Vec2 p = g.point(i, Vec2(0.999f, 0.0f));
    ++seen[static_cast<int>(p.y * 3)][static_cast<int>(p.x * 3)];
  }
  for (auto& row : seen)
    for (int cell : row) CHECK(cell == 1);
  // The square's centre is the mirror direction; its corners are a/2 off along u and v.
  const Vec3 r(0, 0, 1), u(1, 0, 0), v(0, 1, 0);
  check_vec(glossy_direction(r, u, v, 0.4f, Vec2(0.5f)), r, 1e-7);
  check_vec(glossy_direction(r, u, v, 0.4f, Vec2(1.0f, 0.0f)), glm::normalize(Vec3(0.2f, -0.2f, 1.0f)));
}
