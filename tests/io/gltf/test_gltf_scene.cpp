// glTF files as whole scenes: node trees, animation channels, cameras and KHR_lights_punctual.
#include <catch2/catch.hpp>

#include "io/gltf/lights.h"
#include "io/gltf/loader.h"
#include "tests/support/gltf_files.h"
#include "tests/support/gltf_import.h"
#include "tests/support/loading.h"
#include "tests/support/run_rtcli.h"

using namespace rt;

namespace {

Json lit_square() {
  Json doc = {
      {"scenes", {{{"nodes", {0, 1, 2}}}}},
      {"nodes",
       {{{"mesh", 0}},
        {{"name", "lamp"}, {"translation", {0, 0, 2}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
        {{"name", "eye"}, {"translation", {0.5, 0.5, 4}}, {"camera", 0}}}},
      {"cameras", {{{"name", "view"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}}},
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"extensions",
       {{"KHR_lights_punctual",
         {{"lights",
           {{{"type", "spot"},
             {"intensity", 683.0 * M_PI},
             {"color", {1, 0.5, 0.25}},
             {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}}}}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"mode", 6}}}}}}},
      {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 48}}}}};
  return doc;
}

}  // namespace

TEST_CASE("glTF lights: photometric units converted by the documented rule", "[gltf][lights]") {
  std::string why;
  // 683 pi candela of white light: colour 1, falling off as 1 / d^2.
  auto light = light_from_gltf("point", {1, 1, 1}, 683.0 * M_PI, 0, 0, why);
  REQUIRE(light);
  const LightSample at2 = sample_li(*light, Vec3(0, 0, -2), Vec2(0.5f));
  CHECK(at2.radiance.x == Approx(0.25f));
  // A Blender 1000 W point light exported as 1000 * 683 / (4 pi) cd, 5 m away: 1000 / (4 pi 25) / pi = 1.0132.
  light = light_from_gltf("point", {1, 1, 1}, 1000.0 * 683.0 / (4 * M_PI), 0, 0, why);
  CHECK(sample_li(*light, Vec3(5, 0, 0), Vec2(0.5f)).radiance.y == Approx(1000.0 / (4 * M_PI * 25) / M_PI));
  // 10 lux of sunlight straight down: 10 / (683 pi) = 0.00466 everywhere.
  light = light_from_gltf("directional", {}, 10.0, 0, 0, why);
  REQUIRE(light);
  const LightSample sun = sample_li(*light, Vec3(100, -3, 7), Vec2(0.5f));
  CHECK(sun.radiance.z == Approx(10.0 / (683.0 * M_PI)));
  CHECK(sun.direction.z == Approx(1.0f));  // towards the light: the node's +Z, the light shines down -Z
  CHECK(std::isinf(sun.distance));
  // Spot: full inside the inner cone, none outside the outer, t^2 between.
  light = light_from_gltf("spot", {1, 1, 1}, 683.0 * M_PI, 0.2, 0.6, why);
  REQUIRE(light);
  const auto at_angle = [&](double a) {
    return sample_li(*light, Vec3(std::sin(a), 0, -std::cos(a)), Vec2(0.5f)).radiance.x;
  };
  CHECK(at_angle(0.1) == Approx(1.0f));
  CHECK(at_angle(0.7) == 0.0f);
  const double t = (std::cos(0.4) - std::cos(0.6)) / (std::cos(0.2) - std::cos(0.6));
  CHECK(at_angle(0.4) == Approx(t * t));
  CHECK_FALSE(light_from_gltf("area", {}, 1.0, 0, 0, why));
  CHECK_THAT(why, Catch::Contains("\"area\""));
  CHECK_FALSE(light_from_gltf("point", {}, -1.0, 0, 0, why));
}

TEST_CASE("glTF scene: a file's own camera and lights are used, on their nodes", "[gltf][lights]") {
  const std::string path = rt::test::write_gltf("lit_square.gltf", rt::test::square_positions(), lit_square());
  Diagnostics diags;
  const auto loaded = load_scene(path, rt::test::load_options(), diags);
  for (const Diagnostic& d : diags.all()) UNSCOPED_INFO(format_diagnostic(d));
  REQUIRE(loaded);
  const Scene& s = loaded->scene;
  CHECK(s.camera.position == Vec3(0.5f, 0.5f, 4.0f));
  CHECK(s.camera.forward.z == Approx(-1.0f));
  CHECK(s.camera.vertical_fov_degrees == Approx(glm::degrees(0.5f)));
  REQUIRE(s.lights.size() == 1);  // the file's spot light, not the default light
  const auto* spot = std::get_if<SpotLight>(&s.lights[0]);
  REQUIRE(spot);
  CHECK(spot->position.z == Approx(2.0f));
  CHECK(spot->color.y == Approx(0.5f));

  auto r = rt::test::rtcli("render '" + path + "' --camera nope -o '" + rt::test::output_path("nope.png") + "'");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--camera: expected the name of a camera") && Catch::Contains("\"view\""));
  r = rt::test::rtcli("render '" + path + "' --camera eye --width 32 --height 24 -o '" +
                      rt::test::output_path("eye.png") + "'");
  CHECK(r.code == 0);
  // --camera on a model on its own looks through that camera, not the framing one.
  LoadOptions eye = rt::test::load_options();
  eye.camera = "eye";
  const auto through = load_scene(path, eye, diags);
  REQUIRE(through);
  CHECK(through->scene.camera.position == Vec3(0.5f, 0.5f, 4.0f));
}

TEST_CASE("glTF scene: the light rtcli adds to a model stands beside the camera in use", "[gltf][lights]") {
  if (!rt::test::have_sample_models()) return;
  Diagnostics diags;
  const auto loaded = load_scene(rt::test::sample_model("Cameras/glTF/Cameras.gltf"), rt::test::load_options(), diags);
  REQUIRE(loaded);
  REQUIRE(loaded->scene.lights.size() == 1);
  const Camera& c = loaded->scene.camera;
  CHECK(c.position.z == Approx(3.0f));  // the file's first camera
  const Vec3 offset = std::get<PointLight>(loaded->scene.lights[0]).position - c.position;
  CHECK(std::fabs(glm::dot(offset, c.forward)) < 1e-3f * glm::length(offset));  // up and to the right of it
  CHECK(glm::dot(offset, c.right) > 0.0f);
  CHECK(glm::dot(offset, c.up) > 0.0f);
}

TEST_CASE("glTF samples: node trees, animation channels and cameras", "[gltf][animation]") {
  if (!rt::test::have_sample_models()) {
    WARN("../shared/gltf not found: sample-model tests skipped");
    return;
  }
  rt::test::ImportProblems error;
  auto m =
      import_gltf(rt::test::sample_model("BoxAnimated/glTF-Binary/BoxAnimated.glb"), std::nullopt, LoadLimits{}, error);
  REQUIRE(m);
  CHECK(m->nodes.size() == 4);
  const auto imported = [&](int gltf_index) {
    for (size_t i = 0; i < m->nodes.size(); ++i)
      if (m->nodes[i].gltf_index == gltf_index) return static_cast<int32_t>(i);
    return -1;
  };
  CHECK(m->nodes[static_cast<size_t>(imported(1))].parent == imported(0));  // node 0's child, found by the walk
  const auto moved = static_cast<size_t>(imported(0));
  REQUIRE(m->tracks.size() == 2);
  CHECK(m->animation_end == Approx(3.70833f));

  Diagnostics diags;
  auto loaded =
      load_scene(rt::test::sample_model("BoxAnimated/glTF-Binary/BoxAnimated.glb"), rt::test::load_options(), diags);
  REQUIRE(loaded);
  CHECK(loaded->graph.animated);
  CHECK(loaded->graph.timeline.fps == 24.0f);      // a model on its own: Blender's rate unless --fps
  CHECK(loaded->graph.timeline.last_frame == 89);  // ceil(3.708 s * 24 fps)
  const std::vector<Mat4> at0 = loaded->graph.pose_at(0.0f).world, at1 = loaded->graph.pose_at(1.0f).world;
  // The file hangs under the one node the loader makes for it: its nodes start at graph index 1.
  CHECK(at0[moved + 1][3] != at1[moved + 1][3]);  // the translated node moved

  loaded = load_scene(rt::test::sample_model("AnimatedCube/glTF/AnimatedCube.gltf"), rt::test::load_options(), diags);
  REQUIRE(loaded);
  // One rotation channel, keys at 0, 1, 2 s: at 0.5 s between the first two keys.
  REQUIRE(loaded->graph.tracks.size() == 1);
  CHECK(loaded->graph.tracks[0].part == TrsPart::kRotation);
  CHECK(loaded->graph.timeline.last_frame == 48);
  LoadOptions at30 = rt::test::load_options();
  at30.fps = 30.0f;  // --fps 30
  loaded = load_scene(rt::test::sample_model("AnimatedCube/glTF/AnimatedCube.gltf"), at30, diags);
  REQUIRE(loaded);
  CHECK(loaded->graph.timeline.last_frame == 60);

  loaded = load_scene(rt::test::sample_model("Cameras/glTF/Cameras.gltf"), rt::test::load_options(), diags);
  REQUIRE(loaded);
  CHECK(loaded->scene.camera.vertical_fov_degrees == Approx(glm::degrees(0.7f)));
  CHECK(loaded->scene.camera.position.z == Approx(3.0f));
}

TEST_CASE("glTF EXT_mesh_gpu_instancing: one mesh placed once per row, in its node's space", "[gltf][instancing]") {
  std::string buffer = rt::test::square_positions();                      // view 0: 48 bytes
  rt::test::append<float>(buffer, {0, 0, 0, 2, 0, 0, 4, 0, 0});           // view 1: TRANSLATION, 36 bytes
  rt::test::append<float>(buffer, {1, 1, 1, 1, 1, 1, 0.5f, 0.5f, 0.5f});  // view 2: SCALE, 36 bytes
  const Json doc = {
      {"scenes", {{{"nodes", {0}}}}},
      {"extensionsUsed", {"EXT_mesh_gpu_instancing"}},
      {"nodes",
       {{{"mesh", 0},
         {"translation", {0, 1, 0}},
         {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", 1}, {"SCALE", 2}}}}}}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"mode", 6}}}}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 36}},
        {{"buffer", 0}, {"byteOffset", 84}, {"byteLength", 36}}}}};
  const std::string gltf = rt::test::write_gltf("instanced.gltf", buffer, doc);
  const LoadedScene loaded =
      rt::test::load_scene_text("instanced.json", R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
                            "nodes": [{"mesh": {"file": ")" +
                                                      gltf + R"("}}]})");
  CHECK(loaded.scene.bvh.instances().size() == 3);  // one mesh stored, placed three times
  CHECK(loaded.scene.assets->meshes.size() == 1);
  // Placed three times: stored and walked once, not flattened (core/flatten_instances.h).
  for (const MeshInstance& i : loaded.scene.bvh.instances()) CHECK_FALSE(i.flattened);
  const auto hits = [&](float x, float y) {
    Ray r;
    r.origin = Vec3(x, y, 5);
    r.direction = Vec3(0, 0, -1);
    Hit hit;
    return loaded.scene.intersect(r, hit);
  };
  CHECK(hits(0.5f, 1.5f));    // copy 0 at the node: (0..1, 1..2)
  CHECK(hits(2.5f, 1.5f));    // copy 1 moved by 2 in x
  CHECK(hits(4.25f, 1.25f));  // copy 2 moved by 4 and halved: (4..4.5, 1..1.5)
  CHECK_FALSE(hits(4.75f, 1.75f));
  CHECK_FALSE(hits(1.5f, 1.5f));  // between copies
}

TEST_CASE("JSON scenes: a glTF file's materials replaced by name, its nodes animated by name", "[gltf][overrides]") {
  const std::string gem = rt::test::source_path("scenes/models/gem.gltf");
  const LoadedScene loaded = rt::test::load_scene_text("override-by-name.json", R"({
    "camera": {"position": [0, 0, 6], "look_at": [0, 0, 0]},
    "materials": {"glass": {"kd": 0.1, "transmission": 0.9, "ior": 1.5}, "red": {"kd": [0.8, 0.1, 0.1]}},
    "nodes": [{"name": "left", "transform": {"translate": [-2, 0, 0]},
               "mesh": {"file": ")" + gem + R"(", "materials": {"emerald": "glass"}}},
              {"name": "right", "transform": {"translate": [2, 0, 0]}, "mesh": {"file": ")" +
                                                                                    gem + R"("}}],
    "animation": {"fps": 10, "frames": [0, 10],
                  "tracks": [{"node": "gem", "property": "translate",
                              "keys": [{"frame": 0, "value": [0, 0, 0]}, {"frame": 10, "value": [0, 3, 0]}]}]}})");
  const Scene& scene = loaded.scene;
  REQUIRE(scene.bvh.instances().size() == 2);
  // The first placement uses the scene's glass (material 0); the second keeps the file's emerald.
  const MeshInstance& left =
      scene.bvh.instances()[0].bounds.centre().x < 0 ? scene.bvh.instances()[0] : scene.bvh.instances()[1];
  const MeshInstance& right = &left == &scene.bvh.instances()[0] ? scene.bvh.instances()[1] : scene.bvh.instances()[0];
  CHECK(left.material == 0);
  CHECK(right.material >= 2);
  CHECK(scene.materials()[left.material].transmissive());
  CHECK_FALSE(scene.materials()[right.material].transmissive());
  // The track names the node inside the file: both placements of the file move.
  const Scene later = loaded.graph.at(loaded.graph.pose_at(1.0f), BvhBuildOptions{});
  for (const MeshInstance& i : later.bvh.instances()) {
    const MeshInstance& before = i.bounds.centre().x < 0 ? left : right;
    CHECK(i.bounds.centre().y - before.bounds.centre().y == Approx(3.0f).epsilon(1e-4));
  }
}

namespace {

// Two squares, each moved by its own animation ("Left" moves node 0 up, "Right" node 1 down),
// over 2 s and 4 s.
std::string two_animations() {
  std::string buffer = rt::test::square_positions();     // view 0: 48 bytes
  rt::test::append<float>(buffer, {0, 2});               // view 1: times, 8 bytes
  rt::test::append<float>(buffer, {0, 0, 0, 0, 2, 0});   // view 2: translations up, 24 bytes
  rt::test::append<float>(buffer, {0, 4});               // view 3: times, 8 bytes
  rt::test::append<float>(buffer, {3, 0, 0, 3, -2, 0});  // view 4: translations down, 24 bytes
  const auto channel = [](int node) {
    return Json{{"channels", {{{"sampler", 0}, {"target", {{"node", node}, {"path", "translation"}}}}}}};
  };
  Json left = channel(0), right = channel(1);
  left["name"] = "Left";
  left["samplers"] = {{{"input", 1}, {"output", 2}}};
  right["name"] = "Right";
  right["samplers"] = {{{"input", 3}, {"output", 4}}};
  const Json doc = {
      {"scenes", {{{"nodes", {0, 1}}}}},
      {"nodes", {{{"mesh", 0}}, {{"mesh", 0}, {"translation", {3, 0, 0}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"mode", 6}}}}}}},
      {"animations", {left, right}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"}, {"min", {0}}, {"max", {2}}},
        {{"bufferView", 2}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}},
        {{"bufferView", 3}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"}, {"min", {0}}, {"max", {4}}},
        {{"bufferView", 4}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 8}},
        {{"buffer", 0}, {"byteOffset", 56}, {"byteLength", 24}},
        {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 8}},
        {{"buffer", 0}, {"byteOffset", 88}, {"byteLength", 24}}}}};
  return rt::test::write_gltf("two-animations.gltf", buffer, doc);
}

}  // namespace

TEST_CASE("glTF animations: all play together, --animation or \"animation\" picks one", "[gltf][animation]") {
  const std::string path = two_animations();
  Diagnostics diags;
  auto all = load_scene(path, rt::test::load_options(), diags);
  for (const Diagnostic& d : diags.all()) UNSCOPED_INFO(format_diagnostic(d));
  REQUIRE(all);
  CHECK(all->graph.tracks.size() == 2);
  CHECK(all->graph.timeline.last_frame == 96);  // the longer one, 4 s at 24 fps
  // Node 0 (graph node 1) moved up at 2 s, node 1 (graph node 2) down at 4 s.
  const std::vector<Mat4> end = all->graph.pose_at(4.0f).world;
  CHECK(end[1][3].y == Approx(2.0f));
  CHECK(end[2][3].y == Approx(-2.0f));
  // The default camera frames the whole animation: both squares at their highest and lowest.
  const Camera& camera = all->scene.camera;
  for (const Vec3 corner : {Vec3(0, 3, 0), Vec3(4, -2, 0), Vec3(0, 0, 0), Vec3(4, 1, 0)}) {
    const Vec3 d = glm::normalize(corner - camera.position);
    const float up = glm::dot(d, camera.up) / glm::dot(d, camera.forward);
    CHECK(std::fabs(up) <= std::tan(glm::radians(camera.vertical_fov_degrees / 2)) + 1e-4f);
  }

  for (const std::string which : {"Right", "1"}) {
    LoadOptions options = rt::test::load_options();
    options.animation = which;
    auto one = load_scene(path, options, diags);
    REQUIRE(one);
    REQUIRE(one->graph.tracks.size() == 1);
    CHECK(one->graph.timeline.last_frame == 96);
    CHECK(one->graph.pose_at(4.0f).world[1][3].y == Approx(0.0f));  // "Left" does not play
  }
  LoadOptions unknown = rt::test::load_options();
  unknown.animation = "Middle";
  Diagnostics said;
  CHECK_FALSE(load_scene(path, unknown, said));
  REQUIRE(said.has_errors());
  CHECK_THAT(said.all().front().message,
             Catch::Contains("--animation: expected the name or index of an animation in") &&
                 Catch::Contains("(its animations are \"Left\" (0), \"Right\" (1)), found \"Middle\""));

  // A scene file picks one with the glTF reference's "animation".
  const LoadedScene left = rt::test::load_scene_text("pick-animation.json", R"({
    "camera": {"position": [0, 0, 9], "look_at": [0, 0, 0]},
    "nodes": [{"mesh": {"file": ")" + path + R"(", "animation": "Left"}}]})");
  REQUIRE(left.graph.tracks.size() == 1);
  CHECK(left.graph.timeline.last_frame == 60);  // 2 s at a scene file's 30 fps
}

TEST_CASE("a model on its own: adaptive anti-aliasing, no ambient, Blender's world, both overridable",
          "[gltf][defaults]") {
  const std::string path = rt::test::write_gltf("lit_square_defaults.gltf", rt::test::square_positions(), lit_square());
  Diagnostics diags;
  const auto model = load_scene(path, rt::test::load_options(), diags);
  REQUIRE(model);
  CHECK(model->settings.antialias.mode == "adaptive");  // as a scene file without "antialias"
  CHECK(model->scene.ambient == Vec3(0.0f));
  CHECK(model->scene.background.color() == Vec3(kModelBackground));
  CHECK(rt::test::load_scene_text("no_aa_block.json", R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "materials": {"m": {"kd": 0.5}}, "nodes": [{"shape": "sphere", "material": "m"}]})")
            .settings.antialias.mode == "adaptive");
  // --ambient and --background replace either, for a model or a scene file.
  LoadOptions options = rt::test::load_options();
  options.ambient = std::array<float, 3>{0.1f, 0.2f, 0.3f};
  options.background = std::array<float, 3>{0.5f, 0.5f, 0.5f};
  const auto lifted = load_scene(path, options, diags);
  REQUIRE(lifted);
  CHECK(lifted->scene.ambient == Vec3(0.1f, 0.2f, 0.3f));
  CHECK(lifted->scene.background.color() == Vec3(0.5f));
  const auto scene = load_scene(rt::test::source_path("scenes/default.json"), options, diags);
  REQUIRE(scene);
  CHECK(scene->scene.ambient == Vec3(0.1f, 0.2f, 0.3f));

  auto r = rt::test::rtcli("render '" + path + "' --background 0.2,0.3 -o x.png");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("expected a linear RGB colour, R,G,B or one number"));
  r = rt::test::rtcli("render scenes/default.json --fps 30 -o x.png");
  CHECK(r.code == 2);
  CHECK_THAT(r.output, Catch::Contains("--fps applies to a glTF file rendered on its own"));
  r = rt::test::rtcli("render '" + path + "' --ambient 0.1 --background 0.4 --width 16 --height 12 -o '" +
                      rt::test::output_path("lifted.png") + "'");
  CHECK(r.code == 0);
}

TEST_CASE("glTF doubleSided false: rays pass through the back, shadows still fall", "[gltf][materials]") {
  // The unit square in z = 0, counter-clockwise seen from +z: its front faces +z.
  const auto square_with = [](const std::string& name, bool double_sided) {
    Json doc = lit_square();
    doc["materials"] = {{{"doubleSided", double_sided}}};
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    return rt::test::write_gltf(name, rt::test::square_positions(), doc);
  };
  const auto scene = [](const std::string& name, const std::string& gltf, const std::string& scale) {
    return rt::test::load_scene_text(name, R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "nodes": [{"mesh": {"file": ")" + gltf +
                                               R"("}, "transform": {"scale": )" + scale + "}}]}");
  };
  const auto hits = [](const Scene& s, float z, float dz) {
    Ray r{Vec3(0.5f, 0.5f, z), Vec3(0.0f, 0.0f, dz)};
    Hit hit;
    return s.intersect(r, hit);
  };
  const LoadedScene single = scene("single.json", square_with("single-sided.gltf", false), "1");
  CHECK(hits(single.scene, 5.0f, -1.0f));        // from the front: there
  CHECK_FALSE(hits(single.scene, -5.0f, 1.0f));  // from behind: camera and secondary rays pass
  CHECK(single.scene.occluded(Ray{Vec3(0.5f, 0.5f, -5.0f), Vec3(0.0f, 0.0f, 1.0f)}));  // shadows fall
  // Mirrored (a negative scale), the front still faces +z: glTF turns the winding with the determinant.
  const LoadedScene mirrored = scene("mirrored.json", square_with("single-sided-m.gltf", false), "[-1, 1, 1]");
  const auto hits_at = [](const Scene& s, float z, float dz) {
    Ray r{Vec3(-0.5f, 0.5f, z), Vec3(0.0f, 0.0f, dz)};
    Hit hit;
    return s.intersect(r, hit);
  };
  CHECK(hits_at(mirrored.scene, 5.0f, -1.0f));
  CHECK_FALSE(hits_at(mirrored.scene, -5.0f, 1.0f));
  // Double-sided: there from both sides.
  const LoadedScene both = scene("double.json", square_with("double-sided.gltf", true), "1");
  CHECK(hits(both.scene, 5.0f, -1.0f));
  CHECK(hits(both.scene, -5.0f, 1.0f));
}
