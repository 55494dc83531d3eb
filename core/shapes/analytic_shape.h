// The closed set of analytic shapes, dispatched by a tag and a switch (no virtual call in the
// hot path). Each is intersected in its canonical object space through the inverse transform;
// the object-space direction is not renormalised, so t means the same thing in both spaces.
#pragma once

#include <cstdint>

#include "core/aabb.h"
#include "core/hit.h"
#include "core/ray.h"
#include "core/transform.h"

namespace rt {

enum class ShapeKind : uint8_t { kSphere, kCube, kPlane, kCylinder, kCone };

struct AnalyticShape {
  ShapeKind kind = ShapeKind::kSphere;
  uint32_t material = 0;
  Transform transform;
};

// Canonical object-space bounds of each kind.
Aabb object_bounds(ShapeKind kind);
Aabb world_bounds(const AnalyticShape& shape);

// Object-space ray for the shape: origin and direction through to_object, interval unchanged.
inline Ray to_object_ray(const AnalyticShape& shape, const Ray& ray) { return transformed_ray(shape.transform, ray); }

bool intersect_object_space(ShapeKind kind, const Ray& object_ray, Hit& hit);
SurfacePatch object_space_patch(ShapeKind kind, Vec3 object_point, uint32_t part);
// object_space_patch(...).normal alone, to the bit: all a hit needs whose material reads no
// texture coordinates.
Vec3 object_space_normal(ShapeKind kind, Vec3 object_point, uint32_t part);

inline bool intersect_shape(const AnalyticShape& shape, const Ray& ray, Hit& hit) {
  Ray r = to_object_ray(shape, ray);
  const float before_t = hit.t;  // the routines write t and part only on a hit
  const uint32_t before_part = hit.part;
  if (!intersect_object_space(shape.kind, r, hit)) return false;
  // object_ray's rule (core/transform.h), worked out only once there is a hit to judge: a root
  // within the origin's rounding could be the surface the ray starts on. Most tests miss, and
  // shadow rays took a third longer when every test paid for it.
  const float floor = ray.tmin + origin_rounding(shape.transform, ray.origin, r.direction);
  if (hit.t > floor) [[likely]]
    return true;
  r.tmin = floor;
  if (intersect_object_space(shape.kind, r, hit)) return true;
  hit.t = before_t;
  hit.part = before_part;
  return false;
}

// World-space surface at a hit (the hit's t and part from intersect_shape). Without `texcoords`,
// the texture coordinates and their frame are left at UvFrame's defaults (a sphere's need atan2,
// acos and three sines; every shape's frame two matrix products), and so are object_position,
// object_from_world and shape_axis, which only a texture's projection reads.
SurfaceInteraction shape_surface(const AnalyticShape& shape, const Ray& ray, const Hit& hit, bool texcoords = true);

}  // namespace rt
