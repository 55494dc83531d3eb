// The proposal's cone: apex at the origin, opening along +Z, base disc of radius 1 at z = 1,
// base closed. Side: x^2 + y^2 = z^2 with 0 <= z <= 1 (the mirrored nappe z < 0 is not part
// of it). part 0 = side, 2 = base cap (normal +Z).
// UV on the side: u = 1 - angle around +Z from +X / 2 pi, v = z (upright, unmirrored seen from
// outside when the apex points up); the base as the cylinder's top cap.
#pragma once

#include "core/hit.h"
#include "core/ray.h"
#include "core/shapes/cylinder.h"

namespace rt {

enum ConePart : uint32_t { kConeSide = 0, kConeBase = 2 };

bool intersect_cone(const Ray& ray, Hit& hit);
SurfacePatch cone_patch(Vec3 p, uint32_t part);

// Gradient of x^2 + y^2 - z^2 at radius z is (radial, -1) * z: the side leans at 45 degrees.
inline Vec3 cone_side_normal(Vec3 radial) { return glm::normalize(Vec3(radial.x, radial.y, -1.0f)); }
// The normal at p on `part`, as cone_patch makes it (a hit that needs no more).
inline Vec3 cone_normal(Vec3 p, uint32_t part) {
  return part == kConeBase ? cap_normal(true) : cone_side_normal(radial_towards(p));
}

}  // namespace rt
