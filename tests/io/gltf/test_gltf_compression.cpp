// Compressed glTF geometry (io/gltf/compressed_geometry.h): the Khronos Draco samples give the
// meshes and the render of their uncompressed originals; meshopt-encoded buffer views decode to
// the bytes encoded; damaged compressed data is an error naming where, never a crash.
#include <cmath>
#include <string>

#include <meshoptimizer.h>
#include <catch2/catch.hpp>

#include "io/gltf/loader.h"
#include "io/image/png_file.h"
#include "tests/support/gltf_files.h"
#include "tests/support/gltf_import.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

using namespace rt;
using rt::test::append;

namespace {

std::optional<ImportedModel> import(const std::string& path, rt::test::ImportProblems& problems) {
  LimitUsage usage;
  return rt::test::import_gltf(path, std::nullopt, LoadLimits{}, usage, problems);
}

size_t triangles(const ImportedModel& model) {
  size_t n = 0;
  for (const auto& mesh : model.meshes)
    for (const ImportedPrimitive& p : mesh) n += p.mesh.indices.size() / 3;
  return n;
}

// The largest distance from a point of `a` to the nearest point of `b` (by brute force).
float farthest_gap(const TriangleMesh& a, const TriangleMesh& b) {
  float worst = 0.0f;
  for (const Vec3& p : a.positions) {
    float best = 1e30f;
    for (const Vec3& q : b.positions) best = std::min(best, glm::length(p - q));
    worst = std::max(worst, best);
  }
  return worst;
}

double rms_levels(const std::string& a, const std::string& b) {
  std::string error;
  const auto x = rt::read_png(a, error), y = rt::read_png(b, error);
  REQUIRE(x);
  REQUIRE(y);
  REQUIRE(x->rgb.size() == y->rgb.size());
  double sum = 0.0;
  for (size_t i = 0; i < x->rgb.size(); ++i) sum += (double(x->rgb[i]) - y->rgb[i]) * (double(x->rgb[i]) - y->rgb[i]);
  return std::sqrt(sum / double(x->rgb.size()));
}

}  // namespace

TEST_CASE("KHR_draco_mesh_compression: the Draco samples import as their originals", "[gltf][compression]") {
  for (const char* name : {"Box", "Duck"}) {
    INFO(name);
    rt::test::ImportProblems plain_problems, draco_problems;
    const auto plain = import(rt::test::sample_model(std::string(name) + "/glTF/" + name + ".gltf"), plain_problems);
    const auto draco =
        import(rt::test::sample_model(std::string(name) + "/glTF-Draco/" + name + ".gltf"), draco_problems);
    INFO(draco_problems.message);
    REQUIRE(plain);
    REQUIRE(draco);
    CHECK(draco_problems.warnings.empty());
    CHECK(triangles(*draco) == triangles(*plain));
    REQUIRE(draco->meshes.size() == plain->meshes.size());
    const TriangleMesh& a = plain->meshes[0][0].mesh;
    const TriangleMesh& b = draco->meshes[0][0].mesh;
    CHECK(b.normals.size() == b.positions.size());
    // Draco quantises positions (14 bits here): every point within a ten-thousandth of the model's size.
    Vec3 lo(1e30f), hi(-1e30f);
    for (const Vec3& p : a.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    CHECK(farthest_gap(b, a) < 1e-3f * glm::length(hi - lo));
  }
}

TEST_CASE("cli: a Draco model renders as its uncompressed original", "[cli][gltf][compression]") {
  const std::string out = rt::test::fresh_folder("draco-render");
  for (const char* variant : {"glTF", "glTF-Draco"}) {
    const auto run = rt::test::rtcli(std::string("render ../shared/gltf/Duck/") + variant +
                                     "/Duck.gltf --width 96 --height 72 -q -o " + out + "/" + variant + ".png");
    INFO(run.output);
    REQUIRE(run.code == 0);
  }
  // Only silhouette pixels move with the quantised positions (0.4 levels RMS measured).
  CHECK(rms_levels(out + "/glTF.png", out + "/glTF-Draco.png") < 2.0);
}

TEST_CASE("KHR_draco_mesh_compression: damaged data is an error naming the primitive", "[gltf][compression]") {
  const std::string original = rt::test::sample_model("Box/glTF-Draco/Box.gltf");
  const std::string dir = rt::test::fresh_folder("draco-damaged");
  const auto text = rt::test::read_file(original);
  // The Draco data overwritten past its header, then an attribute id the data lacks.
  std::string bin = rt::test::read_file(rt::test::sample_model("Box/glTF-Draco/Box.bin"));
  std::string damaged = bin;
  for (size_t i = 8; i < damaged.size(); ++i) damaged[i] = static_cast<char>(0xff);
  rt::test::write_file("draco-damaged/Box.bin", damaged);
  rt::test::write_file("draco-damaged/cut.gltf", text);
  rt::test::ImportProblems problems;
  CHECK_FALSE(import(dir + "/cut.gltf", problems));
  CHECK_THAT(problems.message, Catch::Contains("its Draco data could not be decoded"));

  rt::test::write_file("draco-damaged/Box.bin", bin);
  Json doc = Json::parse(text);
  doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["NORMAL"] = 99;
  rt::test::write_file("draco-damaged/bad-id.gltf", doc.dump());
  CHECK_FALSE(import(dir + "/bad-id.gltf", problems));
  CHECK_THAT(problems.message, Catch::Contains("expected an attribute id the Draco data has"));
}

TEST_CASE("EXT_meshopt_compression: encoded buffer views decode to the bytes encoded", "[gltf][compression]") {
  // A square's positions and indices, encoded by meshoptimizer, in a buffer after a fallback
  // buffer that has no data (as gltfpack writes them).
  const float positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const uint32_t indices[] = {0, 1, 2, 0, 2, 3};
  std::vector<unsigned char> vertices(meshopt_encodeVertexBufferBound(4, 12));
  vertices.resize(meshopt_encodeVertexBuffer(vertices.data(), vertices.size(), positions, 4, 12));
  std::vector<unsigned char> index_bytes(meshopt_encodeIndexBufferBound(6, 4));
  index_bytes.resize(meshopt_encodeIndexBuffer(index_bytes.data(), index_bytes.size(), indices, 6));
  std::string buffer(vertices.begin(), vertices.end());
  while (buffer.size() % 4) buffer.push_back('\0');
  const size_t index_offset = buffer.size();
  buffer.append(index_bytes.begin(), index_bytes.end());
  const auto data_uri = "data:application/octet-stream;base64," + rt::test::base64(buffer);
  const Json doc = {{"asset", {{"version", "2.0"}}},
                    {"extensionsUsed", {"EXT_meshopt_compression"}},
                    {"extensionsRequired", {"EXT_meshopt_compression"}},
                    {"scene", 0},
                    {"scenes", {{{"nodes", {0}}}}},
                    {"nodes", {{{"mesh", 0}}}},
                    {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
                    {"accessors",
                     {{{"bufferView", 0},
                       {"componentType", 5126},
                       {"count", 4},
                       {"type", "VEC3"},
                       {"min", {0, 0, 0}},
                       {"max", {1, 1, 0}}},
                      {{"bufferView", 1}, {"componentType", 5125}, {"count", 6}, {"type", "SCALAR"}}}},
                    {"bufferViews",
                     {{{"buffer", 0},
                       {"byteLength", 48},
                       {"byteStride", 12},
                       {"extensions",
                        {{"EXT_meshopt_compression",
                          {{"buffer", 1},
                           {"byteLength", vertices.size()},
                           {"byteStride", 12},
                           {"count", 4},
                           {"mode", "ATTRIBUTES"}}}}}},
                      {{"buffer", 0},
                       {"byteOffset", 48},
                       {"byteLength", 24},
                       {"extensions",
                        {{"EXT_meshopt_compression",
                          {{"buffer", 1},
                           {"byteOffset", index_offset},
                           {"byteLength", index_bytes.size()},
                           {"byteStride", 4},
                           {"count", 6},
                           {"mode", "TRIANGLES"}}}}}}}},
                    {"buffers",
                     {{{"byteLength", 72}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}},
                      {{"byteLength", buffer.size()}, {"uri", data_uri}}}}};
  const std::string path = rt::test::write_file("meshopt.gltf", doc.dump());
  rt::test::ImportProblems problems;
  const auto model = import(path, problems);
  INFO(problems.message);
  REQUIRE(model);
  const TriangleMesh& mesh = model->meshes.at(0).at(0).mesh;
  REQUIRE(mesh.positions.size() == 4);
  CHECK(mesh.positions[2] == Vec3(1, 1, 0));
  CHECK(mesh.indices == std::vector<uint32_t>{0, 1, 2, 0, 2, 3});

  // The same with the compressed bytes damaged: an error at the view, no crash.
  Json damaged = doc;
  damaged["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteLength"] = 3;
  rt::test::ImportProblems bad;
  CHECK_FALSE(import(rt::test::write_file("meshopt-damaged.gltf", damaged.dump()), bad));
  CHECK_THAT(bad.message, Catch::Contains("could not be decoded"));
}
