// Whitted's rect-light samples worked out eight at a time (core/lights/rect_light_batch.h) held
// to rect_point and Whitted's rule, one sample at a time, bit for bit: the batch must not move a
// single pixel.
#include <catch2/catch.hpp>

#include "core/lights/rect_light_batch.h"

using namespace rt;

TEST_CASE("light sampling: a rect light's batch of eight gives rect_point's floats and Whitted's factor", "[lights]") {
  RectLight light;
  light.corner = Vec3(-1.3f, 3.7f, -0.6f);
  light.edge1 = Vec3(2.1f, 0.2f, 0.0f);
  light.edge2 = Vec3(0.3f, -0.1f, 1.7f);
  light.attenuation = Attenuation{1.0f, 0.09f, 0.032f};
  uint32_t state = 99;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) * 0x1p-24f;
  };
  int compared = 0;
  for (const bool two_sided : {false, true}) {
    light.two_sided = two_sided;
    const RectFrame frame(light);
    // Points below the light, above it (its dark back when one-sided), and one on its corner.
    for (int k = 0; k < 200; ++k) {
      const Vec3 point = k == 0 ? light.corner : Vec3(4.0f * next() - 2.0f, 8.0f * next() - 2.0f, 4.0f * next() - 2.0f);
      float u[2][kPacketSize];
      for (int j = 0; j < kPacketSize; ++j) {
        u[0][j] = k == 0 && j == 0 ? 0.0f : next();
        u[1][j] = k == 0 && j == 0 ? 0.0f : next();
      }
      RectLightBatch batch;
      rect_light_batch(light, frame, point, u, batch);
      for (int j = 0; j < kPacketSize; ++j) {
        const LightSample ls = rect_point(light, frame, light.point(Vec2(u[0][j], u[1][j])) - point);
        const float scale = ls.distance > 0.0f ? light.attenuation(ls.distance) * ls.cos_light : 0.0f;
        INFO("two-sided " << two_sided << ", point " << k << ", lane " << j);
        REQUIRE(batch.direction(j) == ls.direction);
        REQUIRE(batch.distance[j] == ls.distance);
        REQUIRE(batch.scale[j] == scale);
        ++compared;
      }
    }
  }
  CHECK(compared == 3200);
}

TEST_CASE("light sampling: sample_sides keeps the samples a shadow ray is made for, as one at a time", "[lights]") {
  uint32_t state = 7;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) * 0x1p-24f;
  };
  const auto direction = [&] { return glm::normalize(Vec3(next() - 0.5f, next() - 0.5f, next() - 0.5f)); };
  int lit = 0, dark = 0, behind = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 n = direction(), ng = glm::normalize(n + 0.5f * direction());
    const bool lifted = k % 3 == 0;
    // A colour with a black channel or two, and now and then all black.
    const Vec3 color(k % 5 == 0 ? 0.0f : next(), k % 7 == 0 ? 0.0f : next(), k % 4 == 0 ? 0.0f : next());
    RectLightBatch batch;
    for (int j = 0; j < kPacketSize; ++j) {
      const Vec3 l = direction();
      batch.dx[j] = l.x;
      batch.dy[j] = l.y;
      batch.dz[j] = l.z;
      batch.distance[j] = 1.0f + next();
      batch.scale[j] = j == 3 ? 0.0f : next();  // an edge-on sample
    }
    const SampleSides sides = sample_sides(batch, color, n, ng, lifted);
    for (int j = 0; j < kPacketSize; ++j) {
      // ShadowRays::make's tests (core/render/direct_lighting.cpp), one sample at a time.
      const Vec3 l = batch.direction(j);
      const bool makes = !(glm::dot(n, l) <= 0.0f) && !(glm::dot(ng, l) <= 0.0f && !lifted) &&
                         !(max_component(color * batch.scale[j]) <= 0.0f);
      INFO("round " << k << ", lane " << j);
      REQUIRE(static_cast<bool>(sides.light >> j & 1u) == makes);
      REQUIRE(static_cast<bool>(sides.behind >> j & 1u) == (glm::dot(l, ng) < 0.0f));
      (makes ? lit : dark) += 1;
      behind += glm::dot(l, ng) < 0.0f;
    }
  }
  CHECK(lit > 2000);  // each outcome is met often
  CHECK(dark > 2000);
  CHECK(behind > 2000);
}
