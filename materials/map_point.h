// Where a surface point lies in a texture: the mapping's (u, v), the world-space tangent frame of
// those coordinates (dP/du, dP/dv: what bump and normal maps tilt along) and their gradients in the
// tangent plane (du/dP, dv/dP: how fast the texture runs past, which picks the mip level).
#pragma once

#include "core/hit.h"
#include "core/texture/texture_slot.h"

namespace rt {

struct MappedPoint {
  Vec2 uv{0.0f};
  Vec3 dpdu{1.0f, 0.0f, 0.0f}, dpdv{0.0f, 1.0f, 0.0f};
  Vec3 grad_u{0.0f}, grad_v{0.0f};  // zero where the mapping is degenerate (a pole, an edge-on plane)
};

// The projection's (u, v) of an object-space point and its object-space gradients, about
// `axis` (0 x, 1 y, 2 z; ProjectionAxis resolved for the shape).
struct Projected {
  Vec2 uv{0.0f};
  Vec3 grad_u{0.0f}, grad_v{0.0f};
};
Projected project(Projection projection, int axis, Vec3 object_point);

// The axis a mapping projects about on a surface whose shape runs along `shape_axis`.
int projection_axis(const TextureMapping& mapping, int shape_axis);

// The dual basis of two vectors in their plane: da . a = 1, da . b = 0, db . a = 0, db . b = 1.
// Tangents and gradients are each other's duals. False (outputs untouched) when a and b are
// (nearly) parallel or not finite.
bool dual_basis(Vec3 a, Vec3 b, Vec3& da, Vec3& db);

MappedPoint map_point(const TextureMapping& mapping, const SurfaceInteraction& si);

// How much of the texture, in (u, v) units, a ray cone of world width `width` covers where it
// meets the surface along unit `direction`: the two axes of its elliptical footprint (width
// across, width / cos(theta) along the surface) carried into (u, v), as a GPU picks its level of
// detail (Texture::mip_level measures each in texels).
UvFootprint uv_footprint(const MappedPoint& p, Vec3 normal, Vec3 direction, float width);

}  // namespace rt
