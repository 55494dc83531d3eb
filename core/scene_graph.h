// The scene as loaded, before it is placed in time: shared assets, a node tree whose local
// transforms stay as translation, rotation and scale, what each node carries (a shape, mesh
// primitives, a camera, lights), and the animation tracks that move nodes. A frame is placed in
// two steps: pose(frame) turns the frame number into a time (the timeline's one rule) and
// evaluates the tracks and the tree once, into every node's world transform; at(pose) builds one
// immutable Scene from it, reusing every mesh's object-space BVH and building only the top
// level over shapes and mesh instances (core/frame_scenes.h walks a range of frames).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/animation/track.h"
#include "core/csg_template.h"
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

// The node tree evaluated at one moment: the tracks applied, every node's world transform.
struct Pose {
  float seconds = 0.0f;
  std::vector<Mat4> world;  // per node
};

// Why a node's geometry was left out of a frame.
struct PlacementIssue {
  enum Kind { kSingular, kBeyondRange } kind;
  uint32_t node;
};

struct SceneGraph {
  std::shared_ptr<const SceneAssets> assets = std::make_shared<const SceneAssets>();
  std::vector<SceneNode> nodes;
  // CSG solids; their operand nodes carry no geometry of their own in `nodes`.
  std::vector<CsgTemplate> csgs;
  std::vector<Track> tracks;
  Timeline timeline;
  bool animated = false;  // the scene or its files define an animation
  CameraPlacement camera;
  std::vector<LightPlacement> lights;
  Environment background;
  Vec3 ambient{0.0f};

  // The tree at frame `frame` of the timeline (time frame / fps), or at any time.
  Pose pose(int frame) const { return pose_at(timeline.seconds(frame)); }
  Pose pose_at(float seconds) const;
  // Whether the timeline's last frame shows its first again (every node where it started, as a
  // turntable's 360 degrees do): a loop then plays one frame fewer, or the start shows twice.
  bool ends_where_it_starts() const;
  // The shapes, mesh instances and CSG solids where the pose puts them (what at() builds its BVH over).
  // Geometry whose world transform is singular (animated to a zero scale: glTF's way of hiding
  // a part) or that reaches beyond the float range is left out, and said in `issues` when given.
  PrimitiveSet place(const Pose& pose, std::vector<PlacementIssue>* issues = nullptr) const;
  // The camera where the pose puts it.
  Camera camera_at(const Pose& pose) const;
  // The frame: the placed primitives in a BVH (the instances it can, flattened:
  // core/flatten_instances.h), the camera and lights where the pose puts them.
  Scene at(const Pose& pose, PrimitiveSet placed, const BvhBuildOptions& options) const;
  Scene at(const Pose& pose, const BvhBuildOptions& options) const { return at(pose, place(pose), options); }
};

// A light moved by a node's world transform.
Light transform_light(const Light& light, const Mat4& m);

}  // namespace rt
