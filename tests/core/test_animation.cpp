// Keyframe sampling (at keys, between keys, outside the range) and node transform order.
#include <catch2/catch.hpp>

#include "core/animation/track.h"
#include "core/scene_graph.h"

using namespace rt;

namespace {

Track vec_track(Interpolation interpolation, std::vector<float> times, std::vector<Vec4> values) {
  Track t;
  t.part = TrsPart::kTranslation;
  t.interpolation = interpolation;
  t.keys = std::make_shared<const Keyframes>(Keyframes{std::move(times), std::move(values)});
  return t;
}

Vec4 quat_y(float degrees) {
  const Quat q = axis_angle_to_quat(Vec3(0, 1, 0), degrees);
  return Vec4(q.x, q.y, q.z, q.w);
}

}  // namespace

TEST_CASE("animation: linear and step tracks at keys, between keys and outside the range", "[animation]") {
  const Track linear = vec_track(Interpolation::kLinear, {1.0f, 3.0f}, {Vec4(0, 0, 0, 0), Vec4(4, -2, 8, 0)});
  CHECK(sample_track(linear, 1.0f).x == 0.0f);
  CHECK(sample_track(linear, 3.0f).x == 4.0f);
  CHECK(sample_track(linear, 1.5f).x == Approx(1.0f));  // a quarter of the way
  CHECK(sample_track(linear, 1.5f).y == Approx(-0.5f));
  CHECK(sample_track(linear, 2.0f).z == Approx(4.0f));
  CHECK(sample_track(linear, -10.0f).x == 0.0f);  // before the first key: the first value
  CHECK(sample_track(linear, 99.0f).x == 4.0f);   // after the last key: the last value

  const Track step = vec_track(Interpolation::kStep, {0.0f, 1.0f, 2.0f}, {Vec4(1), Vec4(2), Vec4(3)});
  CHECK(sample_track(step, 0.999f).x == 1.0f);
  CHECK(sample_track(step, 1.0f).x == 2.0f);
  CHECK(sample_track(step, 1.5f).x == 2.0f);
  CHECK(sample_track(step, 5.0f).x == 3.0f);
}

TEST_CASE("animation: rotations slerp at constant speed, the short way round", "[animation]") {
  Track t;
  t.part = TrsPart::kRotation;
  t.keys = std::make_shared<const Keyframes>(Keyframes{{0.0f, 1.0f}, {quat_y(0), quat_y(90)}});
  for (const float s : {0.25f, 0.5f, 0.8f}) {
    const Vec4 q = sample_track(t, s);
    CHECK(glm::length(q) == Approx(1.0f));
    // The angle about Y grows linearly: 2 acos(w) = 90 s degrees.
    CHECK(glm::degrees(2.0f * std::acos(q.w)) == Approx(90.0f * s).margin(1e-3));
    CHECK(q.x == Approx(0.0f).margin(1e-6));
  }
  // 350 degrees from 0 is 10 degrees the other way: slerp takes that way (q and -q agree).
  t.keys = std::make_shared<const Keyframes>(Keyframes{{0.0f, 1.0f}, {quat_y(0), quat_y(350)}});
  const Vec4 mid = sample_track(t, 0.5f);
  const Quat q(mid.w, mid.x, mid.y, mid.z);
  const Vec3 x = q * Vec3(1, 0, 0);
  CHECK(glm::degrees(std::atan2(-x.z, x.x)) == Approx(-5.0f).margin(1e-3));
}

TEST_CASE("animation: cubic spline follows glTF's Hermite form", "[animation]") {
  // Keys at t = 0 and t = 2, values 0 and 1, out-tangent of the first 3, in-tangent of the second -1.
  Track t;
  t.part = TrsPart::kTranslation;
  t.interpolation = Interpolation::kCubicSpline;
  // (in, value, out) per key
  t.keys = std::make_shared<const Keyframes>(
      Keyframes{{0.0f, 2.0f}, {Vec4(9), Vec4(0), Vec4(3), Vec4(-1), Vec4(1), Vec4(9)}});
  // At s = 0.5 the Hermite weights are 0.5, 0.125, 0.5, -0.125 and tangents scale by dt = 2:
  // p = 0.5 * 0 + 0.125 * (2 * 3) + 0.5 * 1 - 0.125 * (2 * -1) = 0.75 + 0.5 + 0.25 = 1.5.
  CHECK(sample_track(t, 1.0f).x == Approx(1.5f));
  CHECK(sample_track(t, 0.0f).x == 0.0f);  // at the keys: the values, never the tangents
  CHECK(sample_track(t, 2.0f).x == 1.0f);
  CHECK(sample_track(t, 3.0f).x == 1.0f);
}

TEST_CASE("animation: node transforms compose parent * T * R * S, tracks replace one part", "[animation]") {
  SceneGraph g;
  SceneNode parent, child;
  parent.trs.translation = Vec3(10, 0, 0);
  parent.trs.rotation = axis_angle_to_quat(Vec3(0, 1, 0), 90);
  child.parent = 0;
  child.trs.translation = Vec3(1, 0, 0);
  child.trs.scale = Vec3(2);
  g.nodes = {parent, child};
  // The child's origin: its translation (1, 0, 0) turned 90 degrees about Y -> (0, 0, -1), moved to x = 10.
  std::vector<Mat4> w = g.pose_at(0.0f).world;
  Vec3 origin = Vec3(w[1] * Vec4(0, 0, 0, 1));
  CHECK(origin.x == Approx(10.0f));
  CHECK(origin.z == Approx(-1.0f));
  // A point at x = 1 in the child: scaled to 2 first, then translated to 3, then turned, then moved.
  const Vec3 p = Vec3(w[1] * Vec4(1, 0, 0, 1));
  CHECK(p.x == Approx(10.0f));
  CHECK(p.z == Approx(-3.0f));

  Track lift = vec_track(Interpolation::kLinear, {0.0f, 1.0f}, {Vec4(1, 0, 0, 0), Vec4(1, 4, 0, 0)});
  lift.node = 1;
  g.tracks = {lift};
  w = g.pose_at(0.5f).world;
  origin = Vec3(w[1] * Vec4(0, 0, 0, 1));
  CHECK(origin.y == Approx(2.0f));  // the track replaced the translation; scale and parent stay
  CHECK(Vec3(w[1] * Vec4(1, 0, 0, 1)).z == Approx(-3.0f));
}
