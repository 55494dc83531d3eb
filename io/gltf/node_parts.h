// What a glTF node carries besides its mesh, read into ImportedModel: its local transform, its
// camera, its KHR_lights_punctual light and its EXT_mesh_gpu_instancing copies. Each returns
// false with a sentence in `error` for a file that breaks the specification; what rtcli merely
// does not model is a warning in out.warnings.
#pragma once

#include <string>

#include "io/base/load_options.h"
#include "io/base/reporter.h"
#include "io/gltf/imported_model.h"

namespace tinygltf {
class Model;
class Node;
}  // namespace tinygltf

namespace rt {

// The node's local transform as glTF gives it: a matrix, or translation, rotation and scale.
void read_node_transform(const tinygltf::Node& node, ImportedNode& out);

// Each reads the node at pointer `at` ("/nodes/3") and reports what is wrong with it there.

// The node's camera, placed on node `index` of out.nodes.
bool import_camera(const tinygltf::Model& model, const tinygltf::Node& node, const std::string& at, int32_t index,
                   ImportedModel& out, Reporter& report);

// The node's KHR_lights_punctual light, placed on node `index` of out.nodes.
bool import_light(const tinygltf::Model& model, const tinygltf::Node& node, const std::string& at, int32_t index,
                  ImportedModel& out, Reporter& report);

// EXT_mesh_gpu_instancing: out.instancing gets one node-space matrix per copy.
bool import_instancing(const tinygltf::Model& model, const tinygltf::Node& node, const std::string& at,
                       const LoadLimits& limits, ImportedNode& out, Reporter& report);

}  // namespace rt
