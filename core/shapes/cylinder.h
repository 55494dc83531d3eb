// The proposal's cylinder: radius 1 around +Z, from z = 0 to z = 1, both caps closed.
// part 0 = side, 1 = base cap (z = 0, normal -Z), 2 = top cap (z = 1, normal +Z).
// UV on the side: u = angle around +Z from +X / 2 pi, v = 1 - z (upright when +Z is up). On
// the caps: planar, v = (1 - y) / 2 and u = (x + 1) / 2 on top, (1 - x) / 2 on the base, so
// that every part reads unmirrored from outside (docs/scene-format.md, "Natural texture coordinates").
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace rt {

enum CylinderPart : uint32_t { kCylinderSide = 0, kCylinderBase = 1, kCylinderTop = 2 };

bool intersect_cylinder(const Ray& ray, Hit& hit);
SurfacePatch cylinder_patch(Vec3 p, uint32_t part);

// Shared with the cone: the disc x^2 + y^2 <= 1 in the plane z = z_cap.
bool intersect_unit_disc(const Ray& ray, float z_cap, double& t);
// Shared with the cone: the nearer of the quadric roots t0 <= t1 that lies inside the ray's
// interval and between z = 0 and z = 1, where the side exists.
bool side_root_in_height(const Ray& ray, double t0, double t1, double& t);
SurfacePatch cap_patch(Vec3 p, bool top);

// Shared with the cone: the angle around +Z from +X in [0, 2 pi), the sides' u.
inline float angle_around_z(Vec3 p) {
  const float phi = std::atan2(p.y, p.x);
  return phi < 0.0f ? phi + 2.0f * kPi : phi;
}
// Shared with the cone: the unit vector from the axis towards p in the XY plane, the direction
// of the sides' normals (+X on the axis itself, a cone's apex). Made from p, not as the cosine and
// sine of its angle: those three library calls a hit gave the same direction less exactly (an
// angle wrapped by 2 pi keeps fewer bits) and took 2% of refraction.json's render.
inline Vec3 radial_towards(Vec3 p) {
  const float r = std::sqrt(p.x * p.x + p.y * p.y);
  return r > 0.0f ? Vec3(p.x / r, p.y / r, 0.0f) : Vec3(1.0f, 0.0f, 0.0f);
}
inline Vec3 cap_normal(bool top) { return Vec3(0.0f, 0.0f, top ? 1.0f : -1.0f); }

// The normal at p on `part`, as cylinder_patch makes it (a hit that needs no more).
inline Vec3 cylinder_normal(Vec3 p, uint32_t part) {
  return part != kCylinderSide ? cap_normal(part == kCylinderTop) : radial_towards(p);
}

}  // namespace rt
