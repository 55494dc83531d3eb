// The point lights' shadow rays of a camera packet, asked beforehand as packets
// (find_point_shadows, WhittedIntegrator::radiance_from_hits): each camera ray gets the radiance
// and the ray counts it would get alone, in scenes with occluders on both sides of the light's
// reach, with glass (rays the packet finds blocked traced again through it), and with more lights
// than are asked.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/render/direct_lighting.h"
#include "core/render/integrator.h"
#include "tests/support/loading.h"

using namespace rt;

namespace {

// A floor under a cube, a sphere and a cylinder; `lights` and the sphere's material (its
// definition) as given.
std::string shadow_scene(const std::string& lights, const std::string& sphere_material) {
  return R"({
    "render": {"width": 64, "height": 48, "max_depth": 3},
    "camera": {"position": [0, 3, 7], "look_at": [0, 0.5, 0], "fov": 50},
    "materials": {
      "matte": {"kd": [0.7, 0.7, 0.7]},
      "mirror": {"kd": 0.2, "reflectivity": 0.5},
      "ball": )" +
         sphere_material + R"(
    },
    "lights": [)" +
         lights + R"(],
    "nodes": [
      {"shape": "plane", "material": "matte", "transform": {"scale": [6, 1, 6]}},
      {"shape": "cube", "material": "mirror", "transform": {"translate": [-1.2, 0.5, 0], "scale": 0.5}},
      {"shape": "sphere", "material": "ball", "transform": {"translate": [1.2, 0.7, 0.5], "scale": 0.7}},
      {"shape": "cylinder", "material": "matte", "transform": {"translate": [0, 0.6, -1.5], "scale": [0.3, 0.6, 0.3]}}
    ]
  })";
}

const std::string kFourLights = R"(
  {"type": "point", "position": [3, 5, 3], "intensity": 0.8},
  {"type": "spot", "position": [-3, 4, 2], "direction": [0.6, -0.8, -0.3], "outer_angle": 40, "intensity": 0.6},
  {"type": "directional", "direction": [-0.3, -1, -0.4], "intensity": 0.3},
  {"type": "rect", "corner": [-0.5, 4, -0.5], "edge1": [1, 0, 0], "edge2": [0, 0, 1], "intensity": 0.4})";

const std::string kMatte = R"({"kd": [0.7, 0.7, 0.7]})";
const std::string kGlass = R"({"kd": 0, "ks": 0.5, "transmission": 1, "ior": 1.5})";

struct Compared {
  int rays = 0;          // camera rays that met a surface
  int lit = 0;           // point-light answers found lit beforehand
  int dark = 0;          // and found dark (blocked, or the light cannot reach)
  int known_lights = 0;  // the most lights known at one point
  int left = 0;          // point-light answers left to be traced as the point is shaded
};

// Every pixel's centre ray, in packets of neighbours along rows: radiance_from_hits against
// radiance_from_hit, exactly, and the same ray counts.
Compared compare_packets(const LoadedScene& s) {
  const auto whitted = make_integrator("whitted");
  const int w = s.settings.width, h = s.settings.height;
  Compared c;
  RayCounters alone, together;
  for (int y = 0; y < h; ++y) {
    for (int x0 = 0; x0 < w; x0 += kPacketSize) {
      const int count = std::min(kPacketSize, w - x0);
      Ray rays[kPacketSize];
      SceneHit met[kPacketSize];
      for (int i = 0; i < count; ++i)
        rays[i] = s.scene.camera.generate_ray(static_cast<float>(x0 + i) + 0.5f, static_cast<float>(y) + 0.5f, w, h);
      s.scene.intersect_packet(rays, met, count);
      std::vector<TraceContext> one, many;
      for (int i = 0; i < count; ++i) {
        const SampleStream numbers(1, 0, static_cast<uint64_t>(y * w + x0 + i), 0);
        one.push_back(TraceContext{s.scene, s.settings, alone, numbers});
        many.push_back(TraceContext{s.scene, s.settings, together, numbers});
      }
      TraceContext* ctx[kPacketSize];
      for (int i = 0; i < count; ++i) ctx[i] = &many[static_cast<size_t>(i)];
      Vec3 found[kPacketSize];
      whitted->radiance_from_hits(rays, met, count, ctx, found);
      for (int i = 0; i < count; ++i) {
        const Vec3 expected = whitted->radiance_from_hit(rays[i], met[i], 0, one[static_cast<size_t>(i)]);
        INFO("pixel " << x0 + i << ", " << y);
        REQUIRE(found[i].x == expected.x);
        REQUIRE(found[i].y == expected.y);
        REQUIRE(found[i].z == expected.z);
      }
      // What was known beforehand, from the surfaces' evaluation as the integrator makes it.
      EvaluatedSurface surfaces[kPacketSize];
      bool has[kPacketSize];
      for (int i = 0; i < count; ++i) {
        has[i] = met[i].surface;
        if (!has[i]) continue;
        ++c.rays;
        const SurfaceInteraction si = s.scene.surface(rays[i], met[i].hit);
        surfaces[i] = evaluate_surface(s.scene.materials()[si.material], si, rays[i].direction, s.scene.textures());
      }
      RayCounters unused;
      PointShadows known[kPacketSize];
      find_point_shadows(surfaces, has, count, s.scene, unused, known);
      for (int i = 0; i < count; ++i) {
        c.known_lights = std::max(c.known_lights, __builtin_popcount(known[i].known));
        c.lit += __builtin_popcount(known[i].lit);
        c.dark += __builtin_popcount(known[i].known & ~known[i].lit);
        if (has[i]) c.left += 3 - __builtin_popcount(known[i].known);
      }
    }
  }
  for (size_t k = 0; k < kRayKindCount; ++k) CHECK(together.count[k] == alone.count[k]);
  CHECK(together[RayKind::kShadow] > 0);
  return c;
}

}  // namespace

TEST_CASE("point shadows in packets: the radiance and ray counts of one ray at a time", "[lights][shadow]") {
  const LoadedScene s = rt::test::load_scene_text("point_packets.json", shadow_scene(kFourLights, kMatte));
  REQUIRE(s.scene.all_opaque);
  const Compared c = compare_packets(s);
  CHECK(c.rays > 1000);
  // Both answers occur, for the three point-like lights (the rect light is sampled as it is shaded).
  CHECK(c.lit > 1000);
  CHECK(c.dark > 500);
  CHECK(c.known_lights == 3);
  CHECK(c.left == 0);
}

TEST_CASE("point shadows in packets: with glass, blocked rays are traced again through it, the same radiance",
          "[lights][shadow]") {
  const LoadedScene s = rt::test::load_scene_text("point_packets_glass.json", shadow_scene(kFourLights, kGlass));
  REQUIRE_FALSE(s.scene.all_opaque);
  const Compared c = compare_packets(s);
  CHECK(c.rays > 1000);
  CHECK(c.known_lights == 3);
  CHECK(c.lit > 1000);
  CHECK(c.left > 100);
}

TEST_CASE("point shadows in packets: lights past the first eight are traced as they are shaded", "[lights][shadow]") {
  std::string lights;
  for (int i = 0; i < 10; ++i)
    lights += std::string(i ? "," : "") + R"({"type": "point", "position": [)" + std::to_string(i - 5) +
              R"(, 4, 2], "intensity": 0.1})";
  const LoadedScene s = rt::test::load_scene_text("point_packets_many.json", shadow_scene(lights, kMatte));
  const Compared c = compare_packets(s);
  CHECK(c.known_lights == static_cast<int>(PointShadows::kMaxLights));
  CHECK(c.dark > 0);
}
