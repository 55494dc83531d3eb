// A triangle mesh placed in the world: the mesh's own BVH, built once in its object space, under
// a transform. The top-level BVH holds instances next to analytic shapes and CSG solids; a ray that reaches one
// is moved into object space (its direction not renormalised, so t means the same in both spaces)
// and handed to the mesh's BVH. A mesh used by many nodes, or by every frame of an animation, is
// stored and indexed once. A flattened instance is walked another way: its triangles, moved to
// world space, are the top level's own (core/flatten_instances.h), and a hit on one is named as
// the instance's all the same.
#pragma once

#include <cstdint>

#include "core/aabb.h"
#include "core/transform.h"

namespace rt {

class Bvh;
struct AlphaCutout;

struct MeshInstance {
  const Bvh* bvh = nullptr;  // object space, triangles only (ids = the mesh's triangle indices)
  Transform transform;
  Aabb bounds;                          // world space: the BVH's box through the transform
  uint32_t mesh = 0;                    // which mesh of the scene's assets, for surface records
  uint32_t material = 0;                // the placement's material (a mesh can be placed with several)
  const AlphaCutout* cutout = nullptr;  // an alpha-masked or single-sided material's test; null: solid
  // Its triangles are in the top level's own list, in world space (PrimitiveSet::owners names
  // them as this instance's): the top-level tree holds them, not the instance.
  bool flattened = false;
};

}  // namespace rt
