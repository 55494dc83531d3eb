#include "io/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <new>

#include "io/assemble/scene_builder.h"
#include "io/json/document.h"
#include "io/json/locate.h"
#include "io/json/reader.h"
#include "io/scene/scene_parser.h"
#include "io/scene/schema.h"

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
  desc.background = Vec3(kModelBackground);
  desc.ambient = Vec3(0.0f);
  desc.frame_the_model = true;
  NodeDescription node;
  node.mesh = MeshReference{path, path, std::nullopt, {}, "", options.animation};
  desc.nodes.push_back(std::move(node));
  std::vector<std::string> files;
  std::optional<BuiltScene> built = build_scene(desc, {}, options, diags, &files);
  if (!built) return std::nullopt;
  return LoadedScene{desc.render, std::move(built->graph), built->frame, std::move(built->scene), std::move(files)};
}

// Schema failures at values the parser or builder already reported (or above or below them)
// are not repeated: their messages say more. Any other gets the prefix "schema:". Each file is
// checked on its own; what the scene requires (a camera, nodes) may come from any of them, and
// the parser checks it of them together.
void check_schema(const SceneSources& sources, Diagnostics& diags) {
  const std::vector<Diagnostic> found = diags.all();
  const bool together = sources.files().size() > 1;
  for (const auto& file : sources.files()) {
    const JsonReader reader(file->doc, diags);
    for (const SchemaError& e : check_scene_schema(file->doc.root)) {
      if (together && e.pointer.empty() && e.message.rfind("Missing required property", 0) == 0) continue;
      // A template's shape may take its material where it is placed (the parser checks each placement).
      if (pointer_is_inside(e.pointer, "/templates") && e.message == "Missing dependency 'material'.") continue;
      const bool reported = std::any_of(found.begin(), found.end(), [&](const Diagnostic& d) {
        return d.severity == Severity::kError && d.file == file->doc.path &&
               pointers_related(d.pointer, e.pointer);  // "" contains every pointer
      });
      if (!reported) reader.error(e.pointer, "schema: " + e.message);
    }
  }
}

// Every check runs whatever the others found, so one run reports every problem: a parse error
// does not stop the textures, glTF files and transforms from being checked (without a BVH).
std::optional<LoadedScene> load_json_scene(const std::string& path, const LoadOptions& options, Diagnostics& diags) {
  std::optional<SceneSources> sources = read_scene_sources(path, options.limits, diags);
  if (!sources) return std::nullopt;
  const SceneDescription desc = parse_scene_partial(*sources, options, diags);
  LoadOptions build_options = options;
  build_options.build_bvh = options.build_bvh && !diags.has_errors();
  std::vector<std::string> models;
  std::optional<BuiltScene> built = build_scene(desc, sources->places(), build_options, diags, &models);
  check_schema(*sources, diags);
  if (!built || diags.has_errors()) return std::nullopt;
  std::vector<std::string> files = sources->paths();
  files.insert(files.end(), models.begin(), models.end());
  return LoadedScene{desc.render, std::move(built->graph), built->frame, std::move(built->scene), std::move(files)};
}

}  // namespace

bool is_gltf_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".gltf" || ext == ".glb";
}

std::optional<LoadedScene> load_scene(const std::string& path, const LoadOptions& options, Diagnostics& diags) {
  std::optional<LoadedScene> loaded;
  try {
    loaded = is_gltf_path(path) ? load_gltf_model(path, options, diags) : load_json_scene(path, options, diags);
  } catch (const std::bad_alloc&) {
    diags.file_error(path, "ran out of memory while loading: the file asks for more than this machine has");
    loaded.reset();
  } catch (const std::exception& e) {
    diags.file_error(path, std::string("could not be loaded: ") + e.what());
    loaded.reset();
  }
  diags.sort_by_position();
  return loaded;
}

}  // namespace rt
