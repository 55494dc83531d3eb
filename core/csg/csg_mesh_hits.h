// What a CSG solid needs of a mesh operand's own BVH: every crossing of a ray with the mesh. The
// BVH (core/accel/, the layer above) holds CSG solids among its primitives, so CSG may not include
// it; it declares the walk it needs here, and core/accel/bvh.cpp defines it, through the kernels
// of the instruction set the mesh's BVH was built for (--isa), as every other query.
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace rt {

class Bvh;

using MeshHitVisitorFn = bool (*)(void* visitor, const Hit& hit);

// Calls visit(visitor, hit) for every crossing of `ray` with the triangles of `mesh` (an object
// space mesh BVH), until it returns true; returns whether it was stopped.
bool visit_mesh_hits(const Bvh& mesh, const Ray& ray, MeshHitVisitorFn visit, void* visitor);

template <class Visitor>
bool visit_mesh_hits(const Bvh& mesh, const Ray& ray, Visitor& visitor) {
  return visit_mesh_hits(
      mesh, ray, [](void* v, const Hit& hit) { return (*static_cast<Visitor*>(v))(hit); }, &visitor);
}

}  // namespace rt
