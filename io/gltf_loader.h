// Triangle meshes from a glTF 2.0 file (.gltf with external or embedded buffers, or .glb).
// Every primitive in triangle, strip or fan mode is imported; points and lines are skipped
// with a warning. Positions stay in the glTF file's own space; instances say where each mesh
// goes, so a mesh used by several nodes is read once. Everything a file says is checked against
// the specification and the limits before it is used (io/gltf_file.h, io/gltf_accessor.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/material.h"
#include "core/mesh.h"
#include "core/texture/texture.h"
#include "io/load_options.h"

namespace rt {

struct ImportedPrimitive {
  TriangleMesh mesh;  // mesh.material unused here: see `material`
  int material = -1;  // index into ImportedModel::materials, -1 = none
};

struct MeshInstance {
  size_t mesh = 0;     // index into ImportedModel::meshes
  Mat4 to_file{1.0f};  // the glTF node's world transform
};

struct ImportedModel {
  std::vector<std::vector<ImportedPrimitive>> meshes;  // per glTF mesh
  std::vector<MeshInstance> instances;
  std::vector<Material> materials;  // per glTF material, mapped by pbr_to_phong; texture slots index `textures`
  std::vector<Texture> textures;    // the images the materials use (normal maps), decoded once each
  std::vector<std::string> warnings;
  std::vector<std::string> files;  // every file read: the model and its external buffers
};

struct ImportError {
  std::string message;        // completes "could not be loaded: ..." or "has no mesh named ..."
  bool unknown_mesh = false;  // the file loaded, but has no mesh of the requested name
};

// With mesh_name: that mesh only, with an identity transform. Without: every mesh the file's
// default scene places, at its node transforms (or every mesh once if the file has no scene).
std::optional<ImportedModel> import_gltf(const std::string& path, const std::optional<std::string>& mesh_name,
                                         const LoadLimits& limits, ImportError& error);

// The same from the file's bytes already in memory; external buffers resolve against base_dir.
std::optional<ImportedModel> import_gltf_bytes(const std::vector<unsigned char>& bytes, const std::string& base_dir,
                                               const std::optional<std::string>& mesh_name, const LoadLimits& limits,
                                               ImportError& error);

}  // namespace rt
