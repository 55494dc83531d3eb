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
  Bvh bvh;            // over mesh's triangles, in object space (none when io builds no BVH: validate)
  Aabb bounds;        // of the triangles' vertices, in object space, BVH or not
};

// The coverage test of one mesh placed with one alpha-masked material.
struct MaskedPlacement {
  uint32_t mesh = 0, material = 0;
  AlphaCutout cutout;
};

struct SceneAssets {
  std::vector<Material> materials;
  std::vector<Texture> textures;  // what materials' texture slots index, each file loaded once
  // Never resized once frames exist: instances point at these BVHs.
  std::vector<MeshGeometry> meshes;
  // Point into `meshes` and `textures`: made by add_mask() once those are final and the assets
  // are where they will stay (behind their shared pointer).
  std::vector<MaskedPlacement> masks;

  SceneAssets() = default;
  SceneAssets(SceneAssets&&) = default;
  SceneAssets& operator=(SceneAssets&&) = default;
  SceneAssets(const SceneAssets&) = delete;  // a copy's masks would point into the original

  // Adds the coverage test of `mesh` placed with `material`, if that material is alpha-masked
  // and the pair has none yet. `stochastic_blend`: a BLEND material's coverage is a probability
  // (the path tracer), not cut at 0.5.
  void add_mask(uint32_t mesh, uint32_t material, bool stochastic_blend);
  // The test for that pair, or null: drawn solid.
  const AlphaCutout* mask(uint32_t mesh, uint32_t material) const;
};

}  // namespace rt
