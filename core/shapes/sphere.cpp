#include "core/shapes/sphere.h"

#include "core/float_error.h"
#include "core/shapes/quadratic.h"

namespace rt {

namespace {

// The line's parameters where it crosses the unit sphere, t0 <= t1; false if it misses.
bool sphere_roots(const Ray& ray, double& t0, double& t1) {
  const glm::dvec3 o(ray.origin), d(ray.direction);
  return solve_quadratic(glm::dot(d, d), 2.0 * glm::dot(o, d), glm::dot(o, o) - 1.0, t0, t1);
}

// The nearer root inside (tmin, tmax) into `hit`; false if neither is.
bool nearer_root(double t0, double t1, float tmin, float tmax, Hit& hit) {
  for (const double t : {t0, t1}) {
    if (t > tmin && t < tmax) {
      hit.t = static_cast<float>(t);
      hit.part = 0;
      return true;
    }
  }
  return false;
}

}  // namespace

bool intersect_sphere(const Ray& ray, Hit& hit) {
  double t0, t1;
  return sphere_roots(ray, t0, t1) && nearer_root(t0, t1, ray.tmin, ray.tmax, hit);
}

bool intersect_sphere_twice(const Ray& ray, Hit& first, Hit& second) {
  double t0, t1;
  return sphere_roots(ray, t0, t1) && nearer_root(t0, t1, ray.tmin, ray.tmax, first) &&
         nearer_root(t0, t1, next_float_up(first.t), ray.tmax, second);
}

SurfacePatch sphere_patch(Vec3 p, uint32_t /*part*/) {
  SurfacePatch s;
  s.normal = glm::normalize(p);
  const Vec3 n = s.normal;
  float phi = std::atan2(n.x, n.z);
  if (phi < 0.0f) phi += 2.0f * kPi;
  const float theta = std::acos(std::clamp(n.y, -1.0f, 1.0f));
  s.uv = Vec2(phi / (2.0f * kPi), theta / kPi);
  // P(u,v) = (sin(theta) sin(phi), cos(theta), sin(theta) cos(phi)), phi = 2 pi u, theta = pi v.
  const float sin_theta = std::sin(theta);
  s.dpdu = 2.0f * kPi * Vec3(n.z, 0.0f, -n.x);
  s.dpdv = kPi * Vec3(std::cos(theta) * std::sin(phi), -sin_theta, std::cos(theta) * std::cos(phi));
  if (sin_theta < 1e-6f) s.dpdu = 2.0f * kPi * Vec3(std::cos(phi), 0.0f, -std::sin(phi)) * 1e-6f;  // pole
  return s;
}

}  // namespace rt
