// Which texture a material slot reads and how a surface point finds its place in it: plain data,
// parsed by io/ and evaluated by materials/map_point.h.
#pragma once

#include <cstdint>

#include "core/math.h"
#include "core/texture/texture.h"

namespace rt {

// Where (u, v) comes from. kUv: the shape's own coordinates (or a mesh's TEXCOORD_n). The others
// are the proposal's projections of the hit point in the shape's canonical box [-1, 1]^3 (a
// mesh's object space) about an axis (docs/rendering.md, "Textures"); with the axis y:
//   planar       along the axis (default z): u = (x + 1) / 2, v = (1 - y) / 2 (the square
//                [-1, 1]^2 seen from +z, upright)
//   spherical    longitude and latitude about the axis, as the sphere's own coordinates
//   cylindrical  longitude about the axis, v = (1 - y) / 2 as planar
enum class Projection : uint8_t { kUv, kPlanar, kSpherical, kCylindrical };

// The projection's axis in object space. kShape: planar's z; for spherical and cylindrical the
// shape's own axis (SurfaceInteraction::shape_axis: z for the cylinder and cone, y otherwise).
enum class ProjectionAxis : uint8_t { kShape, kX, kY, kZ };

inline constexpr uint32_t kNoTexture = 0xffffffffu;

struct TextureMapping {
  Projection projection = Projection::kUv;
  ProjectionAxis axis = ProjectionAxis::kShape;
  uint32_t uv_set = 0;  // kUv on meshes: TEXCOORD_0 or TEXCOORD_1
  // KHR_texture_transform: uv' = offset + R(rotation) (scale * uv), see transformed_uv.
  Vec2 scale{1.0f};
  Vec2 offset{0.0f};
  float rotation_degrees = 0.0f;
  WrapModes wrap;  // per axis: u (glTF's wrapS), v (wrapT)
  TextureFilter filter = TextureFilter::kTrilinear;
};

// KHR_texture_transform's matrix, R = [[cos, sin], [-sin, cos]]: a positive rotation turns the
// UVs counter-clockwise (v points down the image), which turns the image clockwise on the
// surface. The specification's own example (offset [0, 1], rotation 90 degrees, scale 0.5 reads
// the lower-left quarter of the image) fixes the sign.
inline Mat2 texture_rotation(float degrees) {
  const float c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
  return Mat2(Vec2(c, -s), Vec2(s, c));  // glm is column-major: columns (c, -s) and (s, c)
}

inline Vec2 transformed_uv(const TextureMapping& m, Vec2 uv) {
  return m.offset + texture_rotation(m.rotation_degrees) * (m.scale * uv);
}

// One texture a material reads: an index into Scene::textures and its mapping.
struct TextureSlot {
  uint32_t texture = kNoTexture;
  TextureMapping mapping;

  bool present() const { return texture != kNoTexture; }
};

// The proposal's Blinn bump map. Heights are the texel values (the mean of the channels) times
// `strength`, in scene units; `epsilon` is the central-difference step in (u, v), 0 = one texel.
struct BumpMap {
  TextureSlot height;
  float strength = 1.0f;
  float epsilon = 0.0f;
};

// A tangent-space normal map (glTF's normalTexture): RGB = (x, y, z) * 0.5 + 0.5, x along the
// tangent (increasing u), y along the bitangent (decreasing v: up in the image), z the normal;
// `scale` multiplies x and y (glTF's normalTexture.scale; "strength" in scene files, where
// "scale" tiles the map like any texture's).
struct NormalMap {
  TextureSlot map;
  float scale = 1.0f;
};

}  // namespace rt
