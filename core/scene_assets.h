// What a scene loads once and every frame of an animation shares: materials, textures, and each
// triangle mesh in its object space with its own BVH. Frames (core/scene.h) hold a shared,
// read-only pointer to it and place its meshes by reference, so a frame costs only its
// top-level BVH.
#pragma once

#include <vector>

#include "core/accel/bvh.h"
#include "core/material.h"
#include "core/mesh.h"
#include "core/texture/texture.h"

namespace rt {

struct MeshGeometry {
  TriangleMesh mesh;  // object space
  Bvh bvh;            // over mesh's triangles, in object space
};

struct SceneAssets {
  std::vector<Material> materials;
  std::vector<Texture> textures;  // what materials' texture slots index, each file loaded once
  // Never resized once frames exist: instances point at these BVHs.
  std::vector<MeshGeometry> meshes;
};

}  // namespace rt
