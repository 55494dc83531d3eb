#include "io/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "io/json_document.h"
#include "io/scene_builder.h"
#include "io/scene_parser.h"

namespace rt {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::optional<LoadedScene> load_gltf_model(const std::string& path, const LoadOptions& options, Diagnostics& diags) {
  SceneDescription desc;
  desc.path = path;
  desc.background = Vec3(0.05f);
  desc.ambient = Vec3(0.1f);
  NodeDescription node;
  node.mesh = MeshReference{path, path, std::nullopt, ""};
  desc.nodes.push_back(std::move(node));
  std::optional<Scene> scene = build_scene(desc, nullptr, options, diags);
  if (!scene) return std::nullopt;
  const float aspect = static_cast<float>(desc.render.width) / static_cast<float>(desc.render.height);
  scene->camera = Camera::framing(scene->bvh.bounds(), 40.0f, aspect);
  // A light up and to the right of the camera: shading shows the form, shadows fall behind.
  const float reach = glm::length(scene->camera.position - scene->bvh.bounds().centre());
  PointLight light;
  light.position = scene->camera.position + reach * (0.5f * scene->camera.right + 0.6f * scene->camera.up);
  scene->lights = {light};
  desc.camera = CameraDescription{scene->camera.position, scene->bvh.bounds().centre(), Vec3(0.0f, 1.0f, 0.0f), 40.0f};
  return LoadedScene{std::move(desc), std::move(*scene)};
}

}  // namespace

bool is_gltf_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".gltf" || ext == ".glb";
}

std::optional<LoadedScene> load_scene(const std::string& path, const LoadOptions& options, Diagnostics& diags) {
  if (is_gltf_path(path)) return load_gltf_model(path, options, diags);
  std::optional<JsonDocument> doc = read_json_file(path, diags);
  if (!doc) return std::nullopt;
  std::optional<SceneDescription> desc = parse_scene(*doc, options, diags);
  if (!desc) return std::nullopt;
  std::optional<Scene> scene = build_scene(*desc, &*doc, options, diags);
  if (!scene) return std::nullopt;
  return LoadedScene{std::move(*desc), std::move(*scene)};
}

}  // namespace rt
