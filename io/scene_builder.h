// SceneDescription -> the immutable Scene: loads each glTF file once, composes node transforms
// down the tree, turns shapes and meshes into world-space primitives and builds the BVH.
// Problems (an unreadable glTF file, a world transform that became singular, a shape beyond
// the float range, more triangles or instances than the limits allow) are recorded against the
// scene file at the node's JSON pointer.
#pragma once

#include <optional>

#include "core/scene.h"
#include "io/diagnostics.h"
#include "io/json_document.h"
#include "io/load_options.h"
#include "io/scene_description.h"

namespace rt {

// `source` is the scene file the description came from, for error positions (may be null).
// `files`, if given, receives every file read (glTF models and their buffers).
std::optional<Scene> build_scene(const SceneDescription& desc, const JsonDocument* source, const LoadOptions& options,
                                 Diagnostics& diags, std::vector<std::string>* files = nullptr);

}  // namespace rt
