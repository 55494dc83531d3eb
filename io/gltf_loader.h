// A glTF 2.0 file (.gltf with external or embedded buffers, or .glb) as description records:
// its default scene's node tree with each local transform kept as translation, rotation and
// scale, the meshes the nodes use, materials, textures and animation tracks. Every primitive
// in triangle, strip or fan mode is imported; points and lines are skipped with a warning.
// Positions stay in each mesh's own space, so a mesh used by several nodes is read once. Everything a file says is
// checked against the specification and the limits before it is used (io/gltf_file.h, io/gltf_accessor.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/animation/track.h"
#include "core/material.h"
#include "core/mesh.h"
#include "core/scene_graph.h"
#include "core/texture/texture.h"
#include "io/load_options.h"

namespace rt {

struct ImportedPrimitive {
  TriangleMesh mesh;  // in the mesh's object space
  int material = -1;  // index into ImportedModel::materials, -1 = none
};

struct ImportedNode {
  std::string name;
  int32_t parent = -1;  // index into ImportedModel::nodes, always lower than the node's own
  Trs trs;
  std::optional<Mat4> matrix;    // the node's "matrix" instead of TRS
  int32_t mesh = -1;             // index into ImportedModel::meshes
  int32_t gltf_index = -1;       // the node's index in the file, for messages
  std::vector<Mat4> instancing;  // EXT_mesh_gpu_instancing: node-space placements of the mesh
};

// Where a mesh goes in the file's space: a node's world transform at rest.
struct ModelPlacement {
  size_t mesh = 0;
  Mat4 to_file{1.0f};
};

struct ImportedModel {
  std::vector<std::vector<ImportedPrimitive>> meshes;  // per glTF mesh
  std::vector<ImportedNode> nodes;                     // the default scene's, parents first
  std::vector<Track> tracks;                           // Track::node indexes `nodes`
  std::vector<CameraPlacement> cameras;                // node indexes `nodes`; camera in node space
  std::vector<LightPlacement> lights;                  // KHR_lights_punctual, in node space
  float animation_end = 0.0f;                          // the last key time of all tracks, seconds
  std::vector<Material> materials;          // per glTF material (io/gltf_materials.h); texture slots index `textures`
  std::vector<std::string> material_names;  // per glTF material, as the file names them ("" if not)
  std::vector<Texture> textures;            // the images the materials use, decoded once per encoding
  std::vector<std::string> warnings;
  std::vector<std::string> files;  // every file read: the model and its external buffers
};

struct ImportError {
  std::string message;        // completes "could not be loaded: ..." or "has no mesh named ..."
  bool unknown_mesh = false;  // the file loaded, but has no mesh of the requested name
  bool over_limit = false;    // the file is fine, but the scene's limits have no room for it
};

// Every node with a mesh, at rest (the tracks not applied).
std::vector<ModelPlacement> placements(const ImportedModel& model);

// With mesh_name: that mesh only, on one node with an identity transform. Without: every mesh the file's
// default scene places, at its node transforms (or every mesh once if the file has no scene).
// Vertices, triangles, texels and animation keys are checked against what `usage` says the scene
// has left of `limits` before they are read or decoded, and added to it.
std::optional<ImportedModel> import_gltf(const std::string& path, const std::optional<std::string>& mesh_name,
                                         const LoadLimits& limits, LimitUsage& usage, ImportError& error);
// A model on its own: nothing else counts against the limits.
inline std::optional<ImportedModel> import_gltf(const std::string& path, const std::optional<std::string>& mesh_name,
                                                const LoadLimits& limits, ImportError& error) {
  LimitUsage usage;
  return import_gltf(path, mesh_name, limits, usage, error);
}

// The same from the file's bytes already in memory; external buffers resolve against base_dir.
std::optional<ImportedModel> import_gltf_bytes(const std::vector<unsigned char>& bytes, const std::string& base_dir,
                                               const std::optional<std::string>& mesh_name, const LoadLimits& limits,
                                               LimitUsage& usage, ImportError& error);

}  // namespace rt
