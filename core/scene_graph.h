// The scene as loaded, before it is placed in time: shared assets, a node tree whose local
// transforms stay as translation, rotation and scale, what each node carries (a shape, mesh
// primitives, a camera, lights), and the animation tracks that move nodes. at(t) places it:
// it evaluates the tracks and the tree at time t and builds one immutable Scene, reusing every
// mesh's object-space BVH and building only the top level over shapes and mesh instances.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/animation/track.h"
#include "core/scene.h"

namespace rt {

struct NodeMesh {
  uint32_t mesh = 0;  // index into SceneAssets::meshes
  uint32_t material = 0;
};

struct SceneNode {
  std::string name;
  int32_t parent = -1;         // always lower than the node's own index: parents come first
  Trs trs;                     // the local transform, unless `matrix` is given
  std::optional<Mat4> matrix;  // a fixed local transform instead (tracks cannot move it)
  std::optional<ShapeKind> shape;
  uint32_t shape_material = 0;
  std::vector<NodeMesh> meshes;  // the primitives of a glTF mesh, each with its material
  // EXT_mesh_gpu_instancing: the shape and meshes are placed once per matrix (in node space).
  // Empty: once, at the node.
  std::vector<Mat4> instancing;

  bool has_geometry() const { return shape.has_value() || !meshes.empty(); }
};

// A camera fixed in the world (node < 0), or carried by a node: then `camera` is given in the
// node's space (glTF's: at the origin, looking down -Z with +Y up).
struct CameraPlacement {
  std::string name;
  Camera camera;
  int32_t node = -1;
};

// A light fixed in the world (node < 0), or given in the space of the node that carries it.
struct LightPlacement {
  Light light;
  int32_t node = -1;
};

// Frames first..last (inclusive) at `fps`; frame f shows time f / fps seconds.
struct Timeline {
  float fps = 30.0f;
  int first_frame = 0;
  int last_frame = 0;

  float seconds(int frame) const { return static_cast<float>(frame) / fps; }
  int frame_count() const { return last_frame - first_frame + 1; }
};

// Why a node's geometry was left out of a frame.
struct PlacementIssue {
  enum Kind { kSingular, kBeyondRange } kind;
  uint32_t node;
};

struct SceneGraph {
  std::shared_ptr<const SceneAssets> assets = std::make_shared<const SceneAssets>();
  std::vector<SceneNode> nodes;
  std::vector<Track> tracks;
  Timeline timeline;
  bool animated = false;  // the scene or its files define an animation
  CameraPlacement camera;
  std::vector<LightPlacement> lights;
  Vec3 background{0.0f};
  Vec3 ambient{0.0f};

  // Every node's world transform at `seconds`, the tracks applied.
  std::vector<Mat4> world_transforms(float seconds) const;
  // The shapes and mesh instances where they are at `seconds` (what at() builds its BVH over).
  PrimitiveSet place(float seconds, std::vector<PlacementIssue>* issues = nullptr) const;
  // The frame at `seconds`. Geometry whose world transform is singular at that time (animated
  // to a zero scale: glTF's way of hiding a part) or that reaches beyond the float range is left
  // out, and said in `issues` when given.
  Scene at(float seconds, const BvhBuildOptions& options, std::vector<PlacementIssue>* issues = nullptr) const;
  // The frame for the placed primitives, with the camera and lights at `seconds`.
  Scene at(float seconds, const PrimitiveSet& placed, const BvhBuildOptions& options) const;
};

// A light moved by a node's world transform.
Light transform_light(const Light& light, const Mat4& m);

}  // namespace rt
