#include "core/shapes/shape_sampling.h"

#include <algorithm>
#include <cmath>

#include "core/direction_sampling.h"
#include "core/shapes/cone.h"
#include "core/shapes/cylinder.h"

namespace rt {
namespace {

const float kSqrt2 = std::sqrt(2.0f);

// Splits u.x between a first part of share `first` and the rest: which, and u.x stretched back
// over [0, 1) within it.
bool pick_first(float& x, float first) {
  if (x < first) {
    x = std::min(x / first, 0x1.fffffep-1f);
    return true;
  }
  x = std::min((x - first) / (1.0f - first), 0x1.fffffep-1f);
  return false;
}

}  // namespace

float object_area(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::kSphere: return 4.0f * kPi;
    case ShapeKind::kCube: return 24.0f;
    case ShapeKind::kPlane: return 4.0f;
    case ShapeKind::kCylinder: return 4.0f * kPi;         // side 2 pi, two caps of pi
    case ShapeKind::kCone: return kPi * (1.0f + kSqrt2);  // side pi sqrt(2), base pi
  }
  return 0.0f;
}

ShapePoint sample_object_surface(ShapeKind kind, Vec2 u) {
  ShapePoint s;
  switch (kind) {
    case ShapeKind::kSphere: s.position = s.normal = uniform_sphere(u); return s;
    case ShapeKind::kPlane:
      s.position = Vec3(2.0f * u.x - 1.0f, 0.0f, 2.0f * u.y - 1.0f);
      s.normal = Vec3(0.0f, 1.0f, 0.0f);
      return s;
    case ShapeKind::kCube: {
      const float f = u.x * 6.0f;
      const int face = std::min(static_cast<int>(f), 5);
      const float a = std::min(f - static_cast<float>(face), 0x1.fffffep-1f);
      const int axis = face / 2;
      const float sign = face % 2 == 0 ? 1.0f : -1.0f;
      s.position[axis] = sign;
      s.position[(axis + 1) % 3] = 2.0f * a - 1.0f;
      s.position[(axis + 2) % 3] = 2.0f * u.y - 1.0f;
      s.normal = Vec3(0.0f);
      s.normal[axis] = sign;
      s.part = static_cast<uint32_t>(face);
      return s;
    }
    case ShapeKind::kCylinder: {
      float x = u.x;
      if (pick_first(x, 0.5f)) {  // the side: half the area
        const float phi = 2.0f * kPi * x;
        s.normal = Vec3(std::cos(phi), std::sin(phi), 0.0f);
        s.position = Vec3(s.normal.x, s.normal.y, u.y);
        s.part = kCylinderSide;
        return s;
      }
      const bool base = pick_first(x, 0.5f);
      const Vec2 d = concentric_disk(Vec2(x, u.y));
      s.position = Vec3(d.x, d.y, base ? 0.0f : 1.0f);
      s.normal = Vec3(0.0f, 0.0f, base ? -1.0f : 1.0f);
      s.part = base ? kCylinderBase : kCylinderTop;
      return s;
    }
    case ShapeKind::kCone: {
      float x = u.x;
      if (pick_first(x, kSqrt2 / (1.0f + kSqrt2))) {  // the side, whose ring at z has length 2 pi z
        const float phi = 2.0f * kPi * x;
        const float z = std::sqrt(u.y);
        s.position = Vec3(z * std::cos(phi), z * std::sin(phi), z);
        s.normal = Vec3(std::cos(phi), std::sin(phi), -1.0f) / kSqrt2;
        s.part = kConeSide;
        return s;
      }
      const Vec2 d = concentric_disk(Vec2(x, u.y));
      s.position = Vec3(d.x, d.y, 1.0f);
      s.normal = Vec3(0.0f, 0.0f, 1.0f);
      s.part = kConeBase;
      return s;
    }
  }
  return s;
}

float area_scale(const Transform& transform, Vec3 world_normal) {
  const Mat3 linear(transform.to_world);
  const float stretch = glm::length(glm::transpose(linear) * world_normal);
  return stretch > 0.0f ? std::fabs(glm::determinant(linear)) / stretch : 0.0f;
}

}  // namespace rt
