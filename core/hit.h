// Two-phase hits: traversal only produces this small record; the full SurfaceInteraction
// (normals, UV, tangents) is built once, for the closest hit (see core/scene.h).
#pragma once

#include <cstdint>

#include "core/math.h"

namespace rt {

inline constexpr uint32_t kNoPrimitive = 0xffffffffu;

struct Hit {
  float t = kInfinity;
  uint32_t prim = kNoPrimitive;  // primitive id (see core/accel/primitives.h)
  float b1 = 0.0f, b2 = 0.0f;    // triangle barycentrics of vertices 1 and 2
  uint32_t part = 0;             // analytic shapes: which face / cap / side; mesh instances: the triangle
  uint32_t operand = 0;          // CSG solids: which operand surface, and whether the ray leaves there
  uint32_t medium = 0;           // CSG solids: the material inside (core/csg/csg_object.h)
};

// The closest-hit order: nearer first, equals by (prim, part). Any order of testing the
// primitives then finds the same hit, so a packet (whose walk takes leaves in another order than
// a single ray's), the brute-force reference (id order) and a ray inside a closed shape
// (core/accel/shape_interiors.h) agree with the single ray bit for bit. Always inlined: the BVH
// kernels, each built for its instruction set, must not leave a copy of their own for others.
[[gnu::always_inline]] inline bool precedes(const Hit& a, const Hit& b) {
  return a.t < b.t || (a.t == b.t && (a.prim < b.prim || (a.prim == b.prim && a.part < b.part)));
}

inline constexpr uint32_t kOwnMedium = 0xffffffffu;

// Object-space local geometry of an analytic shape at a point: the outward unit normal, the
// texture coordinates and the partial derivatives dP/du, dP/dv (the tangent frame used by
// texture and bump mapping).
struct SurfacePatch {
  Vec3 normal{0.0f, 0.0f, 1.0f};
  Vec2 uv{0.0f};
  Vec3 dpdu{1.0f, 0.0f, 0.0f};
  Vec3 dpdv{0.0f, 1.0f, 0.0f};
};

// Texture coordinates with their tangent frame: dP/du and dP/dv in world space.
struct UvFrame {
  Vec2 uv{0.0f};
  Vec3 dpdu{1.0f, 0.0f, 0.0f};
  Vec3 dpdv{0.0f, 1.0f, 0.0f};
};

// Everything shading needs about the closest hit, in world space.
struct SurfaceInteraction {
  Vec3 position{0.0f};
  Vec3 position_error{0.0f};                // absolute bound per component on position's rounding (core/ray.h)
  Vec3 geometric_normal{0.0f, 0.0f, 1.0f};  // unit, outward (from the winding for triangles)
  Vec3 shading_normal{0.0f, 0.0f, 1.0f};    // unit, interpolated for smooth meshes
  // [0]: the shape's own coordinates, or a mesh's TEXCOORD_0; [1]: a mesh's TEXCOORD_1 (a copy
  // of [0] when it has none).
  UvFrame texcoord[2];
  Vec4 tangent{0.0f};  // a mesh's interpolated TANGENT attribute (xyz, handedness w); w = 0: none
  Vec4 color{1.0f};    // a mesh's interpolated COLOR_0 (linear RGB, alpha); 1 without one
  // The hit in the shape's canonical box [-1, 1]^3 (the cylinder's and cone's z in [0, 1]
  // stretched to it; a mesh instance's object space), for the explicit projections.
  Vec3 object_position{0.0f};
  Mat3 object_from_world{1.0f};  // linear part of the world-to-box transform
  uint8_t shape_axis = 1;        // the axis the shape runs along: 2 (z) for cylinder and cone, else 1 (y)
  uint32_t material = 0;
  // The material whose inside lies behind the surface, for refraction's medium stack: the
  // material's own (kOwnMedium), except on a CSG solid, whose cut surfaces bound another's inside.
  uint32_t medium = kOwnMedium;
  bool front_face = true;  // the ray arrived from the outward side
  // Where shadow rays start, from `position`: on a smooth-shaded mesh, the point lifted off the
  // flat triangle towards the curved surface its vertex normals describe (Hanika, "Hacking the
  // Shadow Terminator", Ray Tracing Gems II, 2021), so that a coarse mesh's own facets do not
  // shadow points its shading normals say are lit. Zero elsewhere.
  Vec3 shadow_lift{0.0f};
};

}  // namespace rt
