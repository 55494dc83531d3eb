// The path tracer as a whole (core/render/path_integrator.h): the white furnace, convergence at
// 1/sqrt(spp), determinism across threads, and no sample that is not a finite, non-negative colour
// in any shipped scene (multiple importance sampling: test_mis.cpp). Fixed seeds: every figure is repeatable.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/render/path_sampler.h"
#include "core/render/renderer.h"
#include "io/scene_loader.h"
#include "tests/support/image_stats.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"
#include "tests/support/two_lights_scene.h"

using namespace rt;
using rt::test::image_stats;
using rt::test::kTwoLights;
using rt::test::render_image;
using rt::test::rmse;

namespace {

// A sphere filling the view (the corners too: 17.4 degrees off-axis, the sphere 19.5) inside a uniform environment of
// radiance 1, no lights.
std::string furnace(const std::string& material) {
  return R"({
  "render": { "width": 12, "height": 12, "integrator": "path", "samples_per_pixel": 64, "max_depth": 64, "seed": 3 },
  "camera": { "position": [0, 0, 3], "look_at": [0, 0, 0], "fov": 25 },
  "background": [1, 1, 1],
  "ambient": [0.7, 0.2, 0.2],
  "materials": { "m": )" +
         material + R"( },
  "nodes": [ { "name": "ball", "shape": "sphere", "material": "m" } ]
})";
}

}  // namespace

TEST_CASE("white furnace: a sphere inside a uniform environment of radiance 1", "[path]") {
  struct Case {
    const char* name;
    const char* material;
    double expected;
    double tolerance;  // besides 4 standard errors
  };
  // Lambert, mirror and glass conserve energy exactly, so the sphere disappears (1) or shows its
  // albedo (0.5). The normalised Phong lobe loses what falls below the surface at grazing angles.
  const Case cases[] = {
      {"Lambert, albedo 1", R"({ "kd": 1 })", 1.0, 1e-4},
      {"Lambert, albedo 0.5", R"({ "kd": 0.5 })", 0.5, 1e-4},
      {"mirror, reflectivity 1", R"({ "kd": 0, "reflectivity": 1 })", 1.0, 1e-4},
      {"glass, ior 1.5", R"({ "kd": 0, "transmission": 1, "ior": 1.5 })", 1.0, 1e-3},
      {"glossy mirror, width 0.2", R"({ "kd": 0, "reflectivity": 1, "glossy": 0.2 })", 0.98, 0.02},
      {"Phong kd 0.5, ks 0.5, n 20", R"({ "kd": 0.5, "ks": 0.5, "shininess": 20 })", 0.97, 0.03},
  };
  for (const Case& c : cases) {
    const LoadedScene s = rt::test::load_scene_text("furnace.json", furnace(c.material));
    RenderStats stats;
    const rt::test::Stats st = image_stats(render_image(s, s.settings, &stats));
    INFO(c.name << ": mean " << st.mean << " +- " << st.error);
    CHECK(std::abs(st.mean - c.expected) <= 4.0 * st.error + c.tolerance);
    CHECK(stats.rays.invalid_samples == 0);
  }
}

TEST_CASE("convergence: the error falls as 1 / sqrt(spp)", "[path]") {
  const LoadedScene s = rt::test::load_scene_text("two_lights_convergence.json", kTwoLights);
  RenderSettings reference_settings = s.settings;
  reference_settings.path.samples_per_pixel = 8192;
  reference_settings.seed = 77;
  const Image reference = render_image(s, reference_settings);
  std::vector<double> xs, ys;
  for (const int spp : {4, 16, 64, 256}) {
    // The mean squared error over four seeds: one 16 x 12 image's is itself noisy at 4 spp.
    double mse = 0.0;
    for (uint64_t seed = 1; seed <= 4; ++seed) {
      RenderSettings settings = s.settings;
      settings.path.samples_per_pixel = spp;
      settings.seed = seed;
      const double e = rmse(render_image(s, settings), reference);
      mse += e * e / 4.0;
    }
    xs.push_back(std::log(static_cast<double>(spp)));
    ys.push_back(0.5 * std::log(mse));
  }
  // Least-squares slope of log RMSE against log spp.
  const double n = static_cast<double>(xs.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    sx += xs[i];
    sy += ys[i];
    sxx += xs[i] * xs[i];
    sxy += xs[i] * ys[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  INFO("slope " << slope << "; RMSE at 4 spp " << std::exp(ys.front()) << ", at 256 spp " << std::exp(ys.back()));
  CHECK(slope == Approx(-0.5).margin(0.1));
}

TEST_CASE("path tracing: the image is the same for any thread count and tile size", "[path][determinism]") {
  const LoadedScene s = rt::test::load_scene_text(
      "cornell_threads.json", rt::test::read_file(rt::test::source_path("scenes/cornell_box.json")));
  RenderSettings settings = s.settings;
  settings.width = settings.height = 24;
  settings.path.samples_per_pixel = 16;
  settings.path.noise_threshold = 0.05f;  // the adaptive stop too
  settings.threads = 1;
  settings.tile_size = 32;
  const Image one = render_image(s, settings);
  settings.threads = 2;
  settings.tile_size = 5;
  const Image two = render_image(s, settings);
  REQUIRE(one.pixels.size() == two.pixels.size());
  for (size_t i = 0; i < one.pixels.size(); ++i) REQUIRE(one.pixels[i] == two.pixels[i]);
}

TEST_CASE("path tracing: every shipped scene gives finite, non-negative samples only", "[path]") {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(rt::test::source_path("scenes"))) {
    if (entry.path().extension() != ".json") continue;
    Diagnostics diags;
    auto loaded = load_scene(entry.path().string(), rt::test::load_options(), diags);
    INFO(entry.path().string());
    REQUIRE(loaded);
    RenderSettings settings = loaded->settings;
    settings.integrator = "path";
    settings.width = 32;
    settings.height = 18;
    settings.path.samples_per_pixel = 4;
    RenderStats stats;
    const Image image = render_image(*loaded, settings, &stats);
    CHECK(stats.rays.invalid_samples == 0);
    for (const Vec3& p : image.pixels) {
      REQUIRE(is_finite(p));
      REQUIRE(std::min(p.x, std::min(p.y, p.z)) >= 0.0f);
    }
    ++scenes;
  }
  CHECK(scenes >= 15);
}

TEST_CASE("noise threshold: converged pixels stop early, noisy ones take every sample", "[path]") {
  const LoadedScene s = rt::test::load_scene_text(
      "cornell_adaptive.json", rt::test::read_file(rt::test::source_path("scenes/cornell_box.json")));
  RenderSettings settings = s.settings;
  settings.width = settings.height = 24;
  settings.path.samples_per_pixel = 256;
  settings.path.noise_threshold = 0.05f;
  Film film;
  const RenderStats stats = render(s.scene, settings, film);
  uint64_t total = 0;
  int at_least = 1 << 30, at_most = 0;
  for (const uint16_t n : film.samples) {
    total += n;
    at_least = std::min<int>(at_least, n);
    at_most = std::max<int>(at_most, n);
  }
  const double mean = static_cast<double>(total) / static_cast<double>(film.samples.size());
  CHECK(stats.pixels.samples == total);
  INFO("samples per pixel: " << at_least << " to " << at_most << ", mean " << mean);
  // The black border outside the box converges at the first check; the lit walls need more.
  CHECK(at_least == 16);
  CHECK(at_most == 256);
  CHECK(mean < 230.0);
  // Pixels that stopped are within the threshold (checked from their own sample count).
  CHECK(pixel_relative_error(0.0, 0.0, 16) < 0.05f);
}

TEST_CASE("environment light: drawn by luminance, or found by BSDF rays alone, the image is the same",
          "[path][environment]") {
  Diagnostics diags;
  auto loaded = load_scene(rt::test::source_path("scenes/environment.json"), rt::test::load_options(), diags);
  REQUIRE(loaded);
  REQUIRE(loaded->scene.background.is_image());
  RenderSettings settings = loaded->settings;
  settings.width = 24;
  settings.height = 14;
  settings.path.samples_per_pixel = 1024;
  settings.max_depth = 3;
  const Image mis = render_image(*loaded, settings);
  settings.path.strategy = PathSettings::Strategy::kBsdf;
  settings.seed = 5;
  const Image bsdf = render_image(*loaded, settings);
  const double a = image_stats(mis).mean, b = image_stats(bsdf).mean;
  // The sun is 3 degrees across: BSDF sampling alone finds it rarely, so its image is far noisier
  // (RMSE against MIS's), but its mean converges to the same.
  INFO("mean " << a << " with the environment drawn by luminance (MIS), " << b << " by BSDF sampling alone");
  CHECK(b == Approx(a).epsilon(0.03));
}

TEST_CASE("progressive passes: with time enough, the same film as one render, out of time, whole passes",
          "[path][progressive]") {
  const LoadedScene s = rt::test::load_scene_text("progressive.json", kTwoLights);
  RenderSettings settings = s.settings;
  settings.path.samples_per_pixel = 40;  // not a multiple of the pass: the last pass is short
  settings.path.noise_threshold = 0.05f;
  RenderView view;
  view.aovs = true;
  Film once, passes;
  const RenderStats a = render(s.scene, settings, once, {}, 0, view);
  RenderControl control;
  control.time_limit = 1e6;
  const RenderStats b = render(s.scene, settings, passes, control, 0, view);
  CHECK(a.passes == 0);
  CHECK(b.passes == 5);
  CHECK_FALSE(b.time_limited);
  CHECK(once.color.pixels == passes.color.pixels);  // the same bits: the sums run in the same order
  CHECK(once.samples == passes.samples);
  // The statistics' totals: the last pass's, not every pass's added up.
  const uint64_t samples = std::accumulate(once.samples.begin(), once.samples.end(), uint64_t{0});
  CHECK(a.pixels.samples == samples);
  CHECK(b.pixels.samples == samples);
  // The noise threshold stopped some pixels early (the same ones, at the same sample, both ways).
  CHECK(std::count_if(once.samples.begin(), once.samples.end(), [](uint16_t n) { return n < 40; }) > 0);
  CHECK(once.albedo.pixels == passes.albedo.pixels);
  CHECK(once.variance == passes.variance);
  CHECK(a.rays.total() == b.rays.total());
  // A limit already past after the first pass: one whole pass, 8 samples in every pixel.
  control.time_limit = 1e-9;
  Film first;
  const RenderStats c = render(s.scene, settings, first, control, 0, view);
  CHECK(c.passes == 1);
  CHECK(c.time_limited);
  for (const uint16_t n : first.samples) REQUIRE(n == kPassSamples);
  CHECK(c.pixels.samples == first.samples.size() * kPassSamples);
}

TEST_CASE("resumed renders: 16 samples, then 24 more from the sums kept, give the bits of 40 at once",
          "[path][progressive][resume]") {
  const LoadedScene s = rt::test::load_scene_text("resume.json", kTwoLights);
  RenderSettings settings = s.settings;
  settings.path.noise_threshold = 0.05f;
  RenderView view;
  view.aovs = true;
  settings.path.samples_per_pixel = 40;
  Film once;
  render(s.scene, settings, once, {}, 0, view);
  // The first part keeps its sums; the second starts from them.
  settings.path.samples_per_pixel = 16;
  view.keep_sums = true;
  Film part;
  render(s.scene, settings, part, {}, 0, view);
  REQUIRE(part.sums.size() == part.color.pixels.size());
  for (const SampleSums& p : part.sums) REQUIRE(p.n == 16);  // no pixel stops at its last sample
  settings.path.samples_per_pixel = 40;
  view.resume_from = &part.sums;
  Film resumed;
  const RenderStats stats = render(s.scene, settings, resumed, {}, 0, view);
  CHECK(resumed.color.pixels == once.color.pixels);
  CHECK(resumed.samples == once.samples);
  CHECK(resumed.albedo.pixels == once.albedo.pixels);
  CHECK(resumed.variance == once.variance);
  CHECK(stats.rays[RayKind::kCamera] < 40u * once.color.pixels.size());  // only the new samples were traced
  // In passes too (a time limit), and to the same end again: nothing more to trace, the same film.
  RenderControl control;
  control.time_limit = 1e6;
  Film passes;
  render(s.scene, settings, passes, control, 0, view);
  CHECK(passes.color.pixels == once.color.pixels);
  view.resume_from = &resumed.sums;
  Film again;
  const RenderStats none = render(s.scene, settings, again, {}, 0, view);
  CHECK(again.color.pixels == once.color.pixels);
  CHECK(none.rays.total() == 0);
}
