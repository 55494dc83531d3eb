#include "tests/fuzz/fuzz_targets.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "core/accel/bvh.h"
#include "core/render/integrator.h"
#include "core/render/pixel_sampler.h"
#include "core/render/renderer.h"
#include "core/render/stereo_images.h"
#include "io/assemble/scene_builder.h"
#include "io/gltf/loader.h"
#include "io/image/texture_file.h"
#include "io/json/document.h"
#include "io/scene/scene_parser.h"

namespace rt::fuzz {
namespace {

// Small limits keep each input fast, so the fuzzer explores instead of allocating.
LoadOptions fuzz_options() {
  LoadOptions options;
  options.threads = 1;
  options.integrators = integrators().names();
  options.pixel_samplers = pixel_samplers().names();
  options.limits.scene_file_bytes = 1 << 20;
  options.limits.gltf_json_bytes = 1 << 20;
  options.limits.gltf_total_bytes = 4 << 20;
  options.limits.vertices = 1 << 16;
  options.limits.triangles = 1 << 16;
  options.limits.instances = 1 << 12;
  options.limits.nodes = 1 << 12;
  return options;
}

// A folder of this process's own for the files an input becomes.
std::filesystem::path scratch_folder() {
  const auto folder = std::filesystem::temp_directory_path() / ("rtcli-fuzz-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  return folder;
}

// A square with UVs whose material uses image 0 in every slot glTF has (and the alpha mask).
nlohmann::json textured_square(nlohmann::json image) {
  const nlohmann::json slot = {{"index", 0}};
  return {{"asset", {{"version", "2.0"}}},
          {"scenes", {{{"nodes", {0}}}}},
          {"nodes", {{{"mesh", 0}}}},
          {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"material", 0}}}}}}},
          {"materials",
           {{{"pbrMetallicRoughness", {{"baseColorTexture", slot}, {"metallicRoughnessTexture", slot}}},
             {"normalTexture", slot},
             {"emissiveTexture", slot},
             {"emissiveFactor", {1, 1, 1}},
             {"alphaMode", "MASK"}}}},
          {"textures", {{{"source", 0}}}},
          {"images", {std::move(image)}},
          {"accessors",
           {{{"bufferView", 0},
             {"componentType", 5126},
             {"count", 3},
             {"type", "VEC3"},
             {"min", {-1, -1, 0}},
             {"max", {1, 1, 0}}},
            {{"bufferView", 0}, {"byteOffset", 36}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}}}};
}

// The square's positions and UVs.
std::vector<unsigned char> square_data() {
  const float v[] = {-1, -1, 0, 1, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0.5f, 1};
  std::vector<unsigned char> out(sizeof v);
  std::memcpy(out.data(), v, sizeof v);
  return out;
}

// Imports a glTF file's bytes from `folder` and places it; an import may fail (with a message).
std::string import_and_place(const std::vector<unsigned char>& bytes, const std::string& folder) {
  const LoadOptions options = fuzz_options();
  Diagnostics found;
  Reporter report(found, folder + "/fuzz.gltf");
  ImportError error;
  LimitUsage usage;
  const auto model = import_gltf_bytes(bytes, folder, std::nullopt, options.limits, usage, report, error);
  if (!model) return found.has_errors() ? "" : "a rejected model came with no error";
  for (const Texture& t : model->textures)
    for (const TextureFilter filter : {TextureFilter::kNearest, TextureFilter::kTrilinear})
      if (!is_finite(t.sample(Vec2(0.3f, 0.7f), TextureWrap::kRepeat, filter, 0.01f)))
        return "a glTF texture sample is not finite";
  return "";
}

}  // namespace

int abort_on_problem(const std::string& problem) {
  if (problem.empty()) return 0;
  std::fprintf(stderr, "invariant broken: %s\n", problem.c_str());
  std::abort();
}

std::string scene_json(const uint8_t* data, size_t size) {
  const LoadOptions options = fuzz_options();
  if (size > options.limits.scene_file_bytes) return "";
  Diagnostics diags;
  // Relative mesh paths resolve against scenes/, where the example models are.
  auto doc = parse_json_text(std::string(RTCLI_SOURCE_DIR) + "/scenes/fuzz.json",
                             std::string(reinterpret_cast<const char*>(data), size), diags);
  if (!doc) return diags.has_errors() ? "" : "a rejected document came with no error";
  // Its includes are not read (the fuzzer reads no files it did not write); the rest is the scene.
  const SceneSources sources(std::move(*doc));
  auto desc = parse_scene(sources, options, diags);
  if (!desc) return diags.has_errors() ? "" : "a rejected scene came with no error";
  auto scene = build_scene(*desc, sources.places(), options, diags);
  if (!scene) return diags.has_errors() ? "" : "a scene that failed to build came with no error";
  if (const std::string problem = scene->scene.bvh.check_structure(); !problem.empty()) return "BVH: " + problem;
  for (const MeshGeometry& g : scene->graph.assets->meshes)
    if (const std::string problem = g.bvh.check_structure(); !problem.empty()) return "mesh BVH: " + problem;
  RenderSettings settings = desc->render;
  settings.width = settings.height = 4;
  settings.antialias.samples = 1;
  settings.antialias.max_depth = std::min(settings.antialias.max_depth, 1);
  settings.threads = 1;
  Image image;
  render(scene->scene, settings, image);
  // A stereo camera's eyes too (off-axis windows, ODS origins), and the two images put together.
  if (const Camera& camera = scene->scene.camera; camera.stereo.enabled()) {
    const Camera right = camera.eye_camera(1);
    Image second;
    render(scene->scene, settings, second, {}, 0, RenderView{&right, 1, {}});
    if (camera.stereo.mode != StereoMode::kPair) compose_stereo(image, second, camera.stereo);
  }
  return "";
}

std::string gltf_model(const uint8_t* data, size_t size) {
  const LoadOptions options = fuzz_options();
  Diagnostics found;
  Reporter report(found, "fuzz.gltf");
  ImportError error;
  const std::vector<unsigned char> bytes(data, data + size);
  LimitUsage usage;
  auto model = import_gltf_bytes(bytes, std::string(RTCLI_SOURCE_DIR) + "/scenes/models", std::nullopt, options.limits,
                                 usage, report, error);
  if (!model) return found.has_errors() ? "" : "a rejected model came with no error";
  std::vector<TriangleMesh> meshes;
  size_t triangles = 0;
  for (const ModelPlacement& instance : placements(*model)) {
    const auto transform = make_transform(instance.to_file);
    if (!transform) continue;
    for (const ImportedPrimitive& p : model->meshes[instance.mesh]) {
      for (const uint32_t i : p.mesh.indices)
        if (i >= p.mesh.positions.size()) return "an index past the vertices survived the import";
      triangles += p.mesh.triangle_count();
      if (triangles > options.limits.triangles) return "";  // the builder refuses this; so do we
      meshes.push_back(transformed(p.mesh, *transform));
    }
  }
  PrimitiveSet prims = make_primitive_set(meshes, {});
  std::erase_if(prims.triangles, [](const PackedTriangle& t) { return !t.is_finite(); });  // the builder refuses these
  const Bvh bvh(prims, BvhBuildOptions{1});
  const std::string problem = bvh.check_structure();
  return problem.empty() ? "" : "BVH: " + problem;
}

std::string texture_file(const uint8_t* data, size_t size) {
  const auto folder = scratch_folder();
  write_bytes(folder / "texture.img", data, size);
  const std::string scene = R"({"camera": {"position": [0, 0, 3], "look_at": [0, 0, 0]},
    "lights": [{"type": "point", "position": [1, 2, 3]}],
    "materials": {"m": {"texture": "texture.img", "bump": "texture.img", "specular_texture": "texture.img"}},
    "nodes": [{"shape": "sphere", "material": "m"}]})";
  const LoadOptions options = fuzz_options();
  Diagnostics diags;
  auto doc = parse_json_text((folder / "scene.json").string(), scene, diags);
  if (!doc) return "the texture_file target's scene does not parse";
  const SceneSources sources(std::move(*doc));
  auto desc = parse_scene(sources, options, diags);
  if (!desc) return "the texture_file target's scene is refused";
  auto built = build_scene(*desc, sources.places(), options, diags);
  if (!built) return diags.has_errors() ? "" : "a scene whose texture failed came with no error";
  RenderSettings settings = desc->render;
  settings.width = settings.height = 4;
  settings.threads = 1;
  Image image;
  render(built->scene, settings, image);
  for (const Vec3& p : image.pixels)
    if (!is_finite(p)) return "a textured pixel is not finite";
  return "";
}

std::string gltf_image(const uint8_t* data, size_t size) {
  std::vector<unsigned char> bin = square_data();
  const size_t image_offset = bin.size();
  bin.insert(bin.end(), data, data + size);
  while (bin.size() % 4) bin.push_back(0);
  nlohmann::json doc = textured_square({{"bufferView", 1}, {"mimeType", "image/png"}});
  doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", 60}},
                        {{"buffer", 0}, {"byteOffset", image_offset}, {"byteLength", size}}};
  if (size == 0) doc["bufferViews"][1]["byteLength"] = 1;  // glTF needs at least one byte
  doc["buffers"] = {{{"byteLength", bin.size()}}};
  std::string json = doc.dump();
  while (json.size() % 4) json.push_back(' ');
  const auto u32 = [](std::vector<unsigned char>& out, uint32_t v) {
    for (int k = 0; k < 4; ++k) out.push_back(static_cast<unsigned char>(v >> (8 * k)));
  };
  std::vector<unsigned char> glb;
  glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
  u32(glb, 2);
  u32(glb, static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  u32(glb, static_cast<uint32_t>(json.size()));
  glb.insert(glb.end(), {'J', 'S', 'O', 'N'});
  glb.insert(glb.end(), json.begin(), json.end());
  u32(glb, static_cast<uint32_t>(bin.size()));
  glb.insert(glb.end(), {'B', 'I', 'N', '\0'});
  glb.insert(glb.end(), bin.begin(), bin.end());
  return import_and_place(glb, scratch_folder().string());
}

std::string extras_image(const uint8_t* data, size_t size) {
  const auto folder = scratch_folder();
  write_bytes(folder / "bump.img", data, size);
  nlohmann::json doc = textured_square({{"uri", "bump.img"}});
  doc["materials"][0]["extras"] = {{"rtcli_bump", {{"image", "bump.img"}, {"strength", 2}}}};
  const std::vector<unsigned char> bin = square_data();
  write_bytes(folder / "square.bin", bin.data(), bin.size());
  doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", 60}}};
  doc["buffers"] = {{{"byteLength", 60}, {"uri", "square.bin"}}};
  const std::string json = doc.dump();
  return import_and_place(std::vector<unsigned char>(json.begin(), json.end()), folder.string());
}

std::string texture_image(const uint8_t* data, size_t size) {
  const std::vector<unsigned char> bytes(data, data + size);
  for (const TextureEncoding encoding : {TextureEncoding::kSrgb, TextureEncoding::kLinear, TextureEncoding::kAlpha}) {
    LoadLimits limits;
    limits.texture_texels = uint64_t{1} << 20;
    LimitUsage usage;
    TextureError error;
    const auto texture = decode_texture(bytes, "fuzz input", encoding, limits, usage, error);
    if (!texture) {
      if (error.message.empty()) return "decode_texture failed without saying why";
      return "";
    }
    if (texture->width() < 1 || texture->height() < 1) return "a decoded texture has no texels";
    const Vec2 points[] = {{0.5f, 0.5f}, {-1e30f, 3.0f}, {1e30f, -0.25f}, {kInfinity, 0.0f}, {std::nanf(""), 1.0f}};
    for (const Vec2 uv : points)
      for (const TextureWrap wrap : {TextureWrap::kRepeat, TextureWrap::kClamp, TextureWrap::kMirror})
        for (const TextureFilter filter :
             {TextureFilter::kNearest, TextureFilter::kBilinear, TextureFilter::kTrilinear})
          for (const float footprint : {0.0f, 0.01f, 1e9f})
            if (!is_finite(texture->sample(uv, wrap, filter, footprint))) return "a texture sample is not finite";
  }
  return "";
}

void write_bytes(const std::filesystem::path& path, const uint8_t* data, size_t size) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

}  // namespace rt::fuzz
