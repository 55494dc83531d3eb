#include "materials/map_point.h"

namespace rt {
namespace {

// Longitude about +y, 0 at +z, growing towards +x (the sphere's own u), and its gradient.
void longitude(Vec3 p, float& u, Vec3& grad) {
  const float rho2 = p.x * p.x + p.z * p.z;
  float phi = std::atan2(p.x, p.z);
  if (phi < 0.0f) phi += 2.0f * kPi;
  u = phi / (2.0f * kPi);
  grad = rho2 > 0.0f ? Vec3(p.z, 0.0f, -p.x) / (2.0f * kPi * rho2) : Vec3(0.0f);
}

// The rotation (a cyclic permutation of the axes, or one with a sign: never a mirror) that takes
// the projection's axis to where the formulas expect it: y for spherical and cylindrical, z for
// planar. Planar along y sees the top from above with -z up the image (as the cube's top face);
// along x, the side from +x with +y up.
Mat3 projection_frame(Projection projection, int axis) {
  const Vec3 x(1.0f, 0.0f, 0.0f), y(0.0f, 1.0f, 0.0f), z(0.0f, 0.0f, 1.0f);
  // glm is column-major: the rows of the rotation are the transposes' columns.
  const auto rows = [](Vec3 a, Vec3 b, Vec3 c) { return glm::transpose(Mat3(a, b, c)); };
  if (projection == Projection::kPlanar) {
    if (axis == 0) return rows(-z, y, x);
    if (axis == 1) return rows(x, -z, y);
    return Mat3(1.0f);
  }
  if (axis == 0) return rows(z, x, y);
  if (axis == 2) return rows(y, z, x);
  return Mat3(1.0f);
}

Projected project_about_y(Projection projection, Vec3 p) {
  Projected out;
  switch (projection) {
    case Projection::kPlanar:
      out.uv = Vec2(0.5f * (p.x + 1.0f), 0.5f * (1.0f - p.y));
      out.grad_u = Vec3(0.5f, 0.0f, 0.0f);
      out.grad_v = Vec3(0.0f, -0.5f, 0.0f);
      break;
    case Projection::kSpherical: {
      longitude(p, out.uv.x, out.grad_u);
      const float r2 = glm::dot(p, p), r = std::sqrt(r2), rho = std::sqrt(p.x * p.x + p.z * p.z);
      out.uv.y = r > 0.0f ? std::acos(std::clamp(p.y / r, -1.0f, 1.0f)) / kPi : 0.5f;
      // theta = acos(y / r): grad theta = -(e_y - y p / r^2) / rho.
      if (rho > 0.0f) out.grad_v = -(Vec3(0.0f, 1.0f, 0.0f) - (p.y / r2) * p) / (kPi * rho);
      break;
    }
    case Projection::kCylindrical:
      longitude(p, out.uv.x, out.grad_u);
      out.uv.y = 0.5f * (1.0f - p.y);
      out.grad_v = Vec3(0.0f, -0.5f, 0.0f);
      break;
    case Projection::kUv: break;
  }
  return out;
}

}  // namespace

int projection_axis(const TextureMapping& m, int shape_axis) {
  switch (m.axis) {
    case ProjectionAxis::kX: return 0;
    case ProjectionAxis::kY: return 1;
    case ProjectionAxis::kZ: return 2;
    case ProjectionAxis::kShape: break;
  }
  return m.projection == Projection::kPlanar ? 2 : shape_axis;
}

Projected project(Projection projection, int axis, Vec3 p) {
  const bool identity = axis == (projection == Projection::kPlanar ? 2 : 1);
  if (identity) return project_about_y(projection, p);
  // p' = R p: u(p) = u'(R p), so grad u = R^T grad' u.
  const Mat3 r = projection_frame(projection, axis);
  Projected out = project_about_y(projection, r * p);
  out.grad_u = glm::transpose(r) * out.grad_u;
  out.grad_v = glm::transpose(r) * out.grad_v;
  return out;
}

bool dual_basis(Vec3 a, Vec3 b, Vec3& da, Vec3& db) {
  const float aa = glm::dot(a, a), ab = glm::dot(a, b), bb = glm::dot(b, b);
  const float det = aa * bb - ab * ab;
  if (!(det > 1e-10f * aa * bb) || !std::isfinite(det)) return false;
  da = (bb * a - ab * b) / det;
  db = (aa * b - ab * a) / det;
  return is_finite(da) && is_finite(db);
}

MappedPoint map_point(const TextureMapping& m, const SurfaceInteraction& si) {
  MappedPoint out;
  Vec3 gu(0.0f), gv(0.0f);
  bool valid;
  if (m.projection == Projection::kUv) {
    const UvFrame& f = si.texcoord[m.uv_set < 2 ? m.uv_set : 0];
    out.uv = f.uv;
    valid = dual_basis(f.dpdu, f.dpdv, gu, gv);
  } else {
    const Projected p = project(m.projection, projection_axis(m, si.shape_axis), si.object_position);
    out.uv = p.uv;
    // u(p_object(p_world)) with p_object = M p_world + c: the world gradient is M^T grad u, then
    // kept to the tangent plane (only motion along the surface moves the texture).
    const Mat3 mt = glm::transpose(si.object_from_world);
    const Vec3 n = si.shading_normal;
    gu = mt * p.grad_u;
    gv = mt * p.grad_v;
    gu -= glm::dot(gu, n) * n;
    gv -= glm::dot(gv, n) * n;
    valid = is_finite(gu) && is_finite(gv);
  }
  // uv' = offset + R (scale * uv): gradients transform with the same matrix A = R S.
  if (m.scale != Vec2(1.0f) || m.rotation_degrees != 0.0f || m.offset != Vec2(0.0f)) {
    out.uv = transformed_uv(m, out.uv);
    const Mat2 r = texture_rotation(m.rotation_degrees);
    const Vec3 su = m.scale.x * gu, sv = m.scale.y * gv;
    gu = r[0][0] * su + r[1][0] * sv;
    gv = r[0][1] * su + r[1][1] * sv;
  }
  if (valid && dual_basis(gu, gv, out.dpdu, out.dpdv)) {
    out.grad_u = gu;
    out.grad_v = gv;
  } else {
    orthonormal_basis(si.shading_normal, out.dpdu, out.dpdv);  // no frame: bumps stay flat
  }
  return out;
}

UvFootprint uv_footprint(const MappedPoint& p, Vec3 normal, Vec3 direction, float width) {
  if (!(width > 0.0f)) return {};
  const float cos_theta = std::max(std::fabs(glm::dot(direction, normal)), 1e-3f);
  Vec3 across = glm::cross(normal, direction);
  const float len = glm::length(across);
  Vec3 along;
  if (len < 1e-6f) orthonormal_basis(normal, across, along);
  else {
    across /= len;
    along = glm::cross(normal, across);
  }
  const Vec3 a1 = width * across, a2 = (width / cos_theta) * along;
  return UvFootprint(Vec2(glm::dot(p.grad_u, a1), glm::dot(p.grad_v, a1)),
                     Vec2(glm::dot(p.grad_u, a2), glm::dot(p.grad_v, a2)));
}

}  // namespace rt
