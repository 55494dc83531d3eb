// glTF materials by the documented rule (io/gltf/materials.h): factors, extensions, texture
// transforms and samplers, vertex colours, metallic-roughness per shading point, alpha masks for
// camera and shadow rays, BLEND and unlit.
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "core/render/shadow_transmittance.h"
#include "io/gltf/loader.h"
#include "io/gltf/supported_extensions.h"
#include "materials/evaluated_surface.h"
#include "materials/pbr_to_phong.h"
#include "tests/support/gltf_files.h"
#include "tests/support/gltf_import.h"
#include "tests/support/loading.h"

using namespace rt;
using rt::test::append;

namespace {

// 2 x 2 RGBA: the left column red and opaque, the right column green and fully transparent.
const char* kHalfAlphaPng =
    "iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAYAAABytg0kAAAAFUlEQVR4nGP4z8Dwn+E/AwMTAxQAACr5AwDBaZIZAAAAAElFTkSuQmCC";
// 2 x 2 RGB, every texel (0, 128, 255): a metallicRoughness map of roughness 128/255, metallic 1.
const char* kMetalRoughPng =
    "iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAFklEQVR4nGNkaPjPwMDAxMDAwMDAAAARHwGDXcgNqQAAAABJRU5ErkJggg==";

// The unit square in z = 0 with u = x, v = 1 - y, one material, the two images above as textures
// 0 (nearest sampler, mirrored in u and clamped in v) and 1 (no sampler); with `colours`, COLOR_0
// as normalised bytes.
std::string quad_file(const std::string& name, const Json& material, const std::vector<uint8_t>& colors = {}) {
  std::string buffer = rt::test::square_positions();  // view 0: 48 bytes
  append<float>(buffer, {0, 1, 1, 1, 1, 0, 0, 0});    // view 1: 32 bytes
  append<uint16_t>(buffer, {0, 1, 2, 0, 2, 3});       // view 2: 12 bytes
  Json attributes = {{"POSITION", 0}, {"TEXCOORD_0", 1}};
  Json views = {{{"buffer", 0}, {"byteLength", 48}},
                {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 32}},
                {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 12}}};
  Json accessors = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                    {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
                    {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}};
  if (!colors.empty()) {
    buffer += std::string(4, '\0');  // align the bytes to 4 (the views above end at 92)
    for (uint8_t c : colors) buffer.push_back(static_cast<char>(c));
    views.push_back({{"buffer", 0}, {"byteOffset", 96}, {"byteLength", colors.size()}});
    accessors.push_back(
        {{"bufferView", 3}, {"componentType", 5121}, {"normalized", true}, {"count", 4}, {"type", "VEC4"}});
    attributes["COLOR_0"] = 3;
  }
  Json doc = {{"scene", 0},
              {"scenes", {{{"nodes", {0}}}}},
              {"nodes", {{{"mesh", 0}}}},
              {"meshes", {{{"primitives", {{{"attributes", attributes}, {"indices", 2}, {"material", 0}}}}}}},
              {"materials", {material}},
              {"textures", {{{"source", 0}, {"sampler", 0}}, {{"source", 1}}}},
              {"samplers", {{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33648}, {"wrapT", 33071}}}},
              {"images",
               {{{"uri", std::string("data:image/png;base64,") + kHalfAlphaPng}},
                {{"uri", std::string("data:image/png;base64,") + kMetalRoughPng}}}},
              {"accessors", accessors},
              {"bufferViews", views}};
  return rt::test::write_gltf(name, buffer, doc);
}

// A scene with the quad from `gltf` and a big cube behind it (z from -3 to -1), rendered by
// `integrator`.
LoadedScene quad_scene(const std::string& name, const std::string& gltf, const std::string& integrator = "whitted") {
  return rt::test::load_scene_text(name, R"({
    "render": {"integrator": ")" + integrator +
                                             R"("},
    "camera": {"position": [0.5, 0.5, 5], "look_at": [0.5, 0.5, 0]},
    "lights": [{"type": "point", "position": [0.5, 0.5, 4], "color": [1, 1, 1]}],
    "materials": {"wall": {"kd": [0.5, 0.5, 0.5]}},
    "nodes": [{"mesh": {"file": ")" + gltf + R"("}},
              {"shape": "cube", "material": "wall", "transform": {"translate": [0, 0, -2], "scale": [5, 5, 1]}}]})");
}

Ray down_z(float x, float y, float z = 5.0f) {
  Ray r;
  r.origin = Vec3(x, y, z);
  r.direction = Vec3(0, 0, -1);
  return r;
}

// The evaluated surface of the quad at (x, y).
EvaluatedSurface quad_surface(const Scene& scene, float x, float y) {
  Ray r = down_z(x, y);
  Hit hit;
  REQUIRE(scene.intersect(r, hit));
  REQUIRE(hit.t == Approx(5.0f));
  const SurfaceInteraction si = scene.surface(r, hit);
  return evaluate_surface(scene.materials()[si.material], si, r.direction, scene.textures());
}

}  // namespace

TEST_CASE("pbr_to_phong: hand-computed terms for a rough metal and a smooth dielectric", "[gltf][materials]") {
  const PhongTerms metal = pbr_to_phong(Vec3(1.0f, 0.5f, 0.25f), 1.0f, 0.5f);
  CHECK(metal.kd.x == Approx(0.5f));  // base * (1 - 1 * 0.5)
  CHECK(metal.kd.z == Approx(0.125f));
  CHECK(metal.ks.y == Approx(0.25f));            // F0 = base; * (1 - 0.5)
  CHECK(metal.shininess == Approx(30.0f));       // 2 / 0.5^4 - 2
  CHECK(metal.reflectivity.x == Approx(0.25f));  // F0 * 0.5^2
  CHECK(metal.glossy == Approx(0.5f));           // 2 * 0.5^2
  const PhongTerms plastic = pbr_to_phong(Vec3(0.2f), 0.0f, 0.0f);
  CHECK(plastic.kd.x == Approx(0.2f));
  CHECK(plastic.ks.x == Approx(0.04f));
  CHECK(plastic.shininess == 4096.0f);
  CHECK(plastic.reflectivity.x == Approx(0.04f));
  CHECK(plastic.glossy == 0.0f);
}

TEST_CASE("glTF materials: factors and extensions by the documented rule", "[gltf][materials]") {
  const Json material = {
      {"pbrMetallicRoughness",
       {{"baseColorFactor", {0.5, 0.25, 1.0, 1.0}}, {"metallicFactor", 0.3}, {"roughnessFactor", 0.6}}},
      {"emissiveFactor", {1.0, 0.5, 0.0}},
      {"extensions",
       {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}},
        {"KHR_materials_ior", {{"ior", 1.33}}},
        {"KHR_materials_transmission", {{"transmissionFactor", 0.8}}},
        {"KHR_materials_volume", {{"attenuationColor", {0.5, 1.0, 0.25}}, {"attenuationDistance", 2.0}}}}}};
  const ImportedModel model = rt::test::imported(quad_file("factors.gltf", material));
  REQUIRE(model.materials.size() == 1);
  const Material& m = model.materials[0];
  CHECK(m.pbr.enabled);
  CHECK(m.kd == Vec3(0.5f, 0.25f, 1.0f));
  CHECK(m.pbr.metallic == Approx(0.3f));
  CHECK(m.pbr.roughness == Approx(0.6f));
  CHECK(m.emission == Vec3(4.0f, 2.0f, 0.0f));
  CHECK(m.ior == Approx(1.33f));
  CHECK(m.transmission == Vec3(0.8f));
  // -ln(colour) / distance: ln 2 / 2, 0, ln 4 / 2.
  CHECK(m.absorption.x == Approx(0.34657f).epsilon(1e-4));
  CHECK(m.absorption.y == Approx(0.0f).margin(1e-6));
  CHECK(m.absorption.z == Approx(0.69315f).epsilon(1e-4));
  CHECK_FALSE(m.cutout.enabled);
  CHECK_FALSE(m.unlit);
}

TEST_CASE("glTF materials: KHR_texture_transform and sampler filters on texture slots", "[gltf][materials][uv]") {
  const Json material = {
      {"pbrMetallicRoughness",
       {{"baseColorTexture",
         {{"index", 0},
          {"extensions",
           {{"KHR_texture_transform",
             {{"offset", {0.5, 0.0}}, {"rotation", M_PI / 2}, {"scale", {2.0, 3.0}}, {"texCoord", 1}}}}}}},
        {"metallicRoughnessTexture", {{"index", 1}}}}}};
  const ImportedModel model = rt::test::imported(quad_file("transform.gltf", material));
  const Material& m = model.materials[0];
  REQUIRE(m.texture.present());
  const TextureMapping& t = m.texture.mapping;
  CHECK(t.offset == Vec2(0.5f, 0.0f));
  CHECK(t.rotation_degrees == Approx(90.0f));
  CHECK(t.scale == Vec2(2.0f, 3.0f));
  CHECK(t.uv_set == 1);                        // the extension's texCoord overrides the textureInfo's
  CHECK(t.filter == TextureFilter::kNearest);  // magFilter NEAREST
  CHECK(m.pbr.texture.mapping.filter == TextureFilter::kTrilinear);  // no sampler: mipmapped
  CHECK(m.texture.texture != m.pbr.texture.texture);
  // wrapS and wrapT each their own axis; no sampler: repeat both ways.
  CHECK(t.wrap == WrapModes(TextureWrap::kMirror, TextureWrap::kClamp));
  CHECK(m.pbr.texture.mapping.wrap == WrapModes(TextureWrap::kRepeat));
}

TEST_CASE("glTF materials: metallicRoughness texture and COLOR_0 at the shading point", "[gltf][materials]") {
  const Json material = {{"pbrMetallicRoughness",
                          {{"baseColorFactor", {0.8, 0.6, 0.4, 1.0}},
                           {"metallicFactor", 0.5},
                           {"roughnessFactor", 1.0},
                           {"metallicRoughnessTexture", {{"index", 1}}}}}};
  // COLOR_0 (255, 128, 0, 255) on every vertex: linear (1, 128/255, 0).
  const std::string gltf =
      quad_file("metal-rough.gltf", material, {255, 128, 0, 255, 255, 128, 0, 255, 255, 128, 0, 255, 255, 128, 0, 255});
  const LoadedScene loaded = quad_scene("metal-rough.json", gltf);
  const EvaluatedSurface s = quad_surface(loaded.scene, 0.3f, 0.6f);
  const Vec3 base = Vec3(0.8f, 0.6f, 0.4f) * Vec3(1.0f, 128.0f / 255.0f, 0.0f);
  const PhongTerms expected = pbr_to_phong(base, 0.5f * 1.0f, 1.0f * 128.0f / 255.0f);
  CHECK(s.diffuse.x == Approx(expected.kd.x).epsilon(1e-4));
  CHECK(s.diffuse.y == Approx(expected.kd.y).epsilon(1e-4));
  CHECK(s.diffuse.z == Approx(0.0f).margin(1e-6));
  CHECK(s.specular.x == Approx(expected.ks.x).epsilon(1e-4));
  CHECK(s.shininess == Approx(expected.shininess).epsilon(1e-3));
  CHECK(s.reflectivity.y == Approx(expected.reflectivity.y).epsilon(1e-4));
  CHECK(s.glossy == Approx(expected.glossy).epsilon(1e-4));
}

TEST_CASE("glTF materials: alpha MASK cuts the surface out for camera and shadow rays", "[gltf][materials][alpha]") {
  const Json mask = {
      {"alphaMode", "MASK"}, {"alphaCutoff", 0.5}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}};
  const LoadedScene loaded = quad_scene("mask.json", quad_file("mask.gltf", mask));
  const Scene& scene = loaded.scene;
  Hit hit;
  Ray left = down_z(0.25f, 0.5f), right = down_z(0.75f, 0.5f);
  // The left half (alpha 1) is there; the right half (alpha 0) is not: the ray goes on to the wall.
  REQUIRE(scene.intersect(left, hit));
  CHECK(hit.t == Approx(5.0f));
  REQUIRE(scene.intersect(right, hit));
  CHECK(hit.t == Approx(6.0f));
  // Shadow rays from just behind the quad to a light in front of it.
  Ray shadow_left = down_z(0.25f, 0.5f, -0.5f), shadow_right = down_z(0.75f, 0.5f, -0.5f);
  shadow_left.direction = shadow_right.direction = Vec3(0, 0, 1);
  shadow_left.tmax = shadow_right.tmax = 4.0f;
  CHECK(scene.occluded(shadow_left));
  CHECK_FALSE(scene.occluded(shadow_right));

  // Opaque, the same file draws the whole square.
  const Json opaque = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}};
  const LoadedScene solid = quad_scene("opaque.json", quad_file("opaque.gltf", opaque));
  Ray again = down_z(0.75f, 0.5f);
  REQUIRE(solid.scene.intersect(again, hit));
  CHECK(hit.t == Approx(5.0f));
  CHECK(solid.scene.occluded(shadow_right));
}

TEST_CASE("glTF materials: alpha MASK reads COLOR_0's alpha and the factor's", "[gltf][materials][alpha]") {
  const Json mask = {{"alphaMode", "MASK"}, {"alphaCutoff", 0.5}};
  // Vertex alpha 0 at x = 0 and 255 at x = 1: alpha = x, cut where x < 0.5.
  const std::vector<uint8_t> colors = {255, 255, 255, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0};
  const LoadedScene loaded = quad_scene("vertex-alpha.json", quad_file("vertex-alpha.gltf", mask, colors));
  Hit hit;
  Ray left = down_z(0.2f, 0.5f), right = down_z(0.8f, 0.5f);
  REQUIRE(loaded.scene.intersect(left, hit));
  CHECK(hit.t == Approx(6.0f));
  REQUIRE(loaded.scene.intersect(right, hit));
  CHECK(hit.t == Approx(5.0f));
  // baseColorFactor's alpha below the cutoff removes it all.
  const Json faint = {{"alphaMode", "MASK"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.4}}}}};
  const LoadedScene gone = quad_scene("faint.json", quad_file("faint.gltf", faint));
  Ray centre = down_z(0.5f, 0.5f);
  REQUIRE(gone.scene.intersect(centre, hit));
  CHECK(hit.t == Approx(6.0f));
}

TEST_CASE("glTF materials: BLEND becomes unbent transmission, unlit shows the base colour", "[gltf][materials]") {
  const Json blend = {{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.25}}}}};
  const ImportedModel model = rt::test::imported(quad_file("blend.gltf", blend));
  CHECK(model.materials[0].transmission == Vec3(0.75f));
  CHECK(model.materials[0].ior == 1.0f);
  CHECK(model.materials[0].cutout.enabled);
  CHECK(model.materials[0].cutout.factor == 1.0f);  // the factor went to transmission, not the mask
  CHECK(model.materials[0].transmission_is_coverage);
  // Coverage, not KHR transmission: what is not covered passes untinted, from a red metal too.
  const Json red_metal = {{"alphaMode", "BLEND"},
                          {"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 0.25}}, {"metallicFactor", 1.0}}}};
  const ImportedModel red = rt::test::imported(quad_file("blend-red.gltf", red_metal));
  SurfaceInteraction si;
  si.geometric_normal = si.shading_normal = Vec3(0, 0, 1);
  const EvaluatedSurface through = evaluate_surface(red.materials[0], si, Vec3(0, 0, -1), red.textures);
  CHECK(through.transmission == Vec3(0.75f));
  CHECK(red.materials[0].transmittance() == Vec3(0.75f));

  const Json unlit = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}}},
                      {"extensions", {{"KHR_materials_unlit", Json::object()}}}};
  const LoadedScene loaded = quad_scene("unlit.json", quad_file("unlit.gltf", unlit));
  const EvaluatedSurface s = quad_surface(loaded.scene, 0.5f, 0.5f);
  CHECK(s.emission.x == Approx(0.2f));
  CHECK(s.emission.y == Approx(0.4f));
  CHECK(s.emission.z == Approx(0.6f));
  CHECK(s.diffuse == Vec3(0.0f));
  CHECK(s.specular == Vec3(0.0f));
}

TEST_CASE("glTF materials: BLEND's vertex alpha is a probability per ray when path traced, a cut in Whitted",
          "[gltf][materials][path]") {
  // Every vertex white with alpha 64/255: a quarter of the surface there.
  const std::vector<uint8_t> colors = {255, 255, 255, 64, 255, 255, 255, 64, 255, 255, 255, 64, 255, 255, 255, 64};
  const Json blend = {{"alphaMode", "BLEND"}};
  const std::string gltf = quad_file("blend-vertex.gltf", blend, colors);
  const LoadedScene path = quad_scene("blend-path.json", gltf, "path");
  const LoadedScene whitted = quad_scene("blend-whitted.json", gltf);
  // Rays through the quad's inside at 4,000 points (each ray draws its own number), and shadow
  // rays that end between the quad and the cube behind it.
  const int n = 4000;
  int path_hits = 0, path_blocked = 0, whitted_hits = 0, whitted_blocked = 0;
  for (int i = 0; i < n; ++i) {
    const float x = 0.05f + 0.9f * static_cast<float>(i % 64) / 64.0f;
    const float y = 0.05f + 0.9f * static_cast<float>(i / 64) / 63.0f;
    Hit hit;
    Ray r = down_z(x, y);
    if (path.scene.intersect(r, hit) && hit.t == Approx(5.0f)) ++path_hits;
    r = down_z(x, y);
    if (whitted.scene.intersect(r, hit) && hit.t == Approx(5.0f)) ++whitted_hits;
    Ray shadow = down_z(x, y);
    shadow.tmax = 5.5f;
    path_blocked += path.scene.occluded(shadow);
    whitted_blocked += whitted.scene.occluded(shadow);
  }
  // Binomial: the mean 64/255 = 0.251, standard error sqrt(0.25 x 0.75 / 4000) = 0.0069; 4 of them.
  const double coverage = 64.0 / 255.0, tolerance = 4.0 * std::sqrt(coverage * (1.0 - coverage) / n);
  CHECK(static_cast<double>(path_hits) / n == Approx(coverage).margin(tolerance));
  CHECK(static_cast<double>(path_blocked) / n == Approx(coverage).margin(tolerance));
  CHECK(whitted_hits == 0);  // 0.251 < 0.5: cut out
  CHECK(whitted_blocked == 0);
  // The same ray draws the same number: the answer does not change when asked again.
  Hit a, b;
  Ray r1 = down_z(0.3f, 0.7f), r2 = down_z(0.3f, 0.7f);
  CHECK(path.scene.intersect(r1, a) == path.scene.intersect(r2, b));
}

TEST_CASE(
    "glTF materials: transmission is tinted by the base colour, scaled by transmissionTexture, none through metal",
    "[gltf][materials]") {
  // Texture 1's texels are (0, 128, 255): red 0, so the texture lets nothing through.
  const auto material = [](double metallic, bool texture) {
    Json transmission = {{"transmissionFactor", 0.8}};
    if (texture) transmission["transmissionTexture"] = {{"index", 1}};
    return Json{{"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 0.5, 0.25, 1.0}}, {"metallicFactor", metallic}}},
                {"extensions", {{"KHR_materials_transmission", transmission}}}};
  };
  const auto passes = [&](double metallic, bool texture) {
    const std::string path =
        quad_file(texture ? "transmission-texture.gltf" : "transmission.gltf", material(metallic, texture));
    rt::test::ImportProblems problems;
    const auto model = import_gltf(path, std::nullopt, LoadLimits{}, problems);
    REQUIRE(model);
    CHECK(problems.warnings.empty());
    const Material& m = model->materials[0];
    CHECK(m.transmission == Vec3(0.8f));
    CHECK(m.transmission_texture.present() == texture);
    SurfaceInteraction si;
    si.geometric_normal = si.shading_normal = Vec3(0, 0, 1);
    const EvaluatedSurface s = evaluate_surface(m, si, Vec3(0, 0, -1), model->textures);
    return s.transmission;
  };
  const Vec3 dielectric = passes(0.0, false);
  CHECK(dielectric.x == Approx(0.8f));
  CHECK(dielectric.y == Approx(0.4f));  // tinted by the base colour
  CHECK(dielectric.z == Approx(0.2f));
  CHECK(passes(1.0, false) == Vec3(0.0f));  // metal lets nothing through
  CHECK(passes(0.0, true) == Vec3(0.0f));   // the texture's red channel is 0
}

TEST_CASE("glTF extensions: the documented list of supported extensions is the code's", "[gltf][docs]") {
  const std::string limits = rt::test::read_file(rt::test::source_path("docs/errors-and-limits.md"));
  const size_t start = limits.find("`extensionsRequired` names only extensions rtcli implements (");
  REQUIRE(start != std::string::npos);
  const std::string sentence = limits.substr(start, limits.find(')', start) - start);
  // As many names as the code supports, and each of them.
  size_t listed = 0;
  for (const char* prefix : {"`KHR_", "`EXT_"})
    for (size_t at = sentence.find(prefix); at != std::string::npos; at = sentence.find(prefix, at + 1)) ++listed;
  CHECK(listed == supported_gltf_extensions().size());
  for (const std::string& name : supported_gltf_extensions()) {
    INFO(name);
    CHECK_THAT(sentence, Catch::Contains("`" + name + "`"));
  }
}

TEST_CASE("glTF materials: shadows through glass follow the textured metallic, as shading does", "[gltf][materials]") {
  // metallicFactor 1, but the metallicRoughness texture's blue (metallic) is 0 everywhere: the
  // quad is clear glass where the camera looks, and so for shadow rays.
  const Json material = {{"pbrMetallicRoughness",
                          {{"baseColorFactor", {1.0, 0.5, 1.0, 1.0}},
                           {"metallicFactor", 1.0},
                           {"roughnessFactor", 0.0},
                           {"metallicRoughnessTexture", {{"index", 0}}}}},
                         {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}};
  const LoadedScene loaded = quad_scene("glass-shadow.json", quad_file("glass-shadow.gltf", material));
  const Scene& scene = loaded.scene;
  const EvaluatedSurface s = quad_surface(scene, 0.25f, 0.5f);
  REQUIRE(s.pbr);
  CHECK(s.pbr->metallic == 0.0f);
  CHECK(s.transmission.y == Approx(0.5f));
  Ray shadow = down_z(0.25f, 0.5f);
  shadow.tmax = 5.5f;  // from z = 5 to -0.5: through the quad, short of the wall
  const Vec3 through = shadow_transmittance(scene, shadow);
  CHECK(through.x > 0.9f);  // (1 - F0) of the interface
  CHECK(through.y == Approx(through.x * 0.5f).epsilon(1e-3));
}
