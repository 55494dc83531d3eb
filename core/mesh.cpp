#include "core/mesh.h"

namespace rt {

SurfaceInteraction mesh_surface(const TriangleMesh& mesh, uint32_t triangle, const Ray& ray, const Hit& hit) {
  const uint32_t i0 = mesh.indices[3 * triangle], i1 = mesh.indices[3 * triangle + 1],
                 i2 = mesh.indices[3 * triangle + 2];
  const float b0 = 1.0f - hit.b1 - hit.b2;
  const Vec3 p0 = mesh.positions[i0], p1 = mesh.positions[i1], p2 = mesh.positions[i2];
  const Vec3 e1 = p1 - p0, e2 = p2 - p0;

  SurfaceInteraction si;
  si.position = b0 * p0 + hit.b1 * p1 + hit.b2 * p2;
  si.geometric_normal = glm::normalize(glm::cross(e1, e2));
  si.shading_normal = si.geometric_normal;
  if (!mesh.normals.empty()) {
    const Vec3 n = b0 * mesh.normals[i0] + hit.b1 * mesh.normals[i1] + hit.b2 * mesh.normals[i2];
    const float len = glm::length(n);
    if (len > 1e-8f) {
      si.shading_normal = n / len;
      // Vertex normals state which side is outside; trust them over the winding.
      if (glm::dot(si.shading_normal, si.geometric_normal) < 0.0f) si.geometric_normal = -si.geometric_normal;
    }
  }

  Vec2 uv0(0.0f, 0.0f), uv1(1.0f, 0.0f), uv2(1.0f, 1.0f);  // pbrt's convention when a mesh has no UVs
  if (!mesh.uvs.empty()) {
    uv0 = mesh.uvs[i0];
    uv1 = mesh.uvs[i1];
    uv2 = mesh.uvs[i2];
  }
  si.uv = b0 * uv0 + hit.b1 * uv1 + hit.b2 * uv2;
  // Solve [du1 dv1; du2 dv2] [dpdu; dpdv] = [e1; e2] for the tangent frame.
  const Vec2 d1 = uv1 - uv0, d2 = uv2 - uv0;
  const float det = d1.x * d2.y - d1.y * d2.x;
  if (std::fabs(det) > 1e-12f) {
    const float inv = 1.0f / det;
    si.dpdu = (d2.y * e1 - d1.y * e2) * inv;
    si.dpdv = (d1.x * e2 - d2.x * e1) * inv;
  }
  if (std::fabs(det) <= 1e-12f || !is_finite(si.dpdu) || !is_finite(si.dpdv) ||
      glm::length(glm::cross(si.dpdu, si.dpdv)) == 0.0f) {
    orthonormal_basis(si.geometric_normal, si.dpdu, si.dpdv);
  }
  si.material = mesh.material;
  si.front_face = glm::dot(ray.direction, si.geometric_normal) < 0.0f;
  return si;
}

TriangleMesh transformed(const TriangleMesh& mesh, const Transform& t) {
  TriangleMesh out = mesh;
  for (Vec3& p : out.positions) p = t.point_to_world(p);
  for (Vec3& n : out.normals)
    if (n != Vec3(0.0f)) n = t.normal_to_world_unit(n);
  if (glm::determinant(Mat3(t.to_world)) < 0.0f)
    for (size_t i = 0; i + 2 < out.indices.size(); i += 3) std::swap(out.indices[i + 1], out.indices[i + 2]);
  return out;
}

}  // namespace rt
