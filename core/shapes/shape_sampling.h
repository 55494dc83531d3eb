// Points drawn uniformly by area on an analytic shape's canonical surface (the object space of
// core/shapes/*.h), for light sampling of emissive shapes (core/lights/emitters.h). Each part of
// a shape (a cube's faces, a cylinder's side and caps, a cone's side and base) is drawn with
// probability proportional to its area, so that the density is 1 / object_area everywhere.
#pragma once

#include <cstdint>

#include "core/shapes/analytic_shape.h"

namespace rt {

struct ShapePoint {
  Vec3 position{0.0f};            // object space, on the surface
  Vec3 normal{0.0f, 0.0f, 1.0f};  // object space, unit, outward
  uint32_t part = 0;              // as the shape's intersection reports it
};

// The area of the shape's canonical surface: the unit sphere's 4 pi, the cube's 24, ...
float object_area(ShapeKind kind);

// u in [0, 1)^2: a point with density 1 / object_area(kind) per unit (object-space) area.
ShapePoint sample_object_surface(ShapeKind kind, Vec2 u);

// How much the transform stretches area at a point of the surface whose world-space unit normal
// is `world_normal`: world area / object area (|det L| / |L^T n| for the linear part L).
float area_scale(const Transform& transform, Vec3 world_normal);

}  // namespace rt
