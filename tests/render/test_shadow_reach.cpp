// Shadow rays to a rect light asked only of the leaves their point's shadow volume reaches
// (direct_lighting, Bvh::leaves_meeting): in a scene with glass, plain and CSG, each ray's
// transmittance is exactly the whole walk's, with points that reach no leaf (a floor and a wall
// away from everything), one, and more.
#include <string>

#include <catch2/catch.hpp>

#include "core/accel/shadow_volume.h"
#include "core/render/direct_lighting.h"
#include "core/render/shadow_transmittance.h"
#include "tests/support/loading.h"

using namespace rt;

TEST_CASE("shadow rays asked of the leaves their volume reaches see the glass the whole walk sees",
          "[lights][shadow]") {
  const LoadedScene s = rt::test::load_scene_text("shadow_reach.json", R"({
    "render": {"width": 48, "height": 36},
    "camera": {"position": [0, 2.5, 7], "look_at": [0, 0.6, 0], "fov": 55},
    "materials": {
      "matte": {"kd": 0.7},
      "glass": {"kd": 0, "ks": 0.5, "transmission": [1, 0.8, 0.5], "ior": 1.5},
      "smoke": {"kd": 0, "transmission": 1, "ior": 1.2, "absorption": [0.5, 0.2, 0.1]}
    },
    "lights": [{"type": "rect", "corner": [-1, 4, -2.5], "edge1": [2, 0, 0], "edge2": [0, 0, 1.5]}],
    "nodes": [
      {"shape": "plane", "material": "matte", "transform": {"scale": [6, 1, 6]}},
      {"shape": "plane", "material": "matte", "transform": {"translate": [0, 2, -3], "rotate": [90, 0, 0], "scale": [6, 1, 2]}},
      {"shape": "sphere", "material": "glass", "transform": {"translate": [-1, 0.8, 0.5], "scale": 0.8}},
      {"shape": "cube", "material": "matte", "transform": {"translate": [0.6, 0.5, 0.2], "scale": 0.5}},
      {"csg": "difference", "material": "smoke", "transform": {"translate": [1, 1.2, 1.2]},
       "children": [{"shape": "sphere", "transform": {"scale": 0.6}}, {"shape": "cube", "transform": {"translate": [0, 0.5, 0], "scale": 0.4}}]}
    ]
  })");
  REQUIRE_FALSE(s.scene.all_opaque);
  const RectLight& light = std::get<RectLight>(s.scene.lights[0]);
  int sets[3] = {0, 0, 0}, through_glass = 0, blocked = 0, lit = 0;
  const int w = s.settings.width, h = s.settings.height;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      Ray ray = s.scene.camera.generate_ray(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, w, h);
      Hit hit;
      if (!s.scene.intersect(ray, hit)) continue;
      const SurfaceInteraction si = s.scene.surface(ray, hit);
      const EvaluatedSurface e =
          evaluate_surface(s.scene.materials()[si.material], si, ray.direction, s.scene.textures());
      const Vec3 origin = shadow_ray_origin(e, e.ng);
      BvhLeafSet leaves;
      if (!s.scene.bvh.leaves_meeting(ShadowVolume(origin, light.corner, light.edge1, light.edge2), leaves)) continue;
      ++sets[std::min(leaves.count, 2)];
      for (int j = 0; j < 16; ++j) {
        const Vec3 to =
            light.point(Vec2((static_cast<float>(j % 4) + 0.37f) / 4.0f, (static_cast<float>(j / 4) + 0.61f) / 4.0f)) -
            origin;
        if (glm::dot(e.ng, to) <= 0.0f) continue;  // behind the surface: no shadow ray (ShadowRays::make)
        const float distance = glm::length(to);
        const Ray shadow(origin, to / distance, 0.0f, distance * (1.0f - kShadowEpsilon));
        const Vec3 walked = shadow_transmittance(s.scene, shadow);
        const Vec3 asked = shadow_transmittance(s.scene, shadow, &leaves);
        INFO("pixel " << x << ", " << y << ", sample " << j);
        REQUIRE(asked.x == walked.x);
        REQUIRE(asked.y == walked.y);
        REQUIRE(asked.z == walked.z);
        if (max_component(walked) <= 0.0f) ++blocked;
        else if (walked.x < 1.0f || walked.z < 1.0f) ++through_glass;
        else ++lit;
      }
    }
  }
  INFO("points reaching no leaf, one, more: " << sets[0] << ", " << sets[1] << ", " << sets[2]);
  CHECK(sets[0] > 300);  // the floor and the wall away from everything
  CHECK(sets[1] > 50);
  CHECK(sets[2] > 30);
  CHECK(through_glass > 500);
  CHECK(blocked > 100);
  CHECK(lit > 5000);
}
