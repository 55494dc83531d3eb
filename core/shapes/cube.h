// Axis-aligned cube [-1, 1]^3 (centred like the unit sphere, so rotations turn it in place).
// part = 2 * axis + (1 if the face is on the negative side): 0 = +X, 1 = -X, ... 5 = -Z.
// UV: the face's two other coordinates mapped from [-1, 1] to [0, 1], ordered so that
// dpdu x dpdv points out of the face.
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace rt {

bool intersect_cube(const Ray& ray, Hit& hit);
SurfacePatch cube_patch(Vec3 p, uint32_t part);

}  // namespace rt
