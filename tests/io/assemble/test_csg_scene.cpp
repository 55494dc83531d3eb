// CSG from scene files: operands leave the node list for the solid, shapes take the CSG node's
// material, a closed glTF mesh is an operand, tracks move operands, and glass CSG lets shadow rays
// through as glass does.
#include <catch2/catch.hpp>

#include "core/render/shadow_transmittance.h"
#include "io/scene_loader.h"
#include "materials/optics.h"
#include "tests/support/geometry.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;
using rt::test::make_ray;

namespace {

std::string scene_with(const std::string& nodes, const std::string& extra = "") {
  return R"({"camera": {"position": [0, 0, 6], "look_at": [0, 0, 0]},
    "materials": {"red": {"kd": [0.8, 0.1, 0.1]}, "blue": {"kd": [0.1, 0.1, 0.8]},
                  "glass": {"kd": 0, "transmission": 1, "ior": 1.5}},
    "lights": [{"type": "point", "position": [0, 5, 5]}],
    "nodes": )" +
         nodes + extra + "}";
}

}  // namespace

TEST_CASE("CSG scenes: operands become one solid, and shapes take the CSG node's material", "[csg][io]") {
  const LoadedScene s = rt::test::load_scene_text("csg-material.json", scene_with(R"([
    {"name": "floor", "shape": "cube", "material": "blue", "transform": {"translate": [0, -3, 0]}},
    {"csg": "difference", "material": "red", "children": [
      {"shape": "sphere"},
      {"shape": "cube", "material": "blue", "transform": {"translate": [0, 0, 1], "scale": 0.5}}]}])"));
  const Bvh& bvh = s.scene.bvh;
  CHECK(bvh.shapes().size() == 1);  // the floor: the operands are not also drawn on their own
  REQUIRE(bvh.csgs().size() == 1);
  const CsgObject& csg = bvh.csgs()[0];
  REQUIRE(csg.surfaces().size() == 2);
  const auto red = [&](uint32_t material) { return s.scene.materials()[material].kd.x > 0.5f; };
  CHECK(red(csg.surface(0).material()));        // from the CSG node
  CHECK_FALSE(red(csg.surface(1).material()));  // blue, its own
  // Straight down the z axis: into the cube-shaped bite, whose floor (the cube's back face at
  // z = 0.5) is blue and faces the camera.
  Ray r = make_ray({0, 0, 6}, {0, 0, -1});
  Hit h;
  REQUIRE(s.scene.intersect(r, h));
  CHECK(h.t == Approx(5.5f));
  CHECK_FALSE(red(s.scene.material_of(h)));
  CHECK(s.scene.surface(r, h).geometric_normal.z == Approx(1.0f));
}

TEST_CASE("CSG scenes: a closed glTF mesh is an operand", "[csg][io]") {
  const std::string box = rt::test::source_path("tests/data/bad/models/closed-box.gltf");
  const LoadedScene s = rt::test::load_scene_text("csg-mesh.json", scene_with(R"([
    {"csg": "intersection", "material": "red", "children": [
      {"mesh": {"file": ")" + box + R"("}, "transform": {"scale": 0.8}},
      {"shape": "sphere"}]}])"));
  CHECK(s.scene.bvh.instances().empty());
  REQUIRE(s.scene.bvh.csgs().size() == 1);
  // Along z the box (half size 0.8) bounds it; along the diagonal the sphere does.
  Ray r = make_ray({0, 0, 6}, {0, 0, -1});
  Hit h;
  REQUIRE(s.scene.intersect(r, h));
  CHECK(h.t == Approx(5.2f).epsilon(1e-5));
  Ray d = make_ray(Vec3(4), glm::normalize(Vec3(-1)));
  REQUIRE(s.scene.intersect(d, h));
  CHECK(glm::length(d.at(h.t)) == Approx(1.0f).epsilon(1e-5));
}

TEST_CASE("CSG scenes: a track on an operand moves it within the solid", "[csg][io][animation]") {
  const LoadedScene s = rt::test::load_scene_text("csg-track.json", scene_with(R"([
    {"csg": "difference", "material": "red", "children": [
      {"shape": "sphere"},
      {"name": "cutter", "shape": "sphere", "transform": {"translate": [0, 0, 3], "scale": 0.5}}]}])",
                                                                               R"(, "animation": {"fps": 1,
      "tracks": [{"node": "cutter", "property": "translate",
                  "keys": [{"frame": 0, "value": [0, 0, 3]}, {"frame": 1, "value": [0, 0, 1]}]}]})"));
  for (const int frame : {0, 1}) {
    const Scene scene = s.graph.at(s.graph.pose(frame), BvhBuildOptions{});
    Ray r = make_ray({0, 0, 6}, {0, 0, -1});
    Hit h;
    REQUIRE(scene.intersect(r, h));
    // Frame 0: the cutter is away, the sphere's front at z = 1; frame 1: a bite down to z = 0.5.
    CHECK(r.at(h.t).z == Approx(frame == 0 ? 1.0f : 0.5f).epsilon(1e-5));
  }
}

TEST_CASE("CSG scenes: shadow rays pass a glass lens as they pass glass, one factor per boundary", "[csg][io]") {
  const LoadedScene s = rt::test::load_scene_text("csg-lens.json", scene_with(R"([
    {"csg": "intersection", "material": "glass", "children": [
      {"shape": "sphere", "transform": {"translate": [0, 0, -1.5], "scale": 2}},
      {"shape": "sphere", "transform": {"translate": [0, 0, 1.5], "scale": 2}}]}])"));
  // Glass of ior 1.5 passes 1 - F0 = 0.96 at each of the lens's two boundaries (not four).
  Ray through = make_ray({0, 0, 5}, {0, 0, -1});
  through.tmax = 10.0f;
  const Vec3 t = shadow_transmittance(s.scene, through);
  CHECK(t.x == Approx(0.96f * 0.96f).epsilon(1e-4));
  Ray beside = make_ray({2, 0, 5}, {0, 0, -1});
  beside.tmax = 10.0f;
  CHECK(shadow_transmittance(s.scene, beside).x == Approx(1.0f));
}

TEST_CASE("CSG scenes: a lens made of two spheres focuses parallel light where the thick-lens formula says",
          "[csg][io][refraction]") {
  // Radius 2.5 spheres 4.4 apart: a biconvex lens 0.6 thick, ior 1.5. Thick-lens formula:
  // 1/f = (n-1) (1/R1 - 1/R2 + (n-1) d / (n R1 R2)) = 0.384, f = 2.6042; back focal length
  // f (1 - (n-1) d / (n R1)) = 2.3958 beyond the back vertex at z = -0.3.
  const LoadedScene s = rt::test::load_scene_text("csg-focus.json", scene_with(R"([
    {"csg": "intersection", "material": "glass", "children": [
      {"shape": "sphere", "transform": {"translate": [0, 0, -2.2], "scale": 2.5}},
      {"shape": "sphere", "transform": {"translate": [0, 0, 2.2], "scale": 2.5}}]}])"));
  const float n = 1.5f;
  for (const float h : {0.005f, 0.01f}) {
    Ray r = make_ray({h, 0, 5}, {0, 0, -1});
    Hit in;
    REQUIRE(s.scene.intersect(r, in));
    SurfaceInteraction a = s.scene.surface(r, in);
    REQUIRE(a.front_face);
    Vec3 inside(0.0f);
    REQUIRE(refract(r.direction, a.geometric_normal, 1.0f / n, inside));
    Ray through = make_ray(offset_ray_origin(a.position, a.position_error, a.geometric_normal, inside), inside);
    Hit out;
    REQUIRE(s.scene.intersect(through, out));
    const SurfaceInteraction b = s.scene.surface(through, out);
    REQUIRE_FALSE(b.front_face);  // leaving, its normal turned to face out of the lens
    Vec3 beyond(0.0f);
    REQUIRE(refract(through.direction, -b.geometric_normal, n, beyond));
    // Where the ray crosses the axis.
    const float t_axis = -b.position.x / beyond.x;
    const Vec3 focus = b.position + t_axis * beyond;
    CHECK(focus.z == Approx(-0.3f - 2.3958f).epsilon(2e-3));
  }
}

TEST_CASE("CSG scenes: a cut surface refracts into the solid's medium, not the cutter's", "[csg][io][refraction]") {
  const LoadedScene s = rt::test::load_scene_text("csg-medium.json", scene_with(R"([
    {"csg": "difference", "material": "glass", "children": [
      {"shape": "sphere"},
      {"shape": "sphere", "material": "red", "transform": {"translate": [0, 0, 1], "scale": 0.5}}]}])"));
  Ray r = make_ray({0, 0, 6}, {0, 0, -1});
  Hit h;
  REQUIRE(s.scene.intersect(r, h));
  const SurfaceInteraction si = s.scene.surface(r, h);
  CHECK(si.position.z == Approx(0.5f));  // the bite's floor, on the cutter
  const auto kd = [&](uint32_t m) { return s.scene.materials()[m].kd.x; };
  CHECK(kd(si.material) == Approx(0.8f));                                // shaded with the cutter's material (red)
  CHECK(s.scene.materials()[si.medium].transmission.x == Approx(1.0f));  // behind it: the glass
}
