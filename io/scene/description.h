// What a scene file says, checked and typed but not yet built: names unresolved into geometry,
// files not yet loaded, transforms still local. Each record keeps the JSON pointer it came from,
// so the builder can report problems it finds later (an unreadable glTF file, a transform that
// becomes singular) at the right place in the file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/animation/track.h"
#include "core/camera.h"
#include "core/csg/csg_spans.h"
#include "core/lights/light.h"
#include "core/material.h"
#include "core/render_settings.h"
#include "core/shapes/analytic_shape.h"
#include "io/scene/texture_parser.h"

namespace rt {

struct CameraDescription {
  Vec3 position{0.0f, 0.0f, 5.0f};
  Vec3 look_at{0.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};
  CameraProjection projection = CameraProjection::kPerspective;
  float fov_degrees = 45.0f;            // vertical (perspective); across the image circle (fisheye, default 180)
  float aperture = 0.0f;                // lens radius; 0 = pinhole
  std::optional<float> focus_distance;  // default: the distance to look_at
  float ortho_width = 2.0f;             // orthographic
  Vec2 shift{0.0f};
  StereoSettings stereo;
  std::optional<float> convergence;  // default: the focus distance
};

struct MaterialDescription {
  std::string name;
  Material material;  // texture slots hold their mappings; the builder fills in the texture indices
  std::optional<TextureFileReference> texture, specular_texture, bump, normal_map;
};

// A triangle mesh taken from a glTF file: one named mesh, or every mesh the file's scene uses.
// "materials": {"<a material's name in the file>": "<a material under /materials>"}.
struct MaterialOverride {
  std::string file_material;
  uint32_t material = 0;  // index into SceneDescription::materials
  std::string pointer;    // of the entry
};

struct MeshReference {
  std::string file;           // as written in the scene
  std::string resolved_path;  // relative paths resolved against the scene file's folder
  std::optional<std::string> mesh_name;
  std::vector<MaterialOverride> materials;
  std::string pointer;                   // of the "mesh" object
  std::optional<std::string> animation;  // one of the file's animations, by name or index; default: all
};

// A node's parent-from-node transform as written: translate / rotate / scale, or a fixed matrix.
struct NodeTransform {
  Trs trs;
  std::optional<Mat4> matrix;

  Mat4 local() const { return matrix ? *matrix : trs.matrix(); }
};

struct NodeDescription {
  std::string name;
  std::string pointer;
  NodeTransform transform;
  std::optional<ShapeKind> shape;
  std::optional<MeshReference> mesh;
  std::optional<uint32_t> material;  // index into SceneDescription::materials
  // A CSG node: its children are the operands (difference: the first minus the others), and its
  // material is the one of the operands that have none.
  std::optional<CsgOp> csg;
  std::vector<NodeDescription> children;
};

// One "animation" track: keys for one part of a named node's transform, times in seconds.
struct TrackDescription {
  std::string node;     // the node's name
  std::string pointer;  // of the track
  Track track;          // Track::node is resolved by the builder
};

struct AnimationDescription {
  std::string pointer;
  float fps = 30.0f;
  std::optional<int> first_frame, last_frame;  // default: 0 to the last key's frame
  std::vector<TrackDescription> tracks;
};

// background: {"environment": FILE, "intensity": k, "rotate": degrees}: an HDR image around the scene.
struct EnvironmentReference {
  std::string file;           // as written
  std::string resolved_path;  // against the scene file's folder
  float intensity = 1.0f;     // multiplies the image's radiance
  float rotate = 0.0f;        // degrees about +Y
  std::string pointer;        // of the file name
};

struct SceneDescription {
  std::string path;  // the scene file, as named by the user
  RenderSettings render;
  CameraDescription camera;
  Vec3 background{0.0f};
  std::optional<EnvironmentReference> environment;  // replaces `background` when given
  Vec3 ambient{0.0f};
  std::vector<MaterialDescription> materials;
  std::vector<Light> lights;
  std::vector<std::string> light_pointers;  // per light: where it is described
  std::vector<NodeDescription> nodes;
  std::optional<AnimationDescription> animation;
  // A glTF file given alone: the camera frames the first frame's bounds, a point light sits
  // beside it, unless the file brings its own.
  bool frame_the_model = false;
};

}  // namespace rt
