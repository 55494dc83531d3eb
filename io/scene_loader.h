// The one entry point from a file name to a render-ready Scene.
//   .json        a scene file (schemas/scene.schema.json)
//   .gltf/.glb   a model on its own: the whole file's default scene, framed by a default camera
//                from the front and above, lit by a point light beside the camera
// Every problem goes into `diags`; nothing comes back if any of them is an error. Loading never
// throws: running out of memory or any other exception on the way becomes an error about the file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/scene_graph.h"
#include "io/base/diagnostics.h"
#include "io/base/load_options.h"
#include "io/scene/description.h"

namespace rt {

struct LoadedScene {
  SceneDescription description;     // render settings and what the file said
  SceneGraph graph;                 // every frame: graph.at(graph.timeline.seconds(frame), ...)
  Scene scene;                      // the first frame
  std::vector<std::string> inputs;  // every file read: the scene, glTF models, their buffers
};

std::optional<LoadedScene> load_scene(const std::string& path, const LoadOptions& options, Diagnostics& diags);

bool is_gltf_path(const std::string& path);

}  // namespace rt
