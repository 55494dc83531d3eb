// The region that every shadow ray from one point to a rectangular light sweeps: the pyramid of
// the point (its apex) and the light's parallelogram (its base). A point's 16 shadow rays to an
// area light stay inside it, so a primitive whose box lies outside it cannot block any of them,
// and a BVH query (Bvh::leaves_meeting) finds, once per point, the few leaves that can: on a
// floor or a wall away from everything, none but the floor's or the wall's own plane, which no
// ray leaving it towards the light can cross (beside_plane). Such a point's rays then meet
// nothing, without a walk (docs/benchmark.md, "Round two, a ninth session").
#pragma once

#include "core/aabb.h"
#include "core/math.h"
#include "core/transform.h"

namespace rt {

class ShadowVolume {
 public:
  // The pyramid of `apex` and the parallelogram corner + [0, 1] edge1 + [0, 1] edge2.
  ShadowVolume(Vec3 apex, Vec3 corner, Vec3 edge1, Vec3 edge2);

  // False only when the box lies wholly outside the pyramid (grown by far more than the rounding
  // of any ray inside it): outside its bounding box, or beyond one of its five faces. True may
  // still be a box that misses it (no edge-edge tests): the answer is conservative, never wrong.
  bool meets(const Aabb& box) const;
  // True when no ray from the apex to the base can cross the plane y = 0 of `plane`'s object
  // space (a plane shape's) in front of its origin: the apex, as intersect_plane sees it (the
  // same floats), lies off the plane on the side the whole base lies on, by far more than
  // rounding. Then every such ray's t = -origin.y / direction.y is negative.
  bool beside_plane(const Transform& plane) const;

 private:
  static constexpr int kFaces = 5;
  Vec3 apex_;
  Vec3 base_[4];
  float margin_;          // far more than any ray's rounding: 1e-5 of the largest coordinate
  Aabb bounds_;           // of the five vertices, grown by the margin
  Vec3 normal_[kFaces];   // outward, not unit; a face too thin to have one has 0 and culls nothing
  float offset_[kFaces];  // a box beyond the face: dot(normal, its nearest corner) > offset
};

}  // namespace rt
