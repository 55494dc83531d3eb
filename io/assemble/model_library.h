// The glTF files a scene places, each read once however often it is placed ("load once"): their
// primitives become meshes in SceneAssets, in their object space, each with its own BVH
// (counted against the triangle limit once); their materials and images join the scene's, with
// texture slots renumbered. The builder then grafts a file's node tree wherever a node names it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/scene_assets.h"
#include "io/assemble/texture_library.h"
#include "io/base/load_options.h"
#include "io/base/reporter.h"
#include "io/gltf/loader.h"
#include "io/scene/description.h"

namespace rt {

struct LoadedPrimitive {
  uint32_t geometry;  // index into SceneAssets::meshes
  uint32_t material;  // into SceneAssets::materials
  int file_material;  // the file's own index (-1: none), for overrides by name
};

struct LoadedModel {
  ImportedModel model;                               // its nodes, tracks, cameras, lights (meshes moved out)
  std::vector<std::vector<LoadedPrimitive>> meshes;  // per glTF mesh
};

class ModelLibrary {
 public:
  ModelLibrary(SceneAssets& assets, TextureLibrary& textures, const LoadOptions& options, LimitUsage& usage,
               const BvhBuildOptions& bvh_options, std::vector<std::string>& files, Reporter& report);

  // The file (or its one named mesh) that `ref` names, loaded the first time; null if it cannot
  // be. Problems are reported at ref's pointer in the scene file, once, each with its place in
  // the glTF file; a limit stops `report`.
  const LoadedModel* load(const MeshReference& ref);

 private:
  // `built`: the mesh's BVH from an earlier load (io/assemble/load_cache.h), else built here.
  bool add_geometry(TriangleMesh mesh, const MeshReference& ref, const Bvh* built = nullptr);
  void add_materials(ImportedModel& model);
  uint32_t default_material();

  SceneAssets& assets_;
  TextureLibrary& textures_;
  const LoadOptions& options_;
  LimitUsage& usage_;  // the scene's, shared with the texture library
  const BvhBuildOptions& bvh_options_;
  std::vector<std::string>& files_;                           // every file read (LoadedScene::inputs)
  Reporter& report_;                                          // on the scene file
  std::map<std::string, std::optional<LoadedModel>> models_;  // by path and mesh name; empty: failed
  std::optional<uint32_t> default_material_;
};

}  // namespace rt
