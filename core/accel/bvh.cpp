// What a placed mesh instance is, and the mesh walk CSG solids ask for (core/csg/csg_mesh_hits.h). The queries
// themselves are the kernels of core/accel/bvh_kernels_impl.h, one build per instruction set.
#include "core/accel/bvh.h"

#include "core/csg/csg_mesh_hits.h"

namespace rt {

MeshInstance place_mesh(const Bvh& mesh_bvh, const Transform& transform, uint32_t mesh, uint32_t material,
                        const AlphaCutout* cutout) {
  return MeshInstance{&mesh_bvh, transform, transform_bounds(transform.to_world, mesh_bvh.bounds()),
                      mesh,      material,  cutout};
}

bool visit_mesh_hits(const Bvh& mesh, const Ray& ray, MeshHitVisitorFn visit, void* visitor) {
  return mesh.visit_hits_through(ray, visit, visitor);
}

}  // namespace rt
