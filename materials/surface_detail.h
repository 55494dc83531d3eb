// Bump and normal maps: how a texture tilts the shading normal (docs/rendering.md, "Bump and normal maps").
// The tilted normal then drives all lighting and secondary rays; the integrator keeps checking the
// geometric normal, so a tilt can never send a ray through the surface.
#pragma once

#include <vector>

#include "core/material.h"
#include "materials/map_point.h"

namespace rt {

// Blinn's perturbation. The surface displaced by a height h(u, v) along its unit normal n has the
// normal of (P_u + h_u n) x (P_v + h_v n), that is (to first order) n + (h_u (n x P_v) - h_v (n x P_u)) /
// |P_u x P_v| once divided by |P_u x P_v| -- the proposal's N + Bu (N x Ov) - Bv (N x Ou) with the
// height in scene units. The sign follows the side P_u x P_v lies on, so that a larger height always
// raises the surface outwards. hu, hv: derivatives of the height (scene units) per unit u and v.
Vec3 blinn_bump(Vec3 n, Vec3 dpdu, Vec3 dpdv, float hu, float hv);

// The height map's derivatives by central differences, Bu = (B(u + E, v) - B(u - E, v)) / 2E and
// likewise Bv, times bump.strength; B is the mean of a texel's channels. E is bump.epsilon, or
// one texel when that is 0, widened to half the footprint so that a far surface is not aliased.
// `filter` is the mapping's, or the one --texture-filter imposes.
Vec2 height_gradient(const BumpMap& bump, const std::vector<Texture>& textures, Vec2 uv, const UvFootprint& footprint,
                     TextureFilter filter);

// A tangent-space normal map's texel (RGB in [0, 1]) in the frame of unit normal n: tangent t
// (made perpendicular to n here), bitangent cross(n, t) * handedness; scale multiplies x and y.
Vec3 tangent_space_normal(Vec3 n, Vec3 tangent, float handedness, Vec3 texel, float scale);

// The handedness that makes the bitangent run up the image (towards decreasing v), as glTF's
// tangents do, for a frame taken from dP/du and dP/dv.
inline float handedness_from_uv(Vec3 n, Vec3 dpdu, Vec3 dpdv) {
  return glm::dot(glm::cross(n, dpdu), dpdv) > 0.0f ? -1.0f : 1.0f;
}

}  // namespace rt
