// The shadow terminator on coarse smooth meshes: a mesh's own flat facets must not shadow the
// points its interpolated normals say are lit (Hanika's lift, core/mesh.cpp).
#include <cmath>

#include <catch2/catch.hpp>

#include "core/mesh.h"
#include "core/render/renderer.h"
#include "tests/support/gltf_files.h"
#include "tests/support/loading.h"

using namespace rt;

namespace {

// A UV sphere of radius 1 with few facets (`segments` around, `rings` from pole to pole) and its
// true normals, as a glTF file.
std::string coarse_sphere(int segments, int rings) {
  std::string positions, indices;
  int count = 0;
  for (int r = 0; r <= rings; ++r) {
    const double theta = M_PI * r / rings;
    for (int s = 0; s <= segments; ++s, ++count) {
      const double phi = 2 * M_PI * s / segments;
      const auto x = static_cast<float>(std::sin(theta) * std::cos(phi)), y = static_cast<float>(std::cos(theta)),
                 z = static_cast<float>(-std::sin(theta) * std::sin(phi));
      rt::test::append<float>(positions, {x, y, z});
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const auto a = static_cast<uint16_t>(r * (segments + 1) + s), b = static_cast<uint16_t>(a + segments + 1);
      rt::test::append<uint16_t>(
          indices, {a, b, static_cast<uint16_t>(a + 1), static_cast<uint16_t>(a + 1), b, static_cast<uint16_t>(b + 1)});
    }
  const size_t bytes = positions.size();
  const std::string buffer = positions + positions + indices;  // unit sphere: normals = positions
  const Json doc = {
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}}}}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", count}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", count}, {"type", "VEC3"}},
        {{"bufferView", 2}, {"componentType", 5123}, {"count", indices.size() / 2}, {"type", "SCALAR"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteLength", bytes}},
        {{"buffer", 0}, {"byteOffset", bytes}, {"byteLength", bytes}},
        {{"buffer", 0}, {"byteOffset", 2 * bytes}, {"byteLength", indices.size()}}}}};
  return rt::test::write_gltf("coarse_sphere.gltf", buffer, doc);
}

}  // namespace

TEST_CASE("shadow terminator: a coarse smooth sphere is lit wherever its normals face the light",
          "[render][shadow][terminator]") {
  // Lit from the side (+x), seen from +z: the terminator runs down the middle of the image.
  const LoadedScene s = rt::test::load_scene_text("terminator.json", R"({
    "render": {"width": 64, "height": 64, "antialias": {"mode": "none"}},
    "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "fov": 35},
    "materials": {"white": {"kd": 1, "ks": 0}},
    "lights": [{"type": "directional", "direction": [-1, -0.2, 0]}],
    "nodes": [{"mesh": {"file": ")" + coarse_sphere(10, 6) + R"("}, "material": "white"}]})");
  Image lit, normals;
  render(s.scene, s.settings, lit);
  RenderSettings debug = s.settings;
  debug.integrator = "normals";
  render(s.scene, debug, normals);
  const Vec3 to_light = glm::normalize(Vec3(1.0f, 0.2f, 0.0f));
  int checked = 0, dark = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const Vec3 c = normals.at(x, y);
      if (c == Vec3(0.0f)) continue;  // the background
      const float facing = glm::dot(glm::normalize(2.0f * c - 1.0f), to_light);
      if (facing < 0.2f) continue;  // near or past the terminator: the facets may rightly differ
      ++checked;
      if (lit.at(x, y).x < 0.5f * facing) ++dark;  // a facet's shadow where the normals face the light
    }
  INFO(dark << " of " << checked << " pixels facing the light are in the mesh's own shadow");
  CHECK(checked > 300);
  CHECK(dark == 0);
}

TEST_CASE("shadow terminator: the lift is zero on flat facets and rises towards the curved surface",
          "[shadow][terminator]") {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  Hit hit;
  hit.b1 = hit.b2 = 1.0f / 3.0f;
  hit.t = 1.0f;
  const Ray ray(Vec3(1.0f / 3, 1.0f / 3, 1), Vec3(0, 0, -1));
  CHECK(mesh_surface(m, 0, ray, hit, Transform{}).shadow_lift == Vec3(0.0f));  // flat: nothing
  // Normals leaning outward, as on a sphere's facet: the centroid lifts along +z, by the tangent
  // planes' heights above it (each vertex's share).
  const Vec3 out = glm::normalize(Vec3(-1, -1, 3)), right = glm::normalize(Vec3(2, -1, 3)),
             up = glm::normalize(Vec3(-1, 2, 3));
  m.normals = {out, right, up};
  const Vec3 lift = mesh_surface(m, 0, ray, hit, Transform{}).shadow_lift;
  const Vec3 p(1.0f / 3, 1.0f / 3, 0);
  Vec3 expected(0.0f);
  for (int i = 0; i < 3; ++i)
    expected += (1.0f / 3) * std::max(0.0f, glm::dot(m.positions[i] - p, m.normals[i])) * m.normals[i];
  CHECK(lift.z > 0.05f);
  CHECK(lift.x == Approx(expected.x));
  CHECK(lift.z == Approx(expected.z));
}
