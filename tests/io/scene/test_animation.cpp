// The scene format's "animation": parsing, node resolution, the degrees rule, errors; and the
// per-frame placement (top-level BVH only) against a full load of the same frame.
#include <catch2/catch.hpp>

#include "core/frame_scenes.h"

#include "core/render/renderer.h"
#include "tests/support/loading.h"

using namespace rt;

namespace {

std::string spinner_scene(const std::string& frames, const std::string& tracks) {
  return R"({
  "render": { "width": 48, "height": 36, "max_depth": 3, "seed": 3 },
  "camera": { "position": [0, 2, 6], "look_at": [0, 0.5, 0], "fov": 40 },
  "materials": { "m": { "kd": [0.7, 0.3, 0.2], "ks": 0.3 }, "glass": { "kd": 0, "transmission": 0.9, "ior": 1.5 } },
  "lights": [ { "type": "point", "position": [3, 5, 4] } ],
  "nodes": [
    { "name": "floor", "shape": "plane", "material": "m", "transform": { "scale": 5 } },
    { "name": "spinner", "transform": { "translate": [0, 0.8, 0] }, "children": [
      { "name": "box", "shape": "cube", "material": "m", "transform": { "translate": [1.2, 0, 0], "scale": 0.4 } },
      { "name": "knot", "mesh": { "file": ")" +
         rt::test::source_path("scenes/models/knot.glb") + R"(" }, "material": "glass", "transform": { "scale": 0.5 } }
    ] },
    { "name": "fixed", "shape": "sphere", "material": "m", "transform": { "matrix": [[0.3,0,0,-1.5],[0,0.3,0,0.3],[0,0,0.3,1],[0,0,0,1]] } }
  ],
  "animation": { "fps": 30, )" +
         frames + R"("tracks": [ )" + tracks + R"( ] }
})";
}

const std::string kTurn = R"({ "node": "spinner", "property": "rotate",
  "keys": [ { "frame": 0, "value": { "axis": [0, 1, 0], "degrees": 0 } }, { "frame": 120, "value": { "axis": [0, 1, 0], "degrees": 360 } } ] })";

// Where the box's centre is at `frame`.
Vec3 box_centre(const LoadedScene& s, int frame) {
  const std::vector<Mat4> w = s.graph.pose_at(s.graph.timeline.seconds(frame)).world;
  for (size_t i = 0; i < s.graph.nodes.size(); ++i)
    if (s.graph.nodes[i].name == "box") return Vec3(w[i] * Vec4(0, 0, 0, 1));
  FAIL("no box");
  return Vec3(0.0f);
}

std::vector<std::string> load_errors(const std::string& name, const std::string& json) {
  Diagnostics diags;
  CHECK_FALSE(load_scene(rt::test::write_file(name, json), rt::test::load_options(), diags));
  std::vector<std::string> out;
  for (const Diagnostic& d : diags.all())
    if (d.severity == Severity::kError) out.push_back(d.pointer + ": " + d.message);
  return out;
}

}  // namespace

TEST_CASE("animation scene: a 0 to 360 degree track turns a full circle, 3 degrees a frame", "[animation][io]") {
  const LoadedScene s = rt::test::load_scene_text("anim_turn.json", spinner_scene(R"("frames": [0, 119], )", kTurn));
  CHECK(s.graph.animated);
  CHECK(s.graph.timeline.first_frame == 0);
  CHECK(s.graph.timeline.last_frame == 119);
  CHECK(s.graph.timeline.fps == 30.0f);
  // The box starts at x = 1.2; a turn about Y by a takes it to (1.2 cos a, 0.8, -1.2 sin a).
  for (const int frame : {0, 10, 30, 60, 90, 119, 120}) {
    const float a = glm::radians(3.0f * static_cast<float>(frame));
    const Vec3 c = box_centre(s, frame);
    INFO("frame " << frame);
    CHECK(c.x == Approx(1.2f * std::cos(a)).margin(1e-4));
    CHECK(c.z == Approx(-1.2f * std::sin(a)).margin(1e-4));
    CHECK(c.y == Approx(0.8f));
  }
  CHECK(box_centre(s, 200).x == Approx(1.2f).margin(1e-4));  // after the last key the last value holds
}

TEST_CASE("animation scene: key forms, step interpolation and the default frame range", "[animation][io]") {
  const std::string tracks = R"({ "node": "box", "property": "translate", "interpolation": "step",
      "keys": [ { "frame": 0, "value": [1, 0, 0] }, { "frame": 15, "value": [2, 0, 0] } ] },
    { "node": "box", "property": "scale", "keys": [ { "frame": 0, "value": 0.4 }, { "frame": 30, "value": [0.8, 0.4, 0.4] } ] },
    { "node": "knot", "property": "rotate", "keys": [ { "frame": 0, "value": [0, 0, 0] }, { "frame": 45, "value": { "quaternion": [0, 0, 0.7071068, 0.7071068] } } ] })";
  const LoadedScene s = rt::test::load_scene_text("anim_forms.json", spinner_scene("", tracks));
  CHECK(s.graph.timeline.first_frame == 0);
  CHECK(s.graph.timeline.last_frame == 45);  // the last key's frame
  CHECK(box_centre(s, 14).x == Approx(1.0f));
  CHECK(box_centre(s, 15).x == Approx(2.0f));
  const std::vector<Mat4> w = s.graph.pose_at(s.graph.timeline.seconds(15)).world;
  for (size_t i = 0; i < s.graph.nodes.size(); ++i)
    if (s.graph.nodes[i].name == "box") CHECK(glm::length(Vec3(w[i][0])) == Approx(0.6f));  // halfway 0.4 -> 0.8
}

TEST_CASE("animation scene: errors name the track, the node and what was expected", "[animation][io]") {
  auto errors = load_errors("anim_bad_node.json", spinner_scene("", R"({ "node": "spiner", "property": "rotate",
      "keys": [ { "frame": 0, "value": [0, 0, 0] } ] })"));
  REQUIRE(errors.size() == 1);
  CHECK_THAT(errors[0], Catch::Contains("/animation/tracks/0/node") && Catch::Contains("did you mean \"spinner\""));

  errors = load_errors("anim_matrix.json", spinner_scene("", R"({ "node": "fixed", "property": "translate",
      "keys": [ { "frame": 0, "value": [0, 0, 0] } ] })"));
  REQUIRE(errors.size() == 1);
  CHECK_THAT(errors[0], Catch::Contains("placed by a matrix"));

  errors = load_errors("anim_order.json", spinner_scene("", R"({ "node": "box", "property": "translate",
      "keys": [ { "frame": 5, "value": [0, 0, 0] }, { "frame": 5, "value": [1, 0, 0] } ] })"));
  REQUIRE(errors.size() == 1);
  CHECK_THAT(errors[0], Catch::Contains("/animation/tracks/0/keys/1/frame") && Catch::Contains("increasing order"));

  errors = load_errors("anim_frames.json", spinner_scene(R"("frames": [10, 2], )", kTurn));
  REQUIRE(errors.size() == 1);
  CHECK_THAT(errors[0], Catch::Contains("/animation/frames") && Catch::Contains("first <= last"));

  errors = load_errors("anim_rotation.json", spinner_scene("", R"({ "node": "box", "property": "rotate",
      "keys": [ { "frame": 0, "value": { "axis": [0, 0, 0], "degrees": 3 } } ] })"));
  REQUIRE(errors.size() == 1);
  CHECK_THAT(errors[0], Catch::Contains("non-zero length"));
}

TEST_CASE("animation scene: a frame placed on the loaded meshes renders as a full load of that frame",
          "[animation][io]") {
  // Loading with frames [40, 40] builds frame 40 from scratch (files, mesh BVHs, top level);
  // graph.at() from a load of frame 0 rebuilds only the top level over the same meshes.
  const LoadedScene from_zero =
      rt::test::load_scene_text("anim_zero.json", spinner_scene(R"("frames": [0, 119], )", kTurn));
  const LoadedScene full =
      rt::test::load_scene_text("anim_forty.json", spinner_scene(R"("frames": [40, 40], )", kTurn));
  const float t = from_zero.graph.timeline.seconds(40);
  const Scene placed = from_zero.graph.at(from_zero.graph.pose_at(t), BvhBuildOptions{1});
  CHECK(placed.assets == from_zero.scene.assets);  // shared, not copied
  CHECK(placed.bvh.instances().size() == from_zero.scene.bvh.instances().size());
  Image a, b, first;
  render(placed, from_zero.settings, a, {}, 40);
  render(full.scene, full.settings, b, {}, 40);
  render(from_zero.scene, from_zero.settings, first, {}, 40);
  REQUIRE(a.pixels.size() == b.pixels.size());
  CHECK(a.pixels == b.pixels);
  CHECK(a.pixels != first.pixels);  // and the frame did move
}

TEST_CASE("animation scene: the loader builds the frame asked for first, and FrameScenes walks the rest",
          "[animation][io]") {
  // `render --frames 40-41` loads with options.frame = 40: the scene built at load is frame 40,
  // the timeline's first frame (0) is never placed into a Scene, and the next frame is posed
  // from the same graph.
  LoadOptions options = rt::test::load_options();
  options.frame = 40;
  Diagnostics diags;
  const auto at_forty = load_scene(
      rt::test::write_file("anim_ask_forty.json", spinner_scene(R"("frames": [0, 119], )", kTurn)), options, diags);
  REQUIRE(at_forty);
  CHECK(at_forty->frame == 40);
  CHECK(at_forty->graph.timeline.first_frame == 0);
  const LoadedScene full =
      rt::test::load_scene_text("anim_forty_again.json", spinner_scene(R"("frames": [40, 40], )", kTurn));
  Image asked, whole;
  render(at_forty->scene, at_forty->settings, asked, {}, 40);
  render(full.scene, full.settings, whole, {}, 40);
  CHECK(asked.pixels == whole.pixels);

  FrameScenes scenes(at_forty->graph, at_forty->frame, at_forty->scene, BvhBuildOptions{1});
  CHECK(&scenes.at(40) == &at_forty->scene);  // kept, not built again
  CHECK(scenes.placing_seconds() == 0.0);
  Image next;
  render(scenes.at(41), at_forty->settings, next, {}, 41);
  CHECK(scenes.placing_seconds() > 0.0);
  CHECK(next.pixels != asked.pixels);
}
