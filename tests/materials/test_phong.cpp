#include <catch2/catch.hpp>

#include "core/color.h"
#include "core/lights/light.h"
#include "core/material.h"
#include "io/image/rgb8_image.h"
#include "materials/phong.h"

using namespace rt;

TEST_CASE("phong: Lambert term plus a specular lobe around the mirror direction", "[materials]") {
  Material m;
  m.kd = Vec3(0.5f);
  m.ks = Vec3(0.25f);
  m.shininess = 10.0f;
  const Vec3 n(0, 1, 0);
  const Vec3 l = glm::normalize(Vec3(1, 1, 0));
  // Viewer exactly in the mirror direction: full specular.
  Vec3 f = phong_reflectance(m.kd, m.ks, m.shininess, n, l, glm::normalize(Vec3(-1, 1, 0)));
  CHECK(f.x == Approx(0.5f * std::sqrt(0.5f) + 0.25f));
  // Viewer at 60 degrees from the mirror direction: cos = 0.5, specular 0.25 * 0.5^10.
  const Vec3 r = glm::normalize(Vec3(-1, 1, 0));
  const Vec3 v = glm::normalize(0.5f * r + std::sqrt(0.75f) * glm::normalize(Vec3(1, 1, 0)));
  f = phong_reflectance(m.kd, m.ks, m.shininess, n, l, v);
  CHECK(f.x == Approx(0.5f * std::sqrt(0.5f) + 0.25f * std::pow(0.5f, 10.0f)).epsilon(1e-4));
  // Light below the surface: nothing.
  CHECK(phong_reflectance(m.kd, m.ks, m.shininess, n, -l, v) == Vec3(0.0f));
}

TEST_CASE("point light: quadratic attenuation 1 / (c0 + c1 d + c2 d^2)", "[lights]") {
  const PointLight light{{0, 4, 0}, Vec3(2.0f), {1.0f, 0.5f, 0.25f}};
  const LightSample s = sample_li(Light(light), Vec3(0), Vec2(0.5f));
  CHECK(s.distance == Approx(4.0f));
  CHECK(s.direction.y == Approx(1.0f));
  CHECK(s.radiance.x == Approx(2.0f / (1.0f + 2.0f + 4.0f)));
}

TEST_CASE("sRGB encoding: clamp, transfer curve, rounding", "[io][image]") {
  CHECK(srgb8(0.0f) == 0);
  CHECK(srgb8(1.0f) == 255);
  CHECK(srgb8(7.0f) == 255);  // clamped
  CHECK(srgb8(-1.0f) == 0);
  CHECK(srgb8(std::nanf("")) == 0);
  CHECK(srgb8(0.5f) == 188);  // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354 -> 187.5 -> 188
  CHECK(srgb8(0.002f) == 7);  // linear segment: 12.92 * 0.002 * 255 = 6.6
}
