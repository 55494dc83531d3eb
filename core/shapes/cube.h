// Axis-aligned cube [-1, 1]^3 (centred like the unit sphere, so rotations turn it in place).
// part = 2 * axis + (1 if the face is on the negative side): 0 = +X, 1 = -X, ... 5 = -Z.
// UV: each face holds the whole image, upright and unmirrored seen from outside, as on a die
// standing on -Y with its +Z face towards the viewer (side faces: v runs down -Y; top: v runs
// towards +Z; bottom: towards -Z). docs/scene-format.md, "Natural texture coordinates".
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace rt {

bool intersect_cube(const Ray& ray, Hit& hit);
SurfacePatch cube_patch(Vec3 p, uint32_t part);

}  // namespace rt
