// Robust ray origins (core/ray.h, core/float_error.h): rays leaving a surface never find it again
// at their own start, on any shape under any transform, yet a blocker a hair above the surface
// still casts its shadow, which the fixed offset rtcli used before (1e-4 of the point's size)
// stepped over.
#include <cmath>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "core/csg/csg_object.h"
#include "tests/support/geometry.h"
#include "tests/support/loading.h"

using namespace rt;
using rt::test::make_ray;

TEST_CASE("float error: gamma and the next float up and down", "[ray-origin]") {
  CHECK(float_gamma(1) == Approx(5.960464e-8).epsilon(1e-6));
  CHECK(float_gamma(7) == Approx(7 * 5.960464e-8).epsilon(1e-6));
  CHECK(next_float_up(1.0f) == std::nextafter(1.0f, 2.0f));
  CHECK(next_float_down(1.0f) == std::nextafter(1.0f, 0.0f));
  CHECK(next_float_up(-1.0f) == std::nextafter(-1.0f, 0.0f));
  CHECK(next_float_up(0.0f) == std::numeric_limits<float>::denorm_min());
  CHECK(next_float_up(-0.0f) == std::numeric_limits<float>::denorm_min());
  CHECK(next_float_down(0.0f) == -std::numeric_limits<float>::denorm_min());
  CHECK(next_float_up(kInfinity) == kInfinity);
  CHECK(next_float_down(-kInfinity) == -kInfinity);
}

TEST_CASE("float error: a transformed point's bound covers the double-precision result", "[ray-origin]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-100.0f, 100.0f);
  for (int i = 0; i < 2000; ++i) {
    const Mat4 m = compose_trs(Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)),
                               Vec3(0.01f + std::fabs(u(rng)) / 10.0f, 0.5f, 3.0f));
    const Vec3 p(u(rng), u(rng) / 100.0f, u(rng) * 10.0f);
    const Vec3 got = Vec3(m * Vec4(p, 1.0f));
    const glm::dvec3 exact = glm::dvec3(glm::dmat4(m) * glm::dvec4(glm::dvec3(p), 1.0));
    const Vec3 e = transformed_point_error(m, p, Vec3(0.0f));
    for (int c = 0; c < 3; ++c) REQUIRE(std::fabs(double(got[c]) - exact[c]) <= double(e[c]));
  }
}

TEST_CASE("ray origins: off the surface by the error bound, rounded away, on the side the ray leaves to",
          "[ray-origin]") {
  const Vec3 p(1.0f, 2.0f, -3.0f), n(0.0f, 1.0f, 0.0f);
  // No error (a point known exactly): it moves one float along the normal and nowhere else.
  Vec3 o = offset_ray_origin(p, Vec3(0.0f), n, Vec3(0.3f, 1.0f, 0.0f));
  CHECK(o.x == p.x);
  CHECK(o.y == std::nextafter(2.0f, 3.0f));
  CHECK(o.z == p.z);
  o = offset_ray_origin(p, Vec3(0.0f), n, Vec3(0.3f, -1.0f, 0.0f));
  CHECK(o.y == std::nextafter(2.0f, 1.0f));
  // With a bound: by dot(|n|, error) along n; the tangential bounds do not count.
  o = offset_ray_origin(p, Vec3(5.0f, 1e-5f, 7.0f), n, Vec3(0.0f, 1.0f, 0.0f));
  CHECK(o.y - p.y == Approx(1e-5f).margin(5e-7));
  CHECK(o.x == p.x);
}

TEST_CASE(
    "ray origins: one float along each axis of the normal, from zero, subnormals, the largest floats and "
    "infinities",
    "[ray-origin]") {
  constexpr float kMin = std::numeric_limits<float>::min();  // the smallest normal float
  constexpr float kMax = std::numeric_limits<float>::max();
  const float sub_min = std::numeric_limits<float>::denorm_min();
  const float values[] = {0.0f,  -0.0f,    sub_min,   -sub_min, kMin - sub_min, kMin,      -kMin,     1.0f,
                          -1.0f, 3.5e-30f, -7.25e12f, kMax,     -kMax,          kInfinity, -kInfinity};
  // The normal's x is positive, its y negative, its z 0: x steps up, y down, z stays. A zero or
  // subnormal coordinate steps to the smallest normal float, never to a subnormal.
  const Vec3 n = glm::normalize(Vec3(1.0f, -1.0f, 0.0f));
  for (const float v : values) {
    CAPTURE(v);
    const Vec3 o = offset_ray_origin(Vec3(v), Vec3(0.0f), n, n);
    const bool tiny = std::fabs(v) < kMin;
    CHECK(o.x == (tiny ? kMin : std::nextafter(v, kInfinity)));
    CHECK(o.y == (tiny ? -kMin : std::nextafter(v, -kInfinity)));
    CHECK(o.z == v);
  }
  const Vec3 nan_origin = offset_ray_origin(Vec3(std::nanf("")), Vec3(0.0f), n, n);
  CHECK(std::isnan(nan_origin.x));
  CHECK(std::isnan(nan_origin.y));
}

namespace {

// Every kind of surface under rotations, non-uniform scales and far translations, a CSG solid and
// a placed mesh: where a ray from outside hits, rays leaving it on both sides must not find the
// same primitive within a thousandth of a unit (each shape is at least 0.3 across).
std::string busy_scene() {
  return R"({"camera": {"position": [0, 0, 90], "look_at": [40, 30, 0]},
    "materials": {"m": {"kd": 0.5}},
    "lights": [{"type": "point", "position": [0, 100, 100]}],
    "nodes": [
      {"shape": "sphere", "material": "m", "transform": {"translate": [40, 30, 0], "rotate": [10, 20, 30], "scale": [2, 0.5, 1]}},
      {"shape": "cube", "material": "m", "transform": {"translate": [36, 27, 1], "rotate": [33, 45, 12], "scale": [1, 2, 0.3]}},
      {"shape": "cylinder", "material": "m", "transform": {"translate": [44, 33, -1], "rotate": [70, 5, 40], "scale": [0.7, 1.5, 2]}},
      {"shape": "cone", "material": "m", "transform": {"translate": [44, 27, 0], "rotate": [-50, 10, 5], "scale": [1, 1.3, 1.8]}},
      {"shape": "plane", "material": "m", "transform": {"translate": [40, 25, 0], "rotate": [5, 0, 3], "scale": 30}},
      {"csg": "difference", "material": "m", "transform": {"translate": [36, 33, 0], "rotate": [20, 30, 0]}, "children": [
        {"shape": "cube", "transform": {"scale": 1.2}},
        {"shape": "sphere", "transform": {"scale": 1.5}}]},
      {"mesh": {"file": ")" +
         rt::test::source_path("scenes/models/knot.glb") + R"("}, "material": "m",
       "transform": {"translate": [40, 36, 0], "rotate": [0, 30, 0], "scale": 2.5}}]})";
}

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> g;
  for (;;) {
    const Vec3 v(g(rng), g(rng), g(rng));
    if (glm::dot(v, v) > 1e-6f) return glm::normalize(v);
  }
}

}  // namespace

TEST_CASE("ray origins: rays leaving any surface never hit it again where they start", "[ray-origin]") {
  const LoadedScene s = rt::test::load_scene_text("ray-origins.json", busy_scene());
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int hits = 0, spawned = 0, self_hits = 0, self_crossings = 0;
  std::string first_self_hit;
  float nearest = kInfinity;
  for (int i = 0; i < 40000; ++i) {
    const Vec3 target(40.0f + 8.0f * u(rng), 30.0f + 8.0f * u(rng), 3.0f * u(rng));
    Ray r = make_ray(target + 20.0f * random_unit(rng), Vec3(0.0f));
    r.direction = target - r.origin;
    Hit hit;
    if (!s.scene.intersect(r, hit)) continue;
    ++hits;
    const SurfaceInteraction si = s.scene.surface(r, hit);
    for (int side = 0; side < 2; ++side) {  // 0: back out the way it came, 1: through (refraction)
      Vec3 w = random_unit(rng);
      const bool outward = glm::dot(w, si.geometric_normal) * glm::dot(r.direction, si.geometric_normal) < 0.0f;
      if (outward != (side == 0)) w = -w;
      Ray leave = make_ray(offset_ray_origin(si.position, si.position_error, si.geometric_normal, w), w);
      Hit again;
      ++spawned;
      // Shadow rays through glass walk every crossing instead (Bvh::visit_hits): the same rule.
      auto crossing = [&](const Hit& h) {
        const float distance = h.t * glm::length(leave.direction);
        if (h.prim == hit.prim && h.part == hit.part && csg_surface_index(h) == csg_surface_index(hit) &&
            distance < 1e-3f) {
          ++self_crossings;
          if (first_self_hit.empty()) first_self_hit = "a crossing at " + std::to_string(distance);
        }
        return false;
      };
      s.scene.bvh.visit_hits(leave, crossing);
      if (!s.scene.intersect(leave, again)) continue;
      const float distance = again.t * glm::length(leave.direction);
      if (again.prim == hit.prim && again.part == hit.part && csg_surface_index(again) == csg_surface_index(hit) &&
          distance < 1e-3f) {
        ++self_hits;
        if (first_self_hit.empty())
          first_self_hit = "primitive " + std::to_string(hit.prim) + " part " + std::to_string(hit.part) +
                           (side == 0 ? ", backing out" : ", going through") + ", again at " + std::to_string(distance);
        nearest = std::min(nearest, distance);
      }
    }
  }
  INFO("hits " << hits << ", rays spawned " << spawned << ", nearest self-hit " << nearest
               << ", first: " << first_self_hit);
  CHECK(hits > 30000);
  CHECK(self_hits == 0);
  CHECK(self_crossings == 0);
}

TEST_CASE("ray origins: a blocker 1e-5 above a surface shadows a grazing ray", "[ray-origin]") {
  // A wide box whose top is at y = 0 and, just above it, a thin slab from x = 0.02 to 0.5.
  const LoadedScene s = rt::test::load_scene_text("ray-origins-graze.json", R"({
    "camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
    "materials": {"m": {"kd": 0.5}},
    "lights": [{"type": "point", "position": [10, 0.02, 0]}],
    "nodes": [
      {"shape": "cube", "material": "m", "transform": {"translate": [0, -1, 0], "scale": [4, 1, 4]}},
      {"shape": "plane", "material": "m", "transform": {"translate": [0.26, 1e-5, 0], "scale": [0.24, 1, 1]}}]})");
  Ray down = make_ray(Vec3(0.0f, 3.0f, 0.0f), Vec3(0.0f, -1.0f, 0.0f));
  Hit hit;
  REQUIRE(s.scene.intersect(down, hit));
  const SurfaceInteraction si = s.scene.surface(down, hit);
  CHECK(si.position.y == 0.0f);
  const Vec3 to_light = glm::normalize(Vec3(10.0f, 0.002f, 0.0f));  // rises 1e-5 over 0.05
  Ray shadow = make_ray(offset_ray_origin(si.position, si.position_error, si.geometric_normal, to_light), to_light);
  CHECK(shadow.origin.y < 1e-6f);
  shadow.tmax = 10.0f;
  CHECK(s.scene.bvh.occluded(shadow));
  // The rule this replaced started the ray 1e-4 above the box and missed the slab.
  Ray fixed = shadow;
  fixed.origin = si.position + Vec3(0.0f, 1e-4f, 0.0f);
  CHECK_FALSE(s.scene.bvh.occluded(fixed));
}
