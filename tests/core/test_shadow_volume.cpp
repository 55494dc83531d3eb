// The shadow volume of a point and a rect light (core/accel/shadow_volume.h) and the BVH query
// over it (Bvh::leaves_meeting): the leaves it finds hold every crossing of every ray inside it,
// so that asking them alone answers as the whole walk does.
#include <algorithm>
#include <tuple>
#include <vector>

#include <catch2/catch.hpp>

#include "core/accel/bvh.h"
#include "core/accel/bvh_traversal.h"
#include "core/accel/shadow_volume.h"
#include "core/rng.h"

using namespace rt;

namespace {

Aabb box_around(Vec3 c, float half) { return Aabb{c - Vec3(half), c + Vec3(half)}; }

Vec3 random_in(Rng& rng, Vec3 lo, Vec3 hi) {
  return lo + (hi - lo) * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
}

using Crossing = std::tuple<float, uint32_t, uint32_t, uint32_t>;  // t, prim, part, operand

std::vector<Crossing> walk_crossings(const Bvh& bvh, const Ray& ray) {
  std::vector<Crossing> out;
  bvh.for_each_hit(ray, [&](const Hit& h) {
    out.emplace_back(h.t, h.prim, h.part, h.operand);
    return false;
  });
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Crossing> leaf_crossings(const Bvh& bvh, const Ray& ray, const BvhLeafSet& leaves) {
  std::vector<Crossing> out;
  auto add = [&](const Hit& h) {
    out.emplace_back(h.t, h.prim, h.part, h.operand);
    return false;
  };
  for (int k = 0; k < leaves.count; ++k) bvh.visit_hits_in_leaf(ray, leaves.leaf[k], add);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("A shadow volume meets the boxes between its point and the light, and not those beside it",
          "[shadow_volume]") {
  // From just above the origin to a 2 x 2 light 4 up: at height 2 the pyramid spans x in
  // [-0.5, 0.5] (half way from the point to the light's half-width of 1).
  const ShadowVolume v(Vec3(0.0f, 0.001f, 0.0f), Vec3(-1.0f, 4.0f, -1.0f), Vec3(2.0f, 0.0f, 0.0f),
                       Vec3(0.0f, 0.0f, 2.0f));
  CHECK(v.meets(box_around(Vec3(0.0f, 2.0f, 0.0f), 0.1f)));
  CHECK(v.meets(box_around(Vec3(0.45f, 2.0f, 0.0f), 0.01f)));
  CHECK_FALSE(v.meets(box_around(Vec3(0.6f, 2.0f, 0.0f), 0.05f)));  // beside a side face, inside the bounding box
  CHECK_FALSE(v.meets(box_around(Vec3(-0.6f, 2.0f, 0.3f), 0.05f)));
  CHECK_FALSE(v.meets(box_around(Vec3(0.0f, 5.0f, 0.0f), 0.5f)));   // beyond the light
  CHECK_FALSE(v.meets(box_around(Vec3(0.0f, -1.0f, 0.0f), 0.5f)));  // under the point
  CHECK_FALSE(v.meets(Aabb{}));                                     // an empty (inverted) box
  CHECK(v.meets(Aabb{Vec3(-50.0f, -50.0f, -50.0f), Vec3(50.0f)}));  // one holding it all

  // Every point of every ray inside is in a box the volume meets, however small the box.
  Rng rng(7);
  for (int i = 0; i < 5000; ++i) {
    const Vec3 on_light = Vec3(-1.0f, 4.0f, -1.0f) + Vec3(2.0f * rng.next_float(), 0.0f, 2.0f * rng.next_float());
    const Vec3 p = Vec3(0.0f, 0.001f, 0.0f) + rng.next_float() * (on_light - Vec3(0.0f, 0.001f, 0.0f));
    REQUIRE(v.meets(box_around(p, 1e-7f)));
  }

  // A point in the light's own plane: the side faces have no side to trust, and the bounding box
  // alone culls (the segment towards the light is still met).
  const ShadowVolume flat(Vec3(3.0f, 4.0f, 0.0f), Vec3(-1.0f, 4.0f, -1.0f), Vec3(2.0f, 0.0f, 0.0f),
                          Vec3(0.0f, 0.0f, 2.0f));
  CHECK(flat.meets(box_around(Vec3(2.0f, 4.0f, 0.0f), 0.01f)));
  CHECK_FALSE(flat.meets(box_around(Vec3(2.0f, 5.0f, 0.0f), 0.01f)));
}

TEST_CASE("A shadow volume passes beside a plane only when its point and its light lie on one side of it",
          "[shadow_volume]") {
  const Transform floor = *make_transform(compose_trs(Vec3(0.0f), Vec3(0.0f), Vec3(5.0f, 1.0f, 5.0f)));
  const Vec3 e1(2.0f, 0.0f, 0.0f), e2(0.0f, 0.0f, 2.0f);
  // A point a rounding above the floor, the light above: no ray down to it.
  CHECK(ShadowVolume(Vec3(0.3f, 1e-6f, 0.2f), Vec3(-1.0f, 4.0f, -1.0f), e1, e2).beside_plane(floor));
  // Both below.
  CHECK(ShadowVolume(Vec3(0.3f, -1e-6f, 0.2f), Vec3(-1.0f, -4.0f, -1.0f), e1, e2).beside_plane(floor));
  // The light on the other side, or the point: rays cross it.
  CHECK_FALSE(ShadowVolume(Vec3(0.3f, 1e-6f, 0.2f), Vec3(-1.0f, -4.0f, -1.0f), e1, e2).beside_plane(floor));
  CHECK_FALSE(ShadowVolume(Vec3(0.3f, -1e-6f, 0.2f), Vec3(-1.0f, 4.0f, -1.0f), e1, e2).beside_plane(floor));
  // A point on the plane itself, a light straddling it, a light edge-on in the plane: no.
  CHECK_FALSE(ShadowVolume(Vec3(0.3f, 0.0f, 0.2f), Vec3(-1.0f, 4.0f, -1.0f), e1, e2).beside_plane(floor));
  CHECK_FALSE(
      ShadowVolume(Vec3(0.3f, 1e-6f, 0.2f), Vec3(-1.0f, -1.0f, -1.0f), e1, Vec3(0.0f, 2.0f, 0.0f)).beside_plane(floor));
  CHECK_FALSE(ShadowVolume(Vec3(0.3f, 1e-6f, 0.2f), Vec3(2.0f, 0.0f, -1.0f), e1, e2).beside_plane(floor));
  // A tilted wall, the light in front of it.
  const Transform wall = *make_transform(compose_trs(Vec3(0.0f, 3.0f, -2.5f), Vec3(90.0f, 0.0f, 0.0f), Vec3(9.0f)));
  const Vec3 on_wall = wall.point_to_world(Vec3(0.2f, 0.0f, 0.1f)) + Vec3(0.0f, 0.0f, 1e-5f);
  const bool front = wall.point_to_object(on_wall).y > 0.0f;
  const Vec3 light = front == (wall.point_to_object(Vec3(0.0f, 3.0f, 5.0f)).y > 0.0f) ? Vec3(-1.0f, 3.0f, 5.0f)
                                                                                      : Vec3(-1.0f, 3.0f, -10.0f);
  CHECK(ShadowVolume(on_wall, light, e1, e2).beside_plane(wall));
}

TEST_CASE("The leaves a shadow volume meets hold every crossing of every ray inside it", "[shadow_volume][bvh]") {
  Rng rng(11);
  PrimitiveSet prims;
  const ShapeKind kinds[] = {ShapeKind::kSphere, ShapeKind::kCube, ShapeKind::kCylinder, ShapeKind::kCone};
  for (int i = 0; i < 48; ++i) {
    AnalyticShape s;
    s.kind = kinds[i % 4];
    s.transform = *make_transform(compose_trs(random_in(rng, Vec3(-8.0f), Vec3(8.0f)),
                                              random_in(rng, Vec3(-180.0f), Vec3(180.0f)),
                                              random_in(rng, Vec3(0.2f), Vec3(0.9f))));
    prims.shapes.push_back(s);
  }
  // A floor the volumes' points lie on, and a few walls.
  std::vector<Transform> planes;
  planes.push_back(*make_transform(compose_trs(Vec3(0.0f, -8.5f, 0.0f), Vec3(0.0f), Vec3(12.0f, 1.0f, 12.0f))));
  for (int i = 0; i < 3; ++i)
    planes.push_back(*make_transform(
        compose_trs(random_in(rng, Vec3(-8.0f), Vec3(8.0f)), random_in(rng, Vec3(-180.0f), Vec3(180.0f)), Vec3(3.0f))));
  for (const Transform& t : planes) prims.shapes.push_back(AnalyticShape{ShapeKind::kPlane, 0, t});
  for (int i = 0; i < 40; ++i) {
    const Vec3 c = random_in(rng, Vec3(-8.0f), Vec3(8.0f));
    prims.triangles.push_back(PackedTriangle::from_vertices(c, c + Vec3(0.5f, 0.0f, 0.1f), c + Vec3(0.0f, 0.5f, 0.2f)));
  }
  const Bvh bvh(prims, BvhBuildOptions{});

  int sets[3] = {0, 0, 0};  // none, one, more leaves
  int too_many = 0, rays_crossing = 0, floors_left_out = 0;
  for (int v = 0; v < 3000; ++v) {
    // Half the points on the floor, a rounding above it, the light above; the rest anywhere.
    const bool on_floor = v % 2 == 0;
    const Vec3 apex = on_floor
                          ? Vec3(-10.0f + 20.0f * rng.next_float(), -8.5f + 1e-5f, -10.0f + 20.0f * rng.next_float())
                          : random_in(rng, Vec3(-9.0f), Vec3(9.0f));
    const Vec3 corner = apex + (on_floor ? Vec3(-2.0f + 4.0f * rng.next_float(), 1.0f + 6.0f * rng.next_float(),
                                                -2.0f + 4.0f * rng.next_float())
                                         : random_in(rng, Vec3(-4.0f), Vec3(4.0f)));
    // Every tenth light wide, for volumes that meet more leaves than a set holds.
    const float size = v % 10 == 1 ? 8.0f : 1.0f;
    const Vec3 e1 = size * random_in(rng, Vec3(-1.0f), Vec3(1.0f)), e2 = glm::cross(e1, Vec3(0.3f, 1.0f, -0.2f));
    const ShadowVolume volume(apex, corner, e1, e2);
    BvhLeafSet leaves;
    if (!bvh.leaves_meeting(volume, leaves)) {
      ++too_many;
      continue;
    }
    ++sets[std::min(leaves.count, 2)];
    if (on_floor && volume.beside_plane(planes[0])) ++floors_left_out;
    for (int r = 0; r < 24; ++r) {
      const Vec3 to = corner + rng.next_float() * e1 + rng.next_float() * e2 - apex;
      const float distance = glm::length(to);
      const Ray ray(apex, to / distance, 0.0f, distance * (1.0f - 1e-4f));
      const std::vector<Crossing> all = walk_crossings(bvh, ray);
      REQUIRE(leaf_crossings(bvh, ray, leaves) == all);
      rays_crossing += all.empty() ? 0 : 1;
    }
  }
  INFO("sets of none, one, more leaves: " << sets[0] << ", " << sets[1] << ", " << sets[2] << "; too many " << too_many
                                          << "; rays crossing something " << rays_crossing);
  CHECK(sets[0] > 300);
  CHECK(sets[1] > 300);
  CHECK(sets[2] > 100);
  CHECK(too_many > 10);
  CHECK(rays_crossing > 1000);
  CHECK(floors_left_out > 500);
}
