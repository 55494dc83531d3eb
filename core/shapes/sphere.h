// Unit sphere at the origin. UV: u = longitude around +Y (0 at +Z, increasing towards +X),
// v = polar angle from +Y divided by pi (0 at the north pole, as image rows run top-down).
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace rt {

bool intersect_sphere(const Ray& ray, Hit& hit);
SurfacePatch sphere_patch(Vec3 p, uint32_t part);

}  // namespace rt
