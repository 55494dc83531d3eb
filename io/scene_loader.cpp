#include "io/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <new>

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
  std::vector<std::string> files;
  std::optional<Scene> scene = build_scene(desc, nullptr, options, diags, &files);
  if (!scene) return std::nullopt;
  const float aspect = static_cast<float>(desc.render.width) / static_cast<float>(desc.render.height);
  // A model without triangles still gets a camera and a light: it renders the background.
  const Aabb bounds = scene->bvh.bounds().empty() ? Aabb{Vec3(-1.0f), Vec3(1.0f)} : scene->bvh.bounds();
  scene->camera = Camera::framing(bounds, 40.0f, aspect);
  // A light up and to the right of the camera: shading shows the form, shadows fall behind.
  const float reach = glm::length(scene->camera.position - bounds.centre());
  PointLight light;
  light.position = scene->camera.position + reach * (0.5f * scene->camera.right + 0.6f * scene->camera.up);
  if (!is_finite(scene->camera.position) || !is_finite(light.position) || !(reach > 0.0f)) {
    diags.file_error(path,
                     "expected a model small enough to frame in single precision, found one whose extent ("
                     "from " +
                         std::to_string(bounds.lo.x) + " to " + std::to_string(bounds.hi.x) +
                         " in x) puts the camera at infinity");
    return std::nullopt;
  }
  scene->lights = {light};
  desc.camera = CameraDescription{scene->camera.position, bounds.centre(), Vec3(0.0f, 1.0f, 0.0f), 40.0f, 0.0f, {}};
  return LoadedScene{std::move(desc), std::move(*scene), std::move(files)};
}

std::optional<LoadedScene> load_json_scene(const std::string& path, const LoadOptions& options, Diagnostics& diags) {
  std::optional<JsonDocument> doc = read_json_file(path, options.limits.scene_file_bytes, diags);
  if (!doc) return std::nullopt;
  std::optional<SceneDescription> desc = parse_scene(*doc, options, diags);
  if (!desc) return std::nullopt;
  std::vector<std::string> files{path};
  std::vector<std::string> models;
  std::optional<Scene> scene = build_scene(*desc, &*doc, options, diags, &models);
  if (!scene) return std::nullopt;
  files.insert(files.end(), models.begin(), models.end());
  return LoadedScene{std::move(*desc), std::move(*scene), std::move(files)};
}

}  // namespace

bool is_gltf_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".gltf" || ext == ".glb";
}

std::optional<LoadedScene> load_scene(const std::string& path, const LoadOptions& options, Diagnostics& diags) {
  try {
    return is_gltf_path(path) ? load_gltf_model(path, options, diags) : load_json_scene(path, options, diags);
  } catch (const std::bad_alloc&) {
    diags.file_error(path, "ran out of memory while loading: the file asks for more than this machine has");
  } catch (const std::exception& e) {
    diags.file_error(path, std::string("could not be loaded: ") + e.what());
  }
  return std::nullopt;
}

}  // namespace rt
