// Finite square in the XZ plane: y = 0, x and z in [-1, 1], normal +Y (Y is up, so an
// unrotated plane is a floor). Finite so that it has bounds and fits in the BVH; scale it to
// the size you need. Two-sided for shading. UV: u = (x + 1) / 2, v = (z + 1) / 2 (upright seen from above with +Z
// towards the viewer; scale the texture mapping to tile it).
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace rt {

bool intersect_plane(const Ray& ray, Hit& hit);
SurfacePatch plane_patch(Vec3 p, uint32_t part);

}  // namespace rt
