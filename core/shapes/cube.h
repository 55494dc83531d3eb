// Axis-aligned cube [-1, 1]^3 (centred like the unit sphere, so rotations turn it in place).
// part = 2 * axis + (1 if the face is on the negative side): 0 = +X, 1 = -X, ... 5 = -Z.
// UV: each face holds the whole image, upright and unmirrored seen from outside, as on a die
// standing on -Y with its +Z face towards the viewer (side faces: v runs down -Y; top: v runs
// towards +Z; bottom: towards -Z). docs/scene-format.md, "Natural texture coordinates".
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace rt {

bool intersect_cube(const Ray& ray, Hit& hit);
SurfacePatch cube_patch(Vec3 p, uint32_t part);

// A face's directions of growing u (right) and v (down) seen from outside, like the faces of a
// die standing on -Y with +Z towards the viewer.
struct CubeFace {
  Vec3 right, down;
};
inline CubeFace cube_face(uint32_t part) {
  static constexpr float kFrames[6][2][3] = {
      // +X, -X, +Y, -Y, +Z, -Z
      {{0, 0, -1}, {0, -1, 0}}, {{0, 0, 1}, {0, -1, 0}}, {{1, 0, 0}, {0, 0, 1}},
      {{1, 0, 0}, {0, 0, -1}},  {{1, 0, 0}, {0, -1, 0}}, {{-1, 0, 0}, {0, -1, 0}},
  };
  const auto& f = kFrames[part < 6 ? part : 0];
  return {Vec3(f[0][0], f[0][1], f[0][2]), Vec3(f[1][0], f[1][1], f[1][2])};
}
// right x down points in: the image reads correctly from outside.
inline Vec3 cube_normal(const CubeFace& face) { return glm::cross(face.down, face.right); }

}  // namespace rt
