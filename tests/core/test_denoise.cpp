// The feature-guided denoiser (core/denoise/feature_filter.h) on images whose truth is known:
// noise goes, edges of geometry and texture stay, lights stay as they are, and the result is the
// same for any thread count.
#include <cmath>

#include <catch2/catch.hpp>

#include "core/denoise/denoiser.h"
#include "core/rng.h"

using namespace rt;

namespace {

constexpr int kSize = 48;

// A scene's first hits as a denoiser sees them, with the truth `clean` and `color` = clean + noise
// of standard deviation `sigma` (its variance in `variance`).
struct Frame {
  Image clean{kSize, kSize}, color{kSize, kSize}, albedo{kSize, kSize}, normal{kSize, kSize}, emission{kSize, kSize};
  std::vector<float> depth = std::vector<float>(kSize * kSize, 5.0f);
  std::vector<float> variance = std::vector<float>(kSize * kSize, 0.0f);

  void add_noise(float sigma, uint64_t seed) {
    Rng rng(seed);
    for (size_t i = 0; i < color.pixels.size(); ++i) {
      // The sum of four uniforms: roughly normal, of standard deviation sigma.
      float u = 0.0f;
      for (int k = 0; k < 4; ++k) u += rng.next_float() - 0.5f;
      color.pixels[i] = clean.pixels[i] + Vec3(u * sigma * std::sqrt(3.0f));
      variance[i] = sigma * sigma;
    }
  }
  DenoiseInput input() const { return DenoiseInput{color, albedo, normal, emission, depth, variance}; }
};

double rmse(const Image& a, const Image& b, int x0 = 0, int x1 = kSize) {
  double sum = 0.0;
  int n = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = x0; x < x1; ++x, ++n)
      for (int c = 0; c < 3; ++c) sum += std::pow(a.at(x, y)[c] - b.at(x, y)[c], 2.0);
  return std::sqrt(sum / (3.0 * n));
}

Image denoised(const Frame& f, unsigned threads = 2) { return make_denoiser("feature")->denoise(f.input(), threads); }

}  // namespace

TEST_CASE("denoiser: a flat, evenly lit wall loses most of its noise", "[denoise]") {
  Frame f;
  for (size_t i = 0; i < f.clean.pixels.size(); ++i) {
    f.clean.pixels[i] = Vec3(0.4f, 0.3f, 0.2f);
    f.albedo.pixels[i] = Vec3(0.8f, 0.6f, 0.4f);
    f.normal.pixels[i] = Vec3(0.0f, 0.0f, 1.0f);
  }
  f.add_noise(0.1f, 1);
  const double before = rmse(f.color, f.clean), after = rmse(denoised(f), f.clean);
  INFO("RMSE " << before << " -> " << after);
  CHECK(after < before / 4.0);
}

TEST_CASE("denoiser: a fold between two walls and a texture's edges stay sharp", "[denoise]") {
  Frame f;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool left = x < kSize / 2;
      // Left wall lit 1.0 facing +z, right wall lit 0.2 facing +x; a checker texture on both.
      const bool dark_square = ((x / 6) + (y / 6)) % 2 == 1;
      const Vec3 albedo = dark_square ? Vec3(0.1f) : Vec3(0.8f);
      f.albedo.at(x, y) = albedo;
      f.normal.at(x, y) = left ? Vec3(0.0f, 0.0f, 1.0f) : Vec3(1.0f, 0.0f, 0.0f);
      f.clean.at(x, y) = albedo * (left ? 1.0f : 0.2f);
    }
  f.add_noise(0.05f, 2);
  const Image out = denoised(f);
  // The columns beside the fold keep their own wall's light (no bleeding across), and the
  // texture is as sharp as the truth: the error falls everywhere, the fold's columns included.
  CHECK(rmse(out, f.clean) < rmse(f.color, f.clean) / 2.5);
  CHECK(rmse(out, f.clean, kSize / 2 - 2, kSize / 2 + 2) < rmse(f.color, f.clean, kSize / 2 - 2, kSize / 2 + 2));
  for (int y = 0; y < kSize; ++y) {
    CHECK(std::fabs(out.at(kSize / 2 - 1, y).x - f.clean.at(kSize / 2 - 1, y).x) < 0.06f);
    CHECK(std::fabs(out.at(kSize / 2, y).x - f.clean.at(kSize / 2, y).x) < 0.06f);
  }
}

TEST_CASE("denoiser: what the camera sees emitted (a light, the background) is kept as it is", "[denoise]") {
  Frame f;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool light = x >= 20 && x < 28 && y >= 20 && y < 28;
      const bool sky = y < 8;
      f.albedo.at(x, y) = light || sky ? Vec3(0.0f) : Vec3(0.7f);
      f.normal.at(x, y) = sky ? Vec3(0.0f) : Vec3(0.0f, 1.0f, 0.0f);
      if (sky) f.depth[static_cast<size_t>(y * kSize + x)] = 1e10f;
      f.emission.at(x, y) = light ? Vec3(20.0f, 15.0f, 10.0f) : sky ? Vec3(0.3f, 0.5f, 0.9f) : Vec3(0.0f);
      f.clean.at(x, y) = light || sky ? f.emission.at(x, y) : Vec3(0.35f);
    }
  f.add_noise(0.05f, 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (f.emission.at(x, y) != Vec3(0.0f)) f.color.at(x, y) = f.emission.at(x, y);  // emitters have no noise
  const Image out = denoised(f);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (f.emission.at(x, y) != Vec3(0.0f)) REQUIRE(out.at(x, y) == f.emission.at(x, y));
  // The floor beside the light does not take its glow.
  CHECK(out.at(19, 24).x == Approx(0.35f).margin(0.05f));
  CHECK(out.at(28, 24).x == Approx(0.35f).margin(0.05f));
}

TEST_CASE("denoiser: the same image for any thread count", "[denoise][determinism]") {
  Frame f;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      f.albedo.at(x, y) = Vec3(0.5f + 0.01f * static_cast<float>(x));
      f.normal.at(x, y) = glm::normalize(Vec3(0.0f, 1.0f, 0.02f * static_cast<float>(y)));
      f.depth[static_cast<size_t>(y * kSize + x)] = 3.0f + 0.1f * static_cast<float>(y);
      f.clean.at(x, y) = Vec3(0.2f + 0.01f * static_cast<float>(y));
    }
  f.add_noise(0.1f, 4);
  const Image one = denoised(f, 1), three = denoised(f, 3);
  CHECK(one.pixels == three.pixels);
}
