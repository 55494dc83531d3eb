// glTF import: the Khronos sample models (../shared/gltf) and small synthetic files for what the
// samples do not cover (sparse accessors, byte indices, strips and fans, normalised UVs, broken
// buffers).
#include <cstring>
#include <filesystem>
#include <set>

#include <catch2/catch.hpp>

#include "io/gltf/loader.h"
#include "io/json/document.h"
#include "io/scene_loader.h"
#include "tests/support/gltf_files.h"
#include "tests/support/gltf_import.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;
using rt::test::append;
using rt::test::square_positions;
using rt::test::write_gltf;

namespace {

size_t triangle_count(const ImportedModel& m) {
  size_t n = 0;
  for (const ModelPlacement& inst : placements(m))
    for (const ImportedPrimitive& p : m.meshes[inst.mesh]) n += p.mesh.triangle_count();
  return n;
}

std::optional<ImportedModel> import(const std::string& path, rt::test::ImportProblems& error,
                                    std::optional<std::string> mesh = {}) {
  return import_gltf(path, mesh, LoadLimits{}, error);
}

}  // namespace

TEST_CASE("glTF samples: Box in all three containers gives the same 12 triangles", "[io][gltf]") {
  if (!rt::test::have_sample_models()) {
    WARN("../shared/gltf not found: sample-model tests skipped");
    return;
  }
  std::vector<Vec3> reference;
  for (const char* path : {"Box/glTF-Binary/Box.glb", "Box/glTF/Box.gltf", "Box/glTF-Embedded/Box.gltf"}) {
    rt::test::ImportProblems error;
    const auto model = import(rt::test::sample_model(path), error);
    INFO(path << ": " << error.message);
    REQUIRE(model);
    REQUIRE(triangle_count(*model) == 12);
    REQUIRE(model->materials.size() == 1);
    const TriangleMesh& mesh = model->meshes[placements(*model)[0].mesh][0].mesh;
    CHECK(mesh.normals.size() == mesh.positions.size());
    if (reference.empty()) reference = mesh.positions;
    else CHECK(mesh.positions == reference);
  }
}

TEST_CASE("glTF samples: interleaved buffers, instancing, UVs, node hierarchies, PBR factors", "[io][gltf]") {
  if (!rt::test::have_sample_models()) {
    WARN("../shared/gltf not found: sample-model tests skipped");
    return;
  }
  rt::test::ImportProblems error;
  auto m = import(rt::test::sample_model("BoxInterleaved/glTF-Binary/BoxInterleaved.glb"), error);
  REQUIRE(m);
  CHECK(triangle_count(*m) == 12);

  m = import(rt::test::sample_model("SimpleMeshes/glTF/SimpleMeshes.gltf"), error);
  REQUIRE(m);
  CHECK(m->meshes.size() == 1);
  CHECK(placements(*m).size() == 2);  // one mesh, two nodes
  CHECK(triangle_count(*m) == 2);
  CHECK(m->meshes[0][0].material == -1);  // no material: the default one

  m = import(rt::test::sample_model("TextureCoordinateTest/glTF-Binary/TextureCoordinateTest.glb"), error);
  REQUIRE(m);
  size_t with_uvs = 0;  // the textured squares have TEXCOORD_0; the rest of the model does not
  for (const ModelPlacement& inst : placements(*m))
    for (const ImportedPrimitive& p : m->meshes[inst.mesh]) {
      CHECK((p.mesh.uvs.empty() || p.mesh.uvs.size() == p.mesh.positions.size()));
      with_uvs += !p.mesh.uvs.empty();
    }
  CHECK(with_uvs > 0);

  m = import(rt::test::sample_model("Duck/glTF-Binary/Duck.glb"), error);
  REQUIRE(m);
  CHECK(triangle_count(*m) == 4212);

  m = import(rt::test::sample_model("MetalRoughSpheresNoTextures/glTF-Binary/MetalRoughSpheresNoTextures.glb"), error);
  REQUIRE(m);
  CHECK(m->materials.size() > 10);
  CHECK(placements(*m).size() > 10);

  for (const char* path : {"OrientationTest/glTF-Binary/OrientationTest.glb", "Avocado/glTF/Avocado.gltf",
                           "AnimatedCube/glTF/AnimatedCube.gltf", "BoxAnimated/glTF-Binary/BoxAnimated.glb",
                           "Cameras/glTF/Cameras.gltf", "BoxTextured/glTF/BoxTextured.gltf"}) {
    INFO(path);
    CHECK(import(rt::test::sample_model(path), error));
  }
}

TEST_CASE("glTF samples: a model renders directly, framed by the default camera", "[io][gltf]") {
  if (!rt::test::have_sample_models()) {
    WARN("../shared/gltf not found: sample-model tests skipped");
    return;
  }
  Diagnostics diags;
  const auto loaded = load_scene(rt::test::sample_model("Avocado/glTF/Avocado.gltf"), rt::test::load_options(), diags);
  REQUIRE(loaded);
  const Aabb b = loaded->scene.bvh.bounds();
  CHECK(glm::length(b.extent()) < 0.2f);  // the avocado is ~6 cm: the camera must come close
  CHECK(glm::length(loaded->scene.camera.position - b.centre()) < 1.0f);
}

TEST_CASE("glTF: a named mesh, and an unknown mesh name", "[io][gltf]") {
  rt::test::ImportProblems error;
  const std::string knot = rt::test::source_path("scenes/models/knot.glb");
  auto m = import(knot, error, "knot");
  REQUIRE(m);
  CHECK(triangle_count(*m) == 7680);
  CHECK_FALSE(import(knot, error, "bunny"));
  CHECK(error.unknown_mesh);
  CHECK_THAT(error.message, Catch::Contains("\"knot\""));
}

TEST_CASE("glTF: byte indices, triangle strips and fans", "[io][gltf]") {
  std::string buffer = square_positions();
  append<uint8_t>(buffer, {0, 1, 3, 2});  // strip: (v0, v1, v2), then (v1, v3, v2) to keep the winding
  append<uint8_t>(buffer, {0, 0, 0, 0});  // padding to 4 bytes
  Json doc = {
      {"meshes",
       {{{"primitives",
          {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"mode", 5}},
           {{"attributes", {{"POSITION", 0}}}, {"mode", 6}}}}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5121}, {"count", 4}, {"type", "SCALAR"}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 48}}, {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 4}}}}};
  rt::test::ImportProblems error;
  const auto m = import(write_gltf("strip-fan.gltf", buffer, doc), error);
  INFO(error.message);
  REQUIRE(m);
  const std::vector<ImportedPrimitive>& prims = m->meshes[0];
  REQUIRE(prims.size() == 2);
  CHECK(prims[0].mesh.indices == std::vector<uint32_t>{0, 1, 3, 1, 2, 3});
  CHECK(prims[1].mesh.indices == std::vector<uint32_t>{1, 2, 0, 2, 3, 0});  // fan around vertex 0, no indices
  CHECK(prims[0].mesh.normals.empty());                                     // flat shading
}

TEST_CASE("glTF: sparse accessors and normalised texture coordinates", "[io][gltf]") {
  std::string buffer = square_positions();                             // view 0: 48 bytes
  append<uint16_t>(buffer, {0, 0, 65535, 0, 65535, 65535, 0, 65535});  // view 1: UVs, 16 bytes
  append<uint16_t>(buffer, {2, 0});                                    // view 2: sparse index (+2 padding)
  append<float>(buffer, {1, 1, 0.5f});                                 // view 3: sparse value for vertex 2
  Json doc = {
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"mode", 6}}}}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"sparse",
          {{"count", 1}, {"indices", {{"bufferView", 2}, {"componentType", 5123}}}, {"values", {{"bufferView", 3}}}}}},
        {{"bufferView", 1}, {"componentType", 5123}, {"normalized", true}, {"count", 4}, {"type", "VEC2"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 16}},
        {{"buffer", 0}, {"byteOffset", 64}, {"byteLength", 2}},
        {{"buffer", 0}, {"byteOffset", 68}, {"byteLength", 12}}}}};
  rt::test::ImportProblems error;
  const auto m = import(write_gltf("sparse.gltf", buffer, doc), error);
  INFO(error.message);
  REQUIRE(m);
  const TriangleMesh& mesh = m->meshes[0][0].mesh;
  CHECK(mesh.positions[2] == Vec3(1, 1, 0.5f));  // substituted
  CHECK(mesh.positions[1] == Vec3(1, 0, 0));     // untouched
  CHECK(mesh.uvs[2] == Vec2(1.0f, 1.0f));        // 65535 normalised
}

TEST_CASE("glTF: out-of-bounds accessors and indices are errors, not crashes", "[io][gltf]") {
  std::string buffer = square_positions();
  append<uint16_t>(buffer, {0, 1, 9, 0});  // index 9 of 4 vertices
  Json doc = {
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 48}}, {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 8}}}}};
  rt::test::ImportProblems error;
  CHECK_FALSE(import(write_gltf("bad-index.gltf", buffer, doc), error));
  CHECK_THAT(error.message, Catch::Contains("element 2 is index 9, but there are only 4 vertices"));

  doc["accessors"][0]["count"] = 400;  // reads far past the 48-byte view
  CHECK_FALSE(import(write_gltf("overrun.gltf", buffer, doc), error));
  CHECK_THAT(error.message, Catch::Contains("truncated or inconsistent"));

  doc["accessors"][0]["count"] = 4;
  doc["bufferViews"][0]["byteStride"] = 4;  // smaller than one VEC3 of floats
  CHECK_FALSE(import(write_gltf("stride.gltf", buffer, doc), error));
  CHECK_THAT(error.message, Catch::Contains("byteStride"));
}

TEST_CASE("glTF samples: Avocado's normal map, with its TANGENT attribute", "[io][gltf][normalmap]") {
  if (!rt::test::have_sample_models()) {
    WARN("../shared/gltf not found: sample-model tests skipped");
    return;
  }
  rt::test::ImportProblems error;
  const auto model = import(rt::test::sample_model("Avocado/glTF/Avocado.gltf"), error);
  INFO(error.message);
  REQUIRE(model);
  REQUIRE(model->materials.size() == 1);
  const NormalMap& normal_map = model->materials[0].normal_map;
  REQUIRE(normal_map.map.present());
  CHECK(normal_map.scale == 1.0f);
  // Base colour (sRGB), metallic-roughness and normal map: three images, each decoded once.
  const Material& m = model->materials[0];
  REQUIRE(model->textures.size() == 3);
  REQUIRE(m.texture.present());
  REQUIRE(m.pbr.texture.present());
  CHECK(m.pbr.enabled);
  CHECK(std::set<uint32_t>{m.texture.texture, m.pbr.texture.texture, normal_map.map.texture}.size() == 3);
  CHECK(model->textures[normal_map.map.texture].width() == 2048);
  const TriangleMesh& mesh = model->meshes[placements(*model)[0].mesh][0].mesh;
  REQUIRE(mesh.tangents.size() == mesh.positions.size());
  for (const Vec4& t : mesh.tangents) {
    CHECK(glm::length(Vec3(t)) == Approx(1.0f).epsilon(1e-4));
    CHECK(std::fabs(t.w) == 1.0f);
  }
  CHECK(std::any_of(model->files.begin(), model->files.end(),
                    [](const std::string& f) { return std::filesystem::path(f).filename() == "Avocado_normal.png"; }));
}
