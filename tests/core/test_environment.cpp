// Environment lighting (core/lights/environment.h): the equirectangular mapping turns round
// exactly, the sampling density integrates to 1 over the sphere, each drawn direction has the
// density pdf() gives it, and drawing by luminance integrates the radiance like uniform sampling.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "core/direction_sampling.h"
#include "core/lights/environment.h"
#include "core/rng.h"

using namespace rt;

namespace {

// 32 x 16 texels: a dim sky, a bright 2 x 1 texel "sun", a dark ground.
std::shared_ptr<const EnvironmentImage> test_image() {
  std::vector<Vec3> texels;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) {
      Vec3 c = y < 8 ? Vec3(0.3f, 0.5f, 1.0f) : Vec3(0.1f, 0.08f, 0.05f);
      if (y == 4 && (x == 20 || x == 21)) c = Vec3(200.0f);
      texels.push_back(c);
    }
  return std::make_shared<const EnvironmentImage>(32, 16, texels);
}

}  // namespace

TEST_CASE("environment: directions and equirectangular coordinates map back and forth, rotated", "[environment]") {
  const Environment env(test_image(), 1.0f, 30.0f);
  Rng rng(1);
  for (int i = 0; i < 1000; ++i) {
    const Vec2 uv(rng.next_float(), 0.01f + 0.98f * rng.next_float());
    const Vec2 back = env.to_uv(env.from_uv(uv));
    CHECK(back.x == Approx(uv.x).margin(1e-4));
    CHECK(back.y == Approx(uv.y).margin(1e-4));
  }
  const Environment plain(test_image(), 1.0f, 0.0f);
  CHECK(plain.to_uv(Vec3(0, 0, -1)).x == Approx(0.5f));  // the image's centre looks down -Z
  CHECK(plain.to_uv(Vec3(1, 0, 0)).x == Approx(0.75f));  // longitude grows towards +X
  CHECK(plain.to_uv(Vec3(0, 1, 0)).y == Approx(0.0f));   // row 0 is straight up
  CHECK(env.to_uv(Vec3(0, 0, -1)).x == Approx(0.5f - 30.0f / 360.0f).margin(1e-5));
}

TEST_CASE("environment: the density integrates to 1 and matches what sampling draws", "[environment]") {
  const Environment env(test_image(), 2.0f, 10.0f);
  // Integral of pdf over the sphere, on a fine (theta, phi) grid.
  double integral = 0.0;
  const int n = 720;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double theta = (i + 0.5) * kPi / n, phi = (j + 0.5) * kPi / n;
      const Vec3 d(static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::cos(theta)),
                   static_cast<float>(std::sin(theta) * std::sin(phi)));
      integral += env.pdf(d) * std::sin(theta) * (kPi / n) * (kPi / n);
    }
  CHECK(integral == Approx(1.0).epsilon(2e-3));

  // Each sample's density is pdf() at its direction; its radiance is radiance() there; and the
  // estimator radiance / pdf integrates the radiance as uniform sampling does.
  Rng rng(2);
  double importance = 0.0, uniform = 0.0;
  const int samples = 200000;
  int sun = 0, on_edges = 0;
  for (int k = 0; k < samples; ++k) {
    Vec3 d, radiance;
    float pdf = 0.0f;
    REQUIRE(env.sample(Vec2(rng.next_float(), rng.next_float()), d, radiance, pdf));
    REQUIRE(pdf > 0.0f);
    // A direction within float rounding of a texel's edge can map back into its neighbour
    // (another weight): counted, and required to be rare.
    if (std::fabs(pdf - env.pdf(d)) > 2e-3f * pdf || std::fabs(radiance.x - env.radiance(d).x) > 1e-4f * radiance.x)
      ++on_edges;
    importance += radiance.y / pdf;
    sun += radiance.x > 100.0f;
    const Vec3 w = uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
    uniform += env.radiance(w).y / kUniformSpherePdf;
  }
  importance /= samples;
  uniform /= samples;
  INFO("integral of radiance: " << importance << " by luminance, " << uniform << " uniformly; sun drawn " << sun << "; "
                                << on_edges << " on texel edges");
  CHECK(importance == Approx(uniform).epsilon(0.03));
  CHECK(on_edges < samples / 5000);
  // The sun covers 2 of 512 texels but holds most of the luminance: most samples go to it.
  CHECK(sun > samples / 2);
}
