// What a glTF import gives the rest of io/: plain description records, shared by the loader and
// the files it calls (animation, images, node parts) and by io/assemble/. Its own header, at the
// bottom of io/gltf/, so that none of those includes the loader above it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/animation/track.h"
#include "core/material.h"
#include "core/mesh.h"
#include "core/scene_graph.h"
#include "core/texture/texture.h"

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

// The world of the scene a file was exported from (the default scene's extras rtcli_world, as
// tools/blender/rtcli/export.py writes Blender's world): a colour, or an environment image.
struct ImportedWorld {
  Vec3 color{0.0f};   // a uniform world's radiance (colour x strength)
  std::string image;  // or an equirectangular .hdr/.exr, resolved against the file's folder ("": none)
  float intensity = 1.0f;
  float rotate = 0.0f;  // degrees about +Y, rtcli's convention (core/lights/environment.h)
};

struct ImportedModel {
  std::vector<std::vector<ImportedPrimitive>> meshes;  // per glTF mesh
  std::vector<ImportedNode> nodes;                     // the default scene's, parents first
  std::vector<Track> tracks;                           // Track::node indexes `nodes`
  std::vector<CameraPlacement> cameras;                // node indexes `nodes`; camera in node space
  std::vector<LightPlacement> lights;                  // KHR_lights_punctual, in node space
  float animation_end = 0.0f;                          // the last key time of all tracks, seconds
  std::vector<Material> materials;          // per glTF material (io/gltf/materials.h); texture slots index `textures`
  std::vector<std::string> material_names;  // per glTF material, as the file names them ("" if not)
  std::vector<Texture> textures;            // the images the materials use, decoded once per encoding
  std::vector<std::string> files;           // every file read: the model and its external buffers
  std::optional<ImportedWorld> world;       // the default scene's rtcli_world extras, if any
};

// What of a file to import. The constructors let a mesh name (or nothing) stand for a selection.
struct GltfSelection {
  std::optional<std::string> mesh;       // one mesh by name, on one node with an identity transform
  std::optional<std::string> animation;  // one animation by name or index; default: all of them together
  GltfSelection() = default;
  GltfSelection(std::nullopt_t) {}                                                     // NOLINT: the whole file
  GltfSelection(std::optional<std::string> mesh_name) : mesh(std::move(mesh_name)) {}  // NOLINT
  GltfSelection(std::optional<std::string> mesh_name, std::optional<std::string> animation_name)
      : mesh(std::move(mesh_name)), animation(std::move(animation_name)) {}
};

// Not a problem in the file but in the request: the file has no mesh, or no animation, of the
// name asked for. (Problems in the file go to the import's Reporter.)
struct ImportError {
  bool unknown_mesh = false;
  bool unknown_animation = false;
  std::string message;  // the names there are: "\"a\", \"b\"" (the first 20)
};

}  // namespace rt
