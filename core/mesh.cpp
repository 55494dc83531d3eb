#include "core/mesh.h"

namespace rt {
namespace {

// The texture coordinates at barycentrics (b1, b2) and the tangent frame that makes them
// linear over the triangle: solve [du1 dv1; du2 dv2] [dpdu; dpdv] = [e1; e2].
UvFrame interpolate_uv_frame(const std::vector<Vec2>& uvs, uint32_t i0, uint32_t i1, uint32_t i2, const Hit& hit,
                             Vec3 e1, Vec3 e2, Vec3 normal) {
  Vec2 uv0(0.0f, 0.0f), uv1(1.0f, 0.0f), uv2(1.0f, 1.0f);  // pbrt's convention when a mesh has no UVs
  if (!uvs.empty()) {
    uv0 = uvs[i0];
    uv1 = uvs[i1];
    uv2 = uvs[i2];
  }
  UvFrame f;
  f.uv = (1.0f - hit.b1 - hit.b2) * uv0 + hit.b1 * uv1 + hit.b2 * uv2;
  const Vec2 d1 = uv1 - uv0, d2 = uv2 - uv0;
  const float det = d1.x * d2.y - d1.y * d2.x;
  if (std::fabs(det) > 1e-12f) {
    const float inv = 1.0f / det;
    f.dpdu = (d2.y * e1 - d1.y * e2) * inv;
    f.dpdv = (d1.x * e2 - d2.x * e1) * inv;
  }
  if (std::fabs(det) <= 1e-12f || !is_finite(f.dpdu) || !is_finite(f.dpdv) ||
      glm::length(glm::cross(f.dpdu, f.dpdv)) == 0.0f) {
    orthonormal_basis(normal, f.dpdu, f.dpdv);
  }
  return f;
}

}  // namespace

SurfaceInteraction mesh_surface(const TriangleMesh& mesh, uint32_t triangle, const Ray& ray, const Hit& hit,
                                const Transform& placement) {
  const uint32_t i0 = mesh.indices[3 * triangle], i1 = mesh.indices[3 * triangle + 1],
                 i2 = mesh.indices[3 * triangle + 2];
  const float b0 = 1.0f - hit.b1 - hit.b2;
  const Vec3 p0 = mesh.positions[i0], p1 = mesh.positions[i1], p2 = mesh.positions[i2];
  const Vec3 e1 = p1 - p0, e2 = p2 - p0;

  // Object space first.
  const Vec3 position = b0 * p0 + hit.b1 * p1 + hit.b2 * p2;
  Vec3 geometric = glm::cross(e1, e2);
  Vec3 shading = geometric;
  bool smooth = false;  // shaded by the vertex normals
  if (!mesh.normals.empty()) {
    const Vec3 n = b0 * mesh.normals[i0] + hit.b1 * mesh.normals[i1] + hit.b2 * mesh.normals[i2];
    if (glm::length(n) > 1e-8f) {
      shading = n;
      smooth = true;
      // Vertex normals state which side is outside; trust them over the winding.
      if (glm::dot(shading, geometric) < 0.0f) geometric = -geometric;
    }
  }
  const Vec3 object_normal = glm::normalize(geometric);
  // Hanika's lift: each vertex's tangent plane, where it lies above the flat triangle's point,
  // raises it (by the barycentric share of that vertex); planes below it change nothing.
  Vec3 lift(0.0f);
  if (smooth) {
    const auto raise = [&](const Vec3& vertex, const Vec3& normal, float weight) {
      lift += weight * std::max(0.0f, glm::dot(vertex - position, normal)) * normal;
    };
    raise(p0, mesh.normals[i0], b0);
    raise(p1, mesh.normals[i1], hit.b1);
    raise(p2, mesh.normals[i2], hit.b2);
  }
  SurfaceInteraction si;
  // Each set's frame goes out to the world as it is made; the second set, where the mesh has
  // none, is the first's (its world frame copied, not transformed again).
  const auto world_frame = [&](const std::vector<Vec2>& uvs) {
    UvFrame f = interpolate_uv_frame(uvs, i0, i1, i2, hit, e1, e2, object_normal);
    f.dpdu = placement.vector_to_world(f.dpdu);
    f.dpdv = placement.vector_to_world(f.dpdv);
    return f;
  };
  si.texcoord[0] = world_frame(mesh.uvs);
  si.texcoord[1] = mesh.uvs1.empty() ? si.texcoord[0] : world_frame(mesh.uvs1);
  if (!mesh.colors.empty()) si.color = b0 * mesh.colors[i0] + hit.b1 * mesh.colors[i1] + hit.b2 * mesh.colors[i2];
  if (!mesh.tangents.empty())
    si.tangent = b0 * mesh.tangents[i0] + hit.b1 * mesh.tangents[i1] + hit.b2 * mesh.tangents[i2];

  // Then the rest out to the world.
  // pbrt-v4's bound for a point from barycentrics (section 6.8.5).
  const Vec3 error = float_gamma(7) * (abs3(b0 * p0) + abs3(hit.b1 * p1) + abs3(hit.b2 * p2));
  si.position = placement.point_to_world(position, error, si.position_error);
  si.geometric_normal = placement.normal_to_world_unit(geometric);
  si.shading_normal = placement.normal_to_world_unit(shading);
  if (si.tangent.w != 0.0f) {
    // The bitangent is cross(normal, tangent) * w; a mirror flips that cross product, so w flips too.
    const bool mirrors = glm::determinant(Mat3(placement.to_world)) < 0.0f;
    const Vec3 t = placement.vector_to_world(Vec3(si.tangent));
    const float len = glm::length(t);
    si.tangent =
        len > 0.0f && std::isfinite(len) ? Vec4(t / len, mirrors == (si.tangent.w < 0.0f) ? 1.0f : -1.0f) : Vec4(0.0f);
  }
  si.shadow_lift = placement.vector_to_world(lift);
  si.object_position = position;
  si.object_from_world = Mat3(placement.to_object);
  si.front_face = glm::dot(ray.direction, si.geometric_normal) < 0.0f;
  return si;
}

TriangleMesh transformed(const TriangleMesh& mesh, const Transform& t) {
  TriangleMesh out = mesh;
  for (Vec3& p : out.positions) p = t.point_to_world(p);
  for (Vec3& n : out.normals)
    if (n != Vec3(0.0f)) n = t.normal_to_world_unit(n);
  const bool mirrors = glm::determinant(Mat3(t.to_world)) < 0.0f;
  // The bitangent is cross(normal, tangent) * w; a mirror flips that cross product, so w flips too.
  for (Vec4& tangent : out.tangents) {
    const Vec3 xyz = t.vector_to_world(Vec3(tangent));
    const float len = glm::length(xyz);
    tangent = len > 0.0f && std::isfinite(len) ? Vec4(xyz / len, mirrors ? -tangent.w : tangent.w) : Vec4(0.0f);
  }
  if (mirrors)
    for (size_t i = 0; i + 2 < out.indices.size(); i += 3) std::swap(out.indices[i + 1], out.indices[i + 2]);
  return out;
}

}  // namespace rt
