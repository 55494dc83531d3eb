// An indexed triangle mesh in its own (object) space, as imported from glTF: scenes place it
// with MeshInstance (core/mesh_instance.h), once or many times. Normals and UVs are
// optional (empty when the file had none); without normals a mesh is shaded flat with its
// geometric normals, as the glTF specification requires.
#pragma once

#include <cstdint>
#include <vector>

#include "core/hit.h"
#include "core/math.h"
#include "core/ray.h"
#include "core/transform.h"

namespace rt {

struct TriangleMesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;      // per vertex, unit; empty = flat shading
  std::vector<Vec2> uvs;          // per vertex (TEXCOORD_0, origin top-left); empty = none
  std::vector<Vec2> uvs1;         // per vertex (TEXCOORD_1); empty = none
  std::vector<Vec4> tangents;     // per vertex (TANGENT: unit xyz, handedness w = +-1); empty = none
  std::vector<Vec4> colors;       // per vertex (COLOR_0: linear RGB and alpha); empty = none
  std::vector<uint32_t> indices;  // three per triangle, each < positions.size()

  size_t triangle_count() const { return indices.size() / 3; }
};

// The mesh moved by an affine transform: positions by it, normals by its inverse transpose,
// tangents by its linear part. A mirroring transform (negative determinant) also reverses the
// winding, so that the geometric normal from the winding keeps pointing the same way relative
// to the surface (glTF's rule for negative scales). For flat, one-level reference structures.
TriangleMesh transformed(const TriangleMesh& mesh, const Transform& t);

// World-space surface of triangle `triangle` of the mesh placed by `placement`, at the hit's
// barycentrics (b1, b2); `ray` is the world ray. Computed in object space and carried out:
// normals through the inverse transpose (which keeps them outward under a mirror, as glTF
// asks), tangent frames through the linear part, the tangent's handedness flipped by a mirror.
SurfaceInteraction mesh_surface(const TriangleMesh& mesh, uint32_t triangle, const Ray& ray, const Hit& hit,
                                const Transform& placement);

}  // namespace rt
