#include "core/accel/shadow_volume.h"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

float sum_abs(Vec3 v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }

}  // namespace

ShadowVolume::ShadowVolume(Vec3 apex, Vec3 corner, Vec3 edge1, Vec3 edge2)
    : apex_(apex), base_{corner, corner + edge1, corner + edge1 + edge2, corner + edge2} {
  // A ray's points stray from the segments the pyramid holds by a few ulps of these coordinates
  // (its direction is taken from the surface point, its origin's rounding offset away; a hit
  // strays from its primitive's box by as little: the BVH's own walk relies on that); the margin
  // is a hundred times that, so no ray inside is ever culled.
  float largest = std::max(1.0f, max_abs_component(apex));
  bounds_.extend(apex);
  for (const Vec3& p : base_) {
    bounds_.extend(p);
    largest = std::max(largest, max_abs_component(p));
  }
  margin_ = 1e-5f * largest;
  bounds_.lo -= Vec3(margin_);
  bounds_.hi += Vec3(margin_);
  // The base, then the four sides, each through the apex and one edge of the base; each normal
  // turned away from a point inside.
  const Vec3 inside = 0.2f * (apex + base_[0] + base_[1] + base_[2] + base_[3]);
  for (int f = 0; f < kFaces; ++f) {
    const Vec3 on = f == 0 ? corner : apex;
    const Vec3 n = f == 0 ? glm::cross(edge1, edge2) : glm::cross(base_[f - 1] - apex, base_[f % 4] - apex);
    const float length = sum_abs(n);  // >= its length: the margin only grows
    const float towards_inside = glm::dot(n, inside - on);
    // A face seen edge-on (the apex in or near the light's plane) has no side worth trusting:
    // the bounding box alone bounds it there.
    if (!(std::fabs(towards_inside) > 1e-4f * length * sum_abs(inside - on)) || !std::isfinite(length)) {
      normal_[f] = Vec3(0.0f);
      offset_[f] = kInfinity;
      continue;
    }
    normal_[f] = towards_inside > 0.0f ? -n : n;
    offset_[f] = glm::dot(normal_[f], on) + margin_ * length;
  }
}

bool ShadowVolume::meets(const Aabb& box) const {
  for (int a = 0; a < 3; ++a)
    if (!(box.lo[a] <= bounds_.hi[a] && box.hi[a] >= bounds_.lo[a])) return false;
  for (int f = 0; f < kFaces; ++f) {
    const Vec3& n = normal_[f];
    // The box's corner farthest against the normal: if even it lies beyond the face, all do.
    const Vec3 nearest(n.x >= 0.0f ? box.lo.x : box.hi.x, n.y >= 0.0f ? box.lo.y : box.hi.y,
                       n.z >= 0.0f ? box.lo.z : box.hi.z);
    if (glm::dot(n, nearest) > offset_[f]) return false;
  }
  return true;
}

bool ShadowVolume::beside_plane(const Transform& plane) const {
  const float origin_y = plane.point_to_object(apex_).y;  // as transformed_ray makes it
  if (!(origin_y != 0.0f) || !std::isfinite(origin_y)) return false;
  // A direction's object-space y is g . d, g the second row of the linear part. Over the base it
  // is linear, so its least value is at a corner; each corner's is asked to be 1e-4 of its
  // largest possible size, a thousand times what the products' rounding can reach, so that no
  // ray's computed direction.y has the other sign. Plus the margin: a light sample's direction
  // is taken from the surface point, a rounding away from the rays' origin.
  const Mat3 linear(plane.to_object);
  const Vec3 g(linear[0][1], linear[1][1], linear[2][1]);
  const float g_size = sum_abs(g);
  for (const Vec3& corner : base_) {
    const Vec3 to = corner - apex_;
    const float along = glm::dot(g, to);
    const float needed = g_size * (1e-4f * sum_abs(to) + margin_);
    if (!(origin_y > 0.0f ? along > needed : along < -needed)) return false;
  }
  return true;
}

}  // namespace rt
