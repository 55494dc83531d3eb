// The one entry point from a file name to a render-ready Scene.
//   .json        a scene file (schemas/scene.schema.json)
//   .gltf/.glb   a model on its own: the whole file's default scene, framed by a default camera
//                from the front and above, lit by a point light beside the camera
// Every problem goes into `diags`, sorted by position; nothing comes back if any of them is an
// error. Every check runs (parser, builder, JSON Schema) whatever the others found, so render and
// validate (which is this without a BVH) report the same problems. Loading never
// throws: running out of memory or any other exception on the way becomes an error about the file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/render_settings.h"
#include "core/scene_graph.h"
#include "io/base/diagnostics.h"
#include "io/base/load_options.h"

namespace rt {

// What a render needs of a loaded scene, and no more.
struct LoadedScene {
  RenderSettings settings;          // the file's render block (defaults for a model on its own)
  SceneGraph graph;                 // every frame: graph.at(graph.pose(frame), ...), or FrameScenes
  int frame = 0;                    // the frame `scene` shows: LoadOptions::frame, or the timeline's first
  Scene scene;                      // that frame, placed
  std::vector<std::string> inputs;  // every file read: the scene, glTF models, their buffers
};

std::optional<LoadedScene> load_scene(const std::string& path, const LoadOptions& options, Diagnostics& diags);

bool is_gltf_path(const std::string& path);

}  // namespace rt
