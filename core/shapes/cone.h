// The proposal's cone: apex at the origin, opening along +Z, base disc of radius 1 at z = 1,
// base closed. Side: x^2 + y^2 = z^2 with 0 <= z <= 1 (the mirrored nappe z < 0 is not part
// of it). part 0 = side, 2 = base cap (normal +Z).
// UV on the side: u = 1 - angle around +Z from +X / 2 pi, v = z (upright, unmirrored seen from
// outside when the apex points up); the base as the cylinder's top cap.
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace rt {

enum ConePart : uint32_t { kConeSide = 0, kConeBase = 2 };

bool intersect_cone(const Ray& ray, Hit& hit);
SurfacePatch cone_patch(Vec3 p, uint32_t part);

}  // namespace rt
