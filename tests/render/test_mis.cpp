// Multiple importance sampling (core/render/path_integrator.cpp): MIS, light sampling alone and
// BSDF sampling alone converge to one image, and MIS's noise is the least where each strategy alone
// does badly somewhere. A strategy's mean is held to the others' within four standard errors
// measured over independent seeds: a strategy whose few large samples find a small bright light
// has a skewed mean at any one seed (most seeds fall below the mean), so one seed's 2% says nothing.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/direction_sampling.h"
#include "core/lights/light.h"
#include "tests/support/image_stats.h"
#include "tests/support/loading.h"
#include "tests/support/two_lights_scene.h"

using namespace rt;
using rt::test::image_stats;
using rt::test::kTwoLights;
using rt::test::render_image;
using rt::test::rmse;

namespace {

// The three ways of finding light, in one order: MIS, light sampling alone, BSDF sampling alone.
constexpr PathSettings::Strategy kStrategies[3] = {PathSettings::Strategy::kMis, PathSettings::Strategy::kLights,
                                                   PathSettings::Strategy::kBsdf};

// `settings` rendered with each of kStrategies, numbers drawn with `seed`.
std::vector<Image> by_strategy(const LoadedScene& s, RenderSettings settings, uint64_t seed) {
  settings.seed = seed;
  std::vector<Image> images;
  for (const PathSettings::Strategy strategy : kStrategies) {
    settings.path.strategy = strategy;
    images.push_back(render_image(s, settings));
  }
  return images;
}

// A glossy floor under the large dim light alone: light sampling is poor at its sharp reflection,
// BSDF sampling on the rough rest.
const char* kLargeLight = R"({
  "render": { "width": 16, "height": 12, "integrator": "path", "samples_per_pixel": 256, "max_depth": 1,
              "sampler": "independent" },
  "camera": { "position": [0, 2, 5], "look_at": [0, 0, 0], "fov": 50 },
  "background": [0, 0, 0],
  "materials": { "floor": { "kd": 0.3, "ks": 0.6, "shininess": 60 } },
  "lights": [
    { "type": "rect", "corner": [0.2, 2.5, -2], "edge1": [2.5, 0, 0], "edge2": [0, 0, 2.5], "color": [1.5, 1.5, 1.5] }
  ],
  "nodes": [ { "name": "floor", "shape": "plane", "material": "floor", "transform": { "scale": 4 } } ]
})";

// One strategy over `seeds` independent renders: the image's mean with its standard error across
// seeds, and the noise (RMS over pixels of each pixel's standard deviation across seeds).
struct SeedSpread {
  double mean = 0.0;
  double error = 0.0;
  double noise = 0.0;
};

SeedSpread over_seeds(const LoadedScene& s, RenderSettings settings, int seeds) {
  std::vector<double> means;
  std::vector<Vec3> sum, squares;
  for (int k = 0; k < seeds; ++k) {
    settings.seed = 1000 + static_cast<uint64_t>(k);
    const Image image = render_image(s, settings);
    means.push_back(image_stats(image).mean);
    sum.resize(image.pixels.size(), Vec3(0.0f));
    squares.resize(image.pixels.size(), Vec3(0.0f));
    for (size_t p = 0; p < image.pixels.size(); ++p) {
      sum[p] += image.pixels[p];
      squares[p] += image.pixels[p] * image.pixels[p];
    }
  }
  const double n = static_cast<double>(seeds);
  SeedSpread out;
  double spread = 0.0;
  for (const double m : means) out.mean += m / n;
  for (const double m : means) spread += (m - out.mean) * (m - out.mean) / (n - 1.0);
  out.error = std::sqrt(spread / n);
  double variance = 0.0;
  for (size_t p = 0; p < sum.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      const double mean = sum[p][c] / n;
      variance += (squares[p][c] / n - mean * mean) * n / (n - 1.0) / (3.0 * static_cast<double>(sum.size()));
    }
  out.noise = std::sqrt(std::max(0.0, variance));
  return out;
}

}  // namespace

TEST_CASE("MIS: light sampling and MIS agree, MIS's error is far below BSDF sampling's", "[path][mis]") {
  const LoadedScene s = rt::test::load_scene_text("two_lights.json", kTwoLights);
  RenderSettings reference_settings = s.settings;
  reference_settings.path.samples_per_pixel = 4096;
  const Image reference = render_image(s, reference_settings);
  double error[3], mean[3];
  const std::vector<Image> images = by_strategy(s, s.settings, 100);  // not the reference's numbers
  for (int k = 0; k < 3; ++k) {
    error[k] = rmse(images[k], reference);
    mean[k] = image_stats(images[k]).mean;
  }
  INFO("RMSE against 4096 spp: MIS " << error[0] << ", lights only " << error[1] << ", BSDF only " << error[2]);
  INFO("means at 32 spp: " << mean[0] << ", " << mean[1] << ", " << mean[2]);
  CHECK(error[0] < 0.1 * error[2]);
  CHECK(error[1] < 0.1 * error[2]);
  CHECK(mean[1] == Approx(mean[0]).epsilon(0.01));
  // At the reference's effort light sampling alone converges to the MIS image's mean.
  RenderSettings lights_only = reference_settings;
  lights_only.path.strategy = PathSettings::Strategy::kLights;
  lights_only.seed = 200;
  CHECK(image_stats(render_image(s, lights_only)).mean == Approx(image_stats(reference).mean).epsilon(0.005));
}

TEST_CASE("MIS: each strategy alone converges to the same mean, MIS is the least noisy (32 seeds)", "[path][mis]") {
  const LoadedScene s = rt::test::load_scene_text("large_light.json", kLargeLight);
  SeedSpread spread[3];
  for (int k = 0; k < 3; ++k) {
    RenderSettings settings = s.settings;
    settings.path.strategy = kStrategies[k];
    spread[k] = over_seeds(s, settings, 32);
    INFO("strategy " << k << ": mean " << spread[k].mean << " +- " << spread[k].error << ", noise " << spread[k].noise);
    CHECK(spread[k].error < 0.005 * spread[k].mean);  // the check below can see a 2% bias
    CHECK(std::abs(spread[k].mean - spread[0].mean) <=
          4.0 * std::hypot(spread[k].error, spread[0].error) + 1e-6 * spread[0].mean);
  }
  CHECK(spread[0].noise < 0.9 * spread[1].noise);
  CHECK(spread[0].noise < 0.9 * spread[2].noise);
}

// The small bright light of kTwoLights at the ray level, from floor points under it and beside it:
// each light sample's direction, traced as a BSDF ray is, meets the light at the sample's distance,
// with the sample's radiance and density (so MIS weighs the two alike); and rays drawn by cos / pi
// (a Lambert BSDF's) meet it as often and as bright as light sampling says, where 1 ray in 200 does.
TEST_CASE("MIS: BSDF rays and light samples see a small bright rect light alike", "[path][mis][lights]") {
  const LoadedScene s = rt::test::load_scene_text("two_lights.json", kTwoLights);
  const Scene& scene = s.scene;
  const RectLight& small = std::get<RectLight>(scene.lights[0]);
  const RectFrame frame(small);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  // From just above the floor, where a BSDF ray leaves it.
  const auto cast = [&](Vec3 point, Vec3 direction, SceneHit& met) {
    Ray ray;
    ray.origin = point;
    ray.direction = direction;
    scene.intersect(ray, met);
    return ray.tmax;
  };
  for (const Vec3 point : {Vec3(-1.475f, 1e-4f, -1.025f), Vec3(0.5f, 1e-4f, 0.5f), Vec3(-1.0f, 1e-4f, 1.5f)}) {
    int mismatches = 0;
    for (int i = 0; i < 10'000; ++i) {
      const LightSample ls = sample_li(small, frame, point, Vec2(uniform(rng), uniform(rng)));
      SceneHit met;
      const float t = cast(point, ls.direction, met);
      const bool alike = met.light == &small && std::abs(t - ls.distance) < 1e-3f * ls.distance &&
                         std::abs(small.lighting_radiance(t, frame.area).x - ls.radiance.x) < 1e-3f * ls.radiance.x &&
                         std::abs(pdf_li(frame, ls.direction, t) - ls.pdf) < 1e-3f * ls.pdf;
      mismatches += alike ? 0 : 1;
    }
    INFO("point " << point.x << ", " << point.z);
    CHECK(mismatches == 0);
  }
  // E[L cos / pdf] / pi, by rays drawn with pdf = cos / pi and by light samples.
  const Vec3 below(-1.475f, 1e-4f, -1.025f);
  constexpr int kRays = 4'000'000;
  double sum = 0.0, squares = 0.0;
  int met_light = 0;
  for (int i = 0; i < kRays; ++i) {
    const Vec3 d = cosine_hemisphere(Vec2(uniform(rng), uniform(rng)));
    SceneHit met;
    const float t = cast(below, Vec3(d.x, d.z, d.y), met);  // about +Y, the floor's normal
    if (met.light != &small) continue;
    const double l = small.lighting_radiance(t, frame.area).x;
    sum += l;
    squares += l * l;
    ++met_light;
  }
  const double bsdf = sum / kRays;
  const double bsdf_error = std::sqrt(std::max(0.0, squares / kRays - bsdf * bsdf) / kRays);
  constexpr int kSamples = 200'000;
  double by_light = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const LightSample ls = sample_li(small, frame, below, Vec2(uniform(rng), uniform(rng)));
    if (ls.pdf > 0.0f) by_light += ls.radiance.x * std::max(0.0f, ls.direction.y) / (ls.pdf * kPi) / kSamples;
  }
  INFO(met_light << " rays met the light; BSDF rays " << bsdf << " +- " << bsdf_error << ", light samples "
                 << by_light);
  CHECK(met_light > 10'000);
  CHECK(std::abs(bsdf - by_light) <= 4.0 * bsdf_error + 0.002 * by_light);
}

TEST_CASE("MIS: emissive shapes and CSG solids are light-sampled, every strategy agrees, MIS beats BSDF rays alone",
          "[path][mis]") {
  // A Lambert floor lit only by a small emissive sphere and an emissive CSG lens (two spheres
  // intersected): BSDF rays rarely find either, light sampling draws them (docs/rendering.md).
  const LoadedScene s = rt::test::load_scene_text("emissive_shapes.json", R"({
  "render": { "width": 16, "height": 12, "integrator": "path", "samples_per_pixel": 16, "max_depth": 1, "seed": 9 },
  "camera": { "position": [0, 2, 5], "look_at": [0, 0, 0], "fov": 50 },
  "background": [0, 0, 0],
  "materials": { "floor": { "kd": 0.5 }, "bulb": { "kd": 0, "emission": [40, 30, 20] } },
  "nodes": [
    { "shape": "plane", "material": "floor", "transform": { "scale": 4 } },
    { "shape": "sphere", "material": "bulb", "transform": { "translate": [-1, 1, 0], "scale": 0.15 } },
    { "csg": "intersection", "material": "bulb", "transform": { "translate": [1, 0.8, -0.5] }, "children": [
      { "shape": "sphere", "transform": { "translate": [0, 0, 0.15], "scale": 0.25 } },
      { "shape": "sphere", "transform": { "translate": [0, 0, -0.15], "scale": 0.25 } } ] } ]
})");
  REQUIRE(s.scene.emitters.size() == 3);
  RenderSettings reference_settings = s.settings;
  reference_settings.path.samples_per_pixel = 2048;
  const Image reference = render_image(s, reference_settings);
  // The floor's pixels only: those showing an emitter itself differ by where their samples fall.
  std::vector<size_t> floor;
  for (size_t p = 0; p < reference.pixels.size(); ++p)
    if (max_component(reference.pixels[p]) < 2.0f) floor.push_back(p);
  REQUIRE(floor.size() > reference.pixels.size() / 2);
  const auto floor_only = [&](const Image& image) {
    Image out;
    out.width = static_cast<int>(floor.size());
    out.height = 1;
    for (size_t p : floor) out.pixels.push_back(image.pixels[p]);
    return out;
  };
  const double ref_mean = image_stats(floor_only(reference)).mean;
  double error[3];
  const std::vector<Image> images = by_strategy(s, s.settings, 100);
  for (int k = 0; k < 3; ++k) error[k] = rmse(floor_only(images[k]), floor_only(reference));
  INFO("RMSE against 2048 spp: MIS " << error[0] << ", lights only " << error[1] << ", BSDF only " << error[2]);
  CHECK(error[0] < 0.5 * error[2]);
  for (int k = 1; k < 3; ++k) {
    RenderSettings settings = reference_settings;
    settings.path.strategy = kStrategies[k];
    settings.seed = 200;
    const double m = image_stats(floor_only(render_image(s, settings))).mean;
    INFO("strategy " << k << " at 2048 spp: mean " << m << " against MIS " << ref_mean);
    CHECK(m == Approx(ref_mean).epsilon(0.03));
  }
}
