// Reflection, refraction and glossy reflection, in scenes small enough to reason about.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "core/render/shadow_transmittance.h"
#include "io/image/rgb8_image.h"
#include "io/scene_loader.h"
#include "materials/evaluated_surface.h"
#include "materials/optics.h"
#include "tests/support/geometry.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;
using rt::test::check_vec;

namespace {

// One refraction exactly as the Whitted integrator makes it: closest hit, evaluated surface,
// Snell at the shading normal, origin offset to the far side. n1 -> n2 across the surface.
Ray refract_at_hit(const Scene& scene, const Ray& ray, float n1, float n2) {
  Ray r = ray;
  Hit hit;
  REQUIRE(scene.intersect(r, hit));
  const EvaluatedSurface s =
      evaluate_surface(scene.materials()[scene.material_of(hit)], scene.surface(r, hit), r.direction, scene.textures());
  Ray out;
  REQUIRE(refract(glm::normalize(r.direction), s.n, n1 / n2, out.direction));
  out.origin = offset_ray_origin(s.position, s.position_error, s.ng, out.direction);
  return out;
}

const char* kGlass = R"("glass": { "kd": 0, "transmission": 1, "ior": 1.5 })";

}  // namespace

TEST_CASE("a ray through a glass slab leaves parallel, offset sideways by h sin(i - t) / cos t", "[refraction]") {
  // The cube scaled to a slab 1 thick (z in [-0.5, 0.5]) and wide.
  const LoadedScene s = rt::test::load_scene_text(
      "slab.json",
      std::string(R"({ "camera": { "position": [0, 0, 9], "look_at": [0, 0, 0] }, "materials": {)") + kGlass + R"(},
    "nodes": [ { "shape": "cube", "material": "glass", "transform": { "scale": [20, 20, 0.5] } } ] })");
  const double incidence = 30.0 * kPi / 180.0;
  Ray in;
  in.origin = Vec3(0, 0, 3);
  in.direction = Vec3(static_cast<float>(std::sin(incidence)), 0, -static_cast<float>(std::cos(incidence)));
  const Ray inside = refract_at_hit(s.scene, in, 1.0f, 1.5f);
  const Ray out = refract_at_hit(s.scene, inside, 1.5f, 1.0f);
  check_vec(out.direction, in.direction, 1e-6);
  // Lateral offset: distance between the incoming line and the outgoing one.
  const double transmitted = std::asin(std::sin(incidence) / 1.5);
  const double expected = 1.0 * std::sin(incidence - transmitted) / std::cos(transmitted);
  const Vec3 between = out.origin - in.origin;
  const float offset = glm::length(between - glm::dot(between, in.direction) * in.direction);
  CHECK(offset == Approx(expected).epsilon(1e-3));
  CHECK(expected == Approx(0.193814).epsilon(1e-4));  // i = 30, t = 19.47 degrees
}

TEST_CASE("a ray through a glass sphere's centre is not bent", "[refraction]") {
  const LoadedScene s = rt::test::load_scene_text(
      "ball.json",
      std::string(R"({ "camera": { "position": [0, 0, 9], "look_at": [0, 0, 0] }, "materials": {)") + kGlass + R"(},
    "nodes": [ { "shape": "sphere", "material": "glass", "transform": { "translate": [1, 2, 3], "scale": 0.7 } } ] })");
  Ray in;
  in.origin = Vec3(1, 2, 3) + Vec3(3, 4, 12) / 13.0f * 5.0f;
  in.direction = -Vec3(3, 4, 12) / 13.0f;
  const Ray inside = refract_at_hit(s.scene, in, 1.0f, 1.5f);
  check_vec(inside.direction, in.direction, 1e-5);
  const Ray out = refract_at_hit(s.scene, inside, 1.5f, 1.0f);
  check_vec(out.direction, in.direction, 1e-5);
  check_vec(out.origin, Vec3(1, 2, 3) - 0.7f * Vec3(3, 4, 12) / 13.0f, 1e-3);
}

namespace {

// A lit checkered backdrop and floor, plus whatever `extra` adds to the nodes.
std::string backdrop_scene(const std::string& extra_materials, const std::string& extra_nodes) {
  return R"({
    "render": { "width": 64, "height": 48, "max_depth": 5 },
    "camera": { "position": [0, 1, 6], "look_at": [0, 0.8, 0], "fov": 40 },
    "background": [0.2, 0.3, 0.4], "ambient": 0.1,
    "materials": { "a": { "kd": [0.9, 0.8, 0.2] }, "b": { "kd": [0.1, 0.2, 0.7] } )" +
         extra_materials + R"( },
    "lights": [ { "type": "point", "position": [-2, 5, 4] } ],
    "nodes": [
      { "shape": "plane", "material": "a", "transform": { "scale": 6 } },
      { "shape": "plane", "material": "b", "transform": { "translate": [-1, 1.5, -2], "rotate": [90, 0, 0] } },
      { "shape": "plane", "material": "b", "transform": { "translate": [1.2, 0.4, -1.9], "rotate": [90, 0, 0], "scale": 0.5 } },
      { "shape": "cube", "material": "b", "transform": { "translate": [1.5, 0.3, 0], "scale": 0.3 } } )" +
         extra_nodes + "] }";
}

Image render_image(const LoadedScene& s, RenderSettings settings, RenderStats* stats = nullptr) {
  Image image;
  const RenderStats st = render(s.scene, settings, image);
  if (stats) *stats = st;
  return image;
}

}  // namespace

TEST_CASE("ior 1 with transmission 1 and no absorption leaves the image behind unchanged", "[refraction]") {
  const LoadedScene without = rt::test::load_scene_text("no_ball.json", backdrop_scene("", ""));
  const LoadedScene with = rt::test::load_scene_text(
      "clear_ball.json",
      backdrop_scene(
          R"(, "clear": { "kd": 0, "transmission": 1, "ior": 1 })",
          R"(, { "shape": "sphere", "material": "clear", "transform": { "translate": [0, 0.8, 1], "scale": 0.8 } })"));
  RenderStats stats;
  const Rgb8Image a = encode_srgb8(render_image(without, without.settings));
  const Rgb8Image b = encode_srgb8(render_image(with, with.settings, &stats));
  CHECK(stats.rays[RayKind::kRefraction] > 500);  // the sphere was there and was crossed
  int max_diff = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) max_diff = std::max(max_diff, std::abs(a.rgb[i] - b.rgb[i]));
  CHECK(max_diff <= 1);  // float rounding of the straight-through ray only
}

TEST_CASE("max_depth bounds the rays traced between two facing mirrors", "[reflection]") {
  const LoadedScene s = rt::test::load_scene_text("mirrors.json", R"({
    "render": { "width": 1, "height": 1, "antialias": { "mode": "none" } },
    "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 10 },
    "materials": { "mirror": { "kd": 0, "reflectivity": 1 } },
    "lights": [ { "type": "point", "position": [0, 0.5, 0] } ],
    "nodes": [
      { "shape": "plane", "material": "mirror", "transform": { "translate": [0, 0, -2], "rotate": [90, 0, 0], "scale": 10 } },
      { "shape": "plane", "material": "mirror", "transform": { "translate": [0, 0, 2], "rotate": [-90, 0, 0], "scale": 10 } } ] })");
  for (const int depth : {0, 1, 5, 64}) {
    RenderSettings settings = s.settings;
    settings.max_depth = depth;
    RenderStats stats;
    render_image(s, settings, &stats);
    INFO("max_depth " << depth);
    CHECK(stats.rays[RayKind::kCamera] == 1);
    CHECK(stats.rays[RayKind::kReflection] == static_cast<uint64_t>(depth));
    CHECK(stats.rays[RayKind::kRefraction] == 0);
  }
}

namespace {

std::string glossy_scene(const std::string& glossy_key) {
  return backdrop_scene(
      R"(, "shiny": { "kd": 0.05, "reflectivity": 0.9)" + glossy_key + " }",
      R"(, { "shape": "sphere", "material": "shiny", "transform": { "translate": [0, 0.8, 1], "scale": 0.8 } })");
}

}  // namespace

TEST_CASE("glossy width 0 is the mirror image bit for bit, --no-glossy too", "[glossy]") {
  const LoadedScene mirror = rt::test::load_scene_text("mirror_ball.json", glossy_scene(""));
  const LoadedScene zero = rt::test::load_scene_text("zero_width.json", glossy_scene(R"(, "glossy": 0)"));
  const LoadedScene wide = rt::test::load_scene_text("wide.json", glossy_scene(R"(, "glossy": 0.3)"));
  const Image reference = render_image(mirror, mirror.settings);
  CHECK(render_image(zero, zero.settings).pixels == reference.pixels);
  RenderSettings off = wide.settings;
  off.glossy = false;
  CHECK(render_image(wide, off).pixels == reference.pixels);
  RenderStats stats;
  CHECK(render_image(wide, wide.settings, &stats).pixels != reference.pixels);
  CHECK(stats.rays[RayKind::kGlossy] > 1000);
}

TEST_CASE("no glossy ray goes below the surface", "[glossy]") {
  // A very blurry mirror floor seen at a grazing angle, black sky above. Below the floor a red
  // box lit from below: any glossy ray that went under the surface would bring red back.
  const auto scene = [](float box_y) {
    return R"({
      "render": { "width": 48, "height": 32, "max_depth": 2, "glossy_samples": 16 },
      "camera": { "position": [0, 0.4, 6], "look_at": [0, 0, 0], "fov": 50 },
      "materials": { "blurry": { "kd": 0, "reflectivity": 1, "glossy": 3 }, "red": { "kd": [1, 0, 0] } },
      "lights": [ { "type": "point", "position": [0, -0.2, 0] }, { "type": "point", "position": [0, 1, 0] } ],
      "nodes": [
        { "shape": "plane", "material": "blurry", "transform": { "scale": 50 } },
        { "shape": "cube", "material": "red", "transform": { "translate": [0, )" +
           std::to_string(box_y) + R"(, 0], "scale": [40, 0.5, 40] } } ] })";
  };
  const LoadedScene below = rt::test::load_scene_text("glossy_below.json", scene(-1.0f));
  RenderStats stats;
  const Image image = render_image(below, below.settings, &stats);
  CHECK(stats.rays[RayKind::kGlossy] > 5000);
  float red = 0.0f;
  for (const Vec3& p : image.pixels) red = std::max(red, p.x);
  CHECK(red == 0.0f);
  // The same box above the floor is seen in it: the test can tell.
  const LoadedScene above = rt::test::load_scene_text("glossy_above.json", scene(2.0f));
  red = 0.0f;
  for (const Vec3& p : render_image(above, above.settings).pixels) red = std::max(red, p.x);
  CHECK(red > 0.05f);
}

TEST_CASE("a clear glass sphere's shadow is lighter than an opaque one's, and tinted glass tints it",
          "[refraction][shadow]") {
  // The camera looks straight down at the centre of the sphere's shadow on the floor.
  const auto scene = [](const std::string& material) {
    return R"({
      "render": { "width": 5, "height": 5 },
      "camera": { "position": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 2 },
      "materials": { "floor": { "kd": 0.8 }, "ball": )" +
           material + R"( },
      "lights": [ { "type": "point", "position": [3, 5, 0] } ],
      "nodes": [
        { "shape": "plane", "material": "floor", "transform": { "scale": 20 } },
        { "shape": "sphere", "material": "ball", "transform": { "translate": [1.2, 2, 0], "scale": 0.5 } } ] })";
  };
  const auto centre = [&](const std::string& name, const std::string& material) {
    const LoadedScene s = rt::test::load_scene_text(name, scene(material));
    return render_image(s, s.settings).at(2, 2);
  };
  const Vec3 opaque = centre("opaque.json", R"({ "kd": 0.5 })");
  const Vec3 glass = centre("glass.json", R"({ "kd": 0, "transmission": 1, "ior": 1.5 })");
  const Vec3 green = centre("green.json", R"({ "kd": 0, "transmission": 1, "ior": 1.5, "absorption": [2, 0.1, 2] })");
  const Vec3 lit = centre("none.json", R"({ "kd": 0.5, "transmission": 1, "ior": 1 })");  // invisible ball
  CHECK(opaque.x == 0.0f);
  CHECK(glass.x > 0.5f * lit.x);
  CHECK(glass.x < lit.x);  // Fresnel losses at two interfaces: (1 - 0.04)^2 at the centre
  CHECK(glass.x == Approx(lit.x * 0.96f * 0.96f).epsilon(0.01));
  CHECK(green.y > 2.0f * green.x);                                    // the path inside absorbs red and blue
  CHECK(green.x == Approx(glass.x * std::exp(-2.0f)).epsilon(0.02));  // 1 unit of glass on the axis
}

TEST_CASE("nested glass: an inner object of the same index inside glass is no interface at all", "[refraction]") {
  // The medium stack's rule: inside glass (1.5), a second sphere of index 1.5 is entered from 1.5
  // and left back into 1.5, so it neither bends nor reflects; treated as glass in air, it would
  // bend the checks behind it. Lit by ambient light only, so no shadow ray is involved.
  const auto scene = [](bool inner) {
    return std::string(R"({
      "render": { "width": 64, "height": 48, "max_depth": 8 },
      "camera": { "position": [0, 0, 6], "look_at": [0, 0, 0], "fov": 30 },
      "ambient": 1,
      "materials": { "a": { "kd": [0.9, 0.8, 0.2] }, "b": { "kd": [0.1, 0.2, 0.7] },
                     "glass": { "kd": 0, "transmission": 1, "ior": 1.5 },
                     "same index": { "kd": 0, "transmission": 1, "ior": 1.5 } },
      "nodes": [
        { "shape": "plane", "material": "a", "transform": { "translate": [0, 0, -3], "rotate": [90, 0, 0], "scale": 5 } },
        { "shape": "cube", "material": "b", "transform": { "translate": [-0.5, 0.3, -2.8], "scale": [0.2, 2, 0.1] } },
        { "shape": "cube", "material": "b", "transform": { "translate": [0.4, -0.2, -2.8], "scale": [2, 0.15, 0.1] } },
        { "shape": "sphere", "material": "glass", "transform": { "scale": 1.2 } })") +
           (inner
                ? R"(, { "shape": "sphere", "material": "same index", "transform": { "translate": [0.2, 0.1, 0.3], "scale": 0.6 } })"
                : "") +
           "] }";
  };
  const LoadedScene plain = rt::test::load_scene_text("nested_plain.json", scene(false));
  const LoadedScene nested = rt::test::load_scene_text("nested_inner.json", scene(true));
  RenderStats a, b;
  const Rgb8Image without = encode_srgb8(render_image(plain, plain.settings, &a));
  const Rgb8Image with = encode_srgb8(render_image(nested, nested.settings, &b));
  CHECK(b.rays[RayKind::kRefraction] > a.rays[RayKind::kRefraction] + 500);  // the inner sphere was crossed
  int max_diff = 0;
  for (size_t i = 0; i < without.rgb.size(); ++i) max_diff = std::max(max_diff, std::abs(without.rgb[i] - with.rgb[i]));
  CHECK(max_diff <= 2);
}

TEST_CASE("a ray that escapes inside an absorbing medium keeps its non-absorbed channels", "[refraction]") {
  // A single transmissive plane is an open surface: the ray enters its medium and never leaves,
  // travelling forever. Red is absorbed (to 0); green and blue, which the medium does not absorb,
  // arrive whole, never exp(-0 * infinity) = NaN.
  const LoadedScene s = rt::test::load_scene_text("open_medium.json", R"({
    "render": { "width": 3, "height": 3 },
    "camera": { "position": [0, 5, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 5 },
    "background": 0.5,
    "materials": { "tinted": { "kd": 0, "transmission": 1, "ior": 1, "absorption": [1, 0, 0] } },
    "nodes": [ { "shape": "plane", "material": "tinted", "transform": { "scale": 10 } } ] })");
  const Vec3 centre = render_image(s, s.settings).at(1, 1);
  CHECK(centre.x == 0.0f);
  CHECK(centre.y == Approx(0.5f));
  CHECK(centre.z == Approx(0.5f));
}

TEST_CASE("a glass sphere's shadow is light all over: each surface filters by transmission x (1 - F0)",
          "[refraction][shadow]") {
  // Unbent shadow rays through a clear sphere (n = 1.5) at growing distances from its centre. Near
  // the rim the unbent ray would leave beyond the critical angle (sin > 1 / 1.5): Fresnel at that
  // angle made it total internal reflection, a black outer ring. Each crossing now passes
  // 1 - F0 = 1 - 0.04, whatever the angle: 0.9216 for the two.
  const LoadedScene s = rt::test::load_scene_text("glass_filter.json", R"({
    "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
    "materials": { "glass": { "kd": 0, "transmission": 1, "ior": 1.5 },
                   "amber": { "kd": 0, "transmission": [1, 0.5, 0.25], "ior": 1.5 } },
    "nodes": [ { "shape": "sphere", "material": "glass" },
               { "shape": "sphere", "material": "amber", "transform": { "translate": [0, 5, 0] } } ] })");
  for (const float x : {0.0f, 0.5f, 0.8f, 0.95f, 0.999f}) {
    INFO("x " << x);
    const Vec3 t = shadow_transmittance(s.scene, Ray(Vec3(x, 0.0f, -5.0f), Vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f));
    CHECK(t.x == Approx(0.9216f));
    CHECK(t.y == Approx(0.9216f));
  }
  // Tinted glass filters each channel by its transmission, at each surface.
  const Vec3 amber = shadow_transmittance(s.scene, Ray(Vec3(0.9f, 5.0f, -5.0f), Vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f));
  CHECK(amber.x == Approx(0.9216f));
  CHECK(amber.y == Approx(0.9216f * 0.25f));
  CHECK(amber.z == Approx(0.9216f * 0.0625f));
}

TEST_CASE("glass below a glossy split follows one branch: glossy_samples x depth rays, not x 2^depth",
          "[glossy][refraction]") {
  // A glossy mirror floor whose 8 rays per camera ray all meet a glass slab hanging over it; the
  // glass would fork each into reflection and refraction at every surface, 2^depth rays each.
  const LoadedScene s = rt::test::load_scene_text("glossy_over_glass.json", R"({
  "render": { "width": 4, "height": 4, "max_depth": 8, "glossy_samples": 8, "shadow_samples": 1,
              "antialias": { "mode": "none" } },
  "camera": { "position": [0, 0.5, 0], "look_at": [0, 0, -0.3], "fov": 10 },
  "background": [0.5, 0.6, 0.7],
  "materials": { "floor": { "kd": 0, "ks": 0, "reflectivity": 1, "glossy": 0.05 },
                 "glass": { "kd": 0, "transmission": 1, "ior": 1.5 } },
  "nodes": [ { "shape": "plane", "material": "floor", "transform": { "scale": 50 } },
             { "shape": "cube", "material": "glass", "transform": { "translate": [0, 3, 0], "scale": [50, 0.5, 50] } } ]
})");
  Image image;
  const RenderStats stats = render(s.scene, s.settings, image);
  // 16 camera rays, 8 glossy rays each, then at most one ray a bounce for the 7 bounces left:
  // 16 x 8 x 8 in all. (Both branches at every glass surface took 1136 here: 256 reflected, 896
  // refracted, 384 glossy.)
  const uint64_t secondary =
      stats.rays[RayKind::kGlossy] + stats.rays[RayKind::kReflection] + stats.rays[RayKind::kRefraction];
  CHECK(secondary <= 16 * 8 * 8);
  CHECK(stats.rays[RayKind::kRefraction] > 16 * 8);  // the rays do go through the glass
}
