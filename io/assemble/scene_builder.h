// SceneDescription -> SceneGraph, in two stages. "Load once": the scene's materials and
// textures, and every glTF file a node names (read once however often it is placed), whose
// primitives become meshes in their object space, each with its own BVH. "Place": the scene's
// nodes and the files' node trees become one node tree with translation, rotation and scale
// kept apart, the animation tracks are resolved to its nodes, and SceneGraph::at(t) gives the
// frame at any time. Problems (an unreadable file, a world transform that became singular, a
// shape beyond the float range, more triangles or instances than the limits allow, a track on
// an unknown node) are recorded against the scene file at the JSON pointer concerned.
#pragma once

#include <optional>

#include "core/scene_graph.h"
#include "io/base/diagnostics.h"
#include "io/base/load_options.h"
#include "io/base/reporter.h"
#include "io/scene/description.h"

namespace rt {

struct BuiltScene {
  SceneGraph graph;
  int frame = 0;  // options.frame, or the timeline's first frame
  Scene scene;    // that frame, placed; without a BVH when options.build_bvh is false
};

// `places` finds the description's pointers in the files it came from (io/scene/scene_sources.h);
// empty for a description the user never wrote (a model on its own): its reports show none.
// `files`, if given, receives every file read (glTF models, their buffers, textures).
std::optional<BuiltScene> build_scene(const SceneDescription& desc, PlaceFinder places, const LoadOptions& options,
                                      Diagnostics& diags, std::vector<std::string>* files = nullptr);

}  // namespace rt
