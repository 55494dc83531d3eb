// The Blender fixture (tests/data/blender/fixture.glb, made by make_fixture.py beside it with
// tools/blender_export.py and Debian's blender 3.4): what Blender exported is recognised — its
// camera, its lights in our units, the area light and bump map from the script's extras, the
// materials by name, the animation — and a JSON scene can place it and replace its materials.
#include <algorithm>
#include <set>

#include <catch2/catch.hpp>

#include "io/gltf/loader.h"
#include "tests/support/gltf_import.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

std::string fixture() { return rt::test::source_path("tests/data/blender/fixture.glb"); }

template <class T>
std::vector<T> lights_of(const std::vector<Light>& lights) {
  std::vector<T> out;
  for (const Light& l : lights)
    if (const T* t = std::get_if<T>(&l)) out.push_back(*t);
  return out;
}

}  // namespace

TEST_CASE("Blender fixture: camera, lights and area-light extras in our units", "[blender][gltf]") {
  Diagnostics diags;
  const auto loaded = load_scene(fixture(), rt::test::load_options(), diags);
  for (const Diagnostic& d : diags.all()) UNSCOPED_INFO(format_diagnostic(d));
  REQUIRE(loaded);
  CHECK(diags.all().empty());  // no warnings: everything Blender wrote is understood
  const Scene& scene = loaded->scene;
  // Blender's camera at (0, -7, 3.5), Z up, is at (0, 3.5, 7) in glTF's Y-up space; 35 mm lens.
  CHECK(scene.camera.position.x == Approx(0.0f).margin(1e-5));
  CHECK(scene.camera.position.y == Approx(3.5f));
  CHECK(scene.camera.position.z == Approx(7.0f));
  CHECK(scene.camera.vertical_fov_degrees == Approx(0.5631969f * 180.0f / kPi).epsilon(1e-4));
  CHECK(scene.camera.forward.y < 0.0f);  // looking down at the models
  REQUIRE(scene.lights.size() == 3);

  // "Softbox": 2 x 1 m, 150 W, colour (1, 0.95, 0.9), 4 m up, facing down.
  const auto rects = lights_of<RectLight>(scene.lights);
  REQUIRE(rects.size() == 1);
  const RectLight& softbox = rects[0];
  CHECK(glm::length(softbox.edge1) == Approx(2.0f));
  CHECK(glm::length(softbox.edge2) == Approx(1.0f));
  const Vec3 centre = softbox.point(Vec2(0.5f));
  CHECK(centre.x == Approx(0.0f).margin(1e-5));
  CHECK(centre.y == Approx(4.0f));
  CHECK(centre.z == Approx(0.0f).margin(1e-5));
  CHECK(softbox.normal().y == Approx(-1.0f));
  // Its face's radiance P / (4 A) = 18.75, as Cycles'; its samples fall off from P / (4 pi)
  // = 11.937 head-on at 1 m: colour x attenuation(1), so that the face's radiance is its colour.
  CHECK(softbox.color.x == Approx(150.0f / (4.0f * 2.0f)));
  CHECK(softbox.color.y == Approx(0.95f * 150.0f / (4.0f * 2.0f)));
  CHECK(softbox.color.x * softbox.attenuation(1.0f) == Approx(150.0f / (4.0f * kPi)));
  CHECK(softbox.color.x * softbox.attenuation(2.0f) == Approx(150.0f / (4.0f * kPi) / 4.0f));
  CHECK(softbox.lighting_radiance(3.0f, 2.0f).x == Approx(softbox.color.x));
  CHECK_FALSE(softbox.two_sided);

  // "Lamp": 200 W point light, exported as 200 x 683 / 4 pi cd: colour P / (4 pi^2) = 5.066.
  const auto points = lights_of<PointLight>(scene.lights);
  REQUIRE(points.size() == 1);
  CHECK(points[0].color.x == Approx(200.0f / (4.0f * kPi * kPi)).epsilon(1e-4));
  CHECK(points[0].position.y == Approx(3.0f));  // Blender z = 3
  // "Sun": 3 W/m^2, exported as 2049 lux: colour 2049 / (683 pi) = 0.955.
  const auto suns = lights_of<DirectionalLight>(scene.lights);
  REQUIRE(suns.size() == 1);
  CHECK(suns[0].color.x == Approx(2049.0f / (683.0f * kPi)).epsilon(1e-4));
  CHECK(suns[0].direction.y < 0.0f);  // shining down
}

TEST_CASE("Blender fixture: materials, the bump map from extras and the animation", "[blender][gltf]") {
  rt::test::ImportProblems error;
  const auto model = import_gltf(fixture(), std::nullopt, LoadLimits{}, error);
  INFO(error.message);
  REQUIRE(model);
  REQUIRE(model->material_names == std::vector<std::string>{"Floor", "Red", "Glass"});
  const Material& floor = model->materials[0];
  const Material& red = model->materials[1];
  const Material& glass = model->materials[2];
  // The Bump node (Strength 0.5 x Distance 0.4) is a bump map from ridges.png beside the file;
  // the normalTexture Blender's exporter made of the same image is dropped.
  REQUIRE(floor.bump.height.present());
  CHECK(floor.bump.strength == Approx(0.2f));
  CHECK_FALSE(floor.normal_map.map.present());
  CHECK(model->textures[floor.bump.height.texture].width() == 32);
  CHECK(std::any_of(model->files.begin(), model->files.end(),
                    [](const std::string& f) { return f.find("ridges.png") != std::string::npos; }));
  CHECK(red.kd.x == Approx(0.8f));
  CHECK(red.pbr.roughness == Approx(0.4f));
  CHECK(glass.transmission == Vec3(1.0f));
  CHECK(glass.ior == Approx(1.45f));
  // "Box" turns 90 degrees about Blender's Z (glTF's Y) over frames 1-24, which Blender exports
  // at frame / fps: 1/24 to 1 s.
  REQUIRE(model->tracks.size() == 1);
  CHECK(model->animation_end == Approx(1.0f).epsilon(1e-4));
  Trs end;
  apply_track(model->tracks[0], model->animation_end, end);
  const Vec3 x = glm::mat3_cast(end.rotation) * Vec3(1, 0, 0);
  CHECK(x.x == Approx(0.0f).margin(1e-3));
  CHECK(x.z == Approx(-1.0f).epsilon(1e-3));  // +90 degrees about +Y takes +X to -Z
}

TEST_CASE("Blender fixture: a JSON scene makes the Blender material glass by name", "[blender][gltf][overrides]") {
  const LoadedScene loaded = rt::test::load_scene_text("blender-override.json", R"({
    "camera": {"position": [0, 3.5, 7], "look_at": [0, 0.5, 0]},
    "materials": {"diamond": {"kd": 0.05, "transmission": 0.95, "ior": 2.42},
                  "chrome": {"kd": 0.1, "ks": 0.9, "reflectivity": 0.9, "glossy": 0.05}},
    "nodes": [{"mesh": {"file": ")" + fixture() + R"(", "materials": {"Glass": "diamond", "Red": "chrome"}}}]})");
  std::set<uint32_t> used;
  for (const MeshInstance& i : loaded.scene.bvh.instances()) used.insert(i.material);
  CHECK(used.count(0) == 1);               // diamond
  CHECK(used.count(1) == 1);               // chrome
  CHECK(used.size() == 3);                 // and the file's own Floor
  CHECK(loaded.scene.lights.size() == 3);  // the scene has none of its own: the file's
}

TEST_CASE("Blender fixture: its meshes, each placed once, are flattened into the top level and hit by name",
          "[blender][gltf][flatten]") {
  Diagnostics diags;
  const auto loaded = load_scene(fixture(), rt::test::load_options(), diags);
  REQUIRE(loaded);
  const Scene& scene = loaded->scene;
  REQUIRE(scene.bvh.instances().size() == 3);
  for (const MeshInstance& i : scene.bvh.instances()) CHECK(i.flattened);
  CHECK(scene.bvh.triangle_count() == 2 + 12 + 960);  // the floor, the box, the ball
  CHECK(scene.bvh.check_structure().empty());
  // Straight down between the box and the ball: the floor, named as its placement, shaded by its
  // own mesh's record at y = 0.
  Ray down;
  down.origin = Vec3(0.0f, 3.0f, 0.0f);
  down.direction = Vec3(0.0f, -1.0f, 0.0f);
  Hit hit;
  REQUIRE(scene.intersect(down, hit));
  REQUIRE(scene.bvh.kind(hit.prim) == PrimitiveKind::kInstance);
  CHECK(hit.part < 2);
  CHECK(scene.materials()[scene.material_of(hit)].bump.height.present());  // the Floor's
  CHECK(hit.t == Approx(3.0f));
  CHECK(scene.surface(down, hit).position.y == Approx(0.0f).margin(1e-5));
}
