// What a scene file says, checked and typed but not yet built: names unresolved into geometry,
// files not yet loaded, transforms still local. Each record keeps the JSON pointer it came from,
// so the builder can report problems it finds later (an unreadable glTF file, a transform that
// becomes singular) at the right place in the file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/lights/light.h"
#include "core/material.h"
#include "core/render_settings.h"
#include "core/shapes/analytic_shape.h"
#include "io/texture_parser.h"

namespace rt {

struct CameraDescription {
  Vec3 position{0.0f, 0.0f, 5.0f};
  Vec3 look_at{0.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};
  float fov_degrees = 45.0f;            // vertical
  float aperture = 0.0f;                // lens radius; 0 = pinhole
  std::optional<float> focus_distance;  // default: the distance to look_at
};

struct MaterialDescription {
  std::string name;
  Material material;  // texture slots hold their mappings; the builder fills in the texture indices
  std::optional<TextureFileReference> texture, specular_texture, bump, normal_map;
};

// A triangle mesh taken from a glTF file: one named mesh, or every mesh the file's scene uses.
struct MeshReference {
  std::string file;           // as written in the scene
  std::string resolved_path;  // relative paths resolved against the scene file's folder
  std::optional<std::string> mesh_name;
  std::string pointer;  // of the "mesh" object
};

struct NodeDescription {
  std::string name;
  std::string pointer;
  Mat4 local{1.0f};  // parent-from-node transform
  std::optional<ShapeKind> shape;
  std::optional<MeshReference> mesh;
  std::optional<uint32_t> material;  // index into SceneDescription::materials
  std::vector<NodeDescription> children;
};

struct SceneDescription {
  std::string path;  // the scene file, as named by the user
  RenderSettings render;
  CameraDescription camera;
  Vec3 background{0.0f};
  Vec3 ambient{0.0f};
  std::vector<MaterialDescription> materials;
  std::vector<Light> lights;
  std::vector<NodeDescription> nodes;
};

}  // namespace rt
