// Unit sphere at the origin. UV: u = longitude around +Y (0 at +Z, increasing towards +X),
// v = polar angle from +Y divided by pi (0 at the north pole, as image rows run top-down).
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace rt {

bool intersect_sphere(const Ray& ray, Hit& hit);
// intersect_sphere(ray, first), then intersect_sphere from just past it (ray.tmin the float after
// first.t) into `second`: the same two hits, from one solution of the quadratic (a CSG operand's
// two crossings of a line). False when either is missing.
bool intersect_sphere_twice(const Ray& ray, Hit& first, Hit& second);
SurfacePatch sphere_patch(Vec3 p, uint32_t part);

}  // namespace rt
