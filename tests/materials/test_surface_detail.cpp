// Texture mapping, bump and normal maps with real numbers: projections and their gradients,
// the texture transform, ray-cone footprints, Blinn's perturbation on constant and ramp height
// maps, and tangent-space normal maps.
#include <catch2/catch.hpp>

#include "core/shapes/analytic_shape.h"
#include "materials/evaluated_surface.h"
#include "materials/map_point.h"
#include "materials/surface_detail.h"

using namespace rt;

namespace {

// A plane hit straight from above at (x, 0, z): the natural frame u right (+X), v down (+Z).
SurfaceInteraction plane_hit(float x, float z, float scale = 1.0f) {
  AnalyticShape plane;
  plane.kind = ShapeKind::kPlane;
  plane.transform = *make_transform(compose_trs({0, 0, 0}, {0, 0, 0}, {scale, 1, scale}));
  Ray r;
  r.origin = Vec3(x, 5, z);
  r.direction = Vec3(0, -1, 0);
  Hit h;
  REQUIRE(intersect_shape(plane, r, h));
  return shape_surface(plane, r, h);
}

// A width x 1 texture whose value grows linearly with u: texel i holds (i + 0.5) / width, so
// bilinear filtering returns exactly u between the first and last texel centres.
Texture ramp(int width) {
  std::vector<Vec3> texels;
  for (int i = 0; i < width; ++i) texels.push_back(Vec3((static_cast<float>(i) + 0.5f) / static_cast<float>(width)));
  return Texture(width, 1, texels);
}

float degrees_between(Vec3 a, Vec3 b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)) * 180.0f / kPi;
}

}  // namespace

TEST_CASE("projections: (u, v) at known points", "[materials][uv]") {
  CHECK(project(Projection::kPlanar, 2, {-1, 1, 7}).uv == Vec2(0, 0));  // z dropped; top left
  CHECK(project(Projection::kPlanar, 2, {1, -1, 0}).uv == Vec2(1, 1));
  const Projected px = project(Projection::kSpherical, 1, {2, 0, 0});
  CHECK(px.uv.x == Approx(0.25f));
  CHECK(px.uv.y == Approx(0.5f));
  CHECK(project(Projection::kSpherical, 1, {0, 3, 0}).uv.y == Approx(0.0f));  // north pole
  CHECK(project(Projection::kSpherical, 1, {0, -3, 0}).uv.y == Approx(1.0f));
  const Projected c = project(Projection::kCylindrical, 1, {0, 0.5f, -4});
  CHECK(c.uv.x == Approx(0.5f));  // -Z: half a turn
  CHECK(c.uv.y == Approx(0.25f));
}

TEST_CASE("projections: gradients equal central differences, about every axis", "[materials][uv]") {
  const Vec3 points[] = {{0.3f, 0.4f, 0.8f}, {-0.7f, -0.2f, 0.5f}, {0.1f, 0.9f, -0.3f}};
  for (Projection proj : {Projection::kPlanar, Projection::kSpherical, Projection::kCylindrical}) {
    for (int about = 0; about < 3; ++about) {
      for (const Vec3 p : points) {
        const Projected at = project(proj, about, p);
        for (int axis = 0; axis < 3; ++axis) {
          Vec3 e(0.0f);
          e[axis] = 1e-3f;
          const Vec2 d = (project(proj, about, p + e).uv - project(proj, about, p - e).uv) / 2e-3f;
          CHECK(d.x == Approx(at.grad_u[axis]).margin(1e-3));
          CHECK(d.y == Approx(at.grad_v[axis]).margin(1e-3));
        }
      }
    }
  }
}

TEST_CASE("projections: the axis, and a label on a cylinder", "[materials][uv]") {
  // About z, cylindrical turns from +x towards +y, v running down z; about x, from +y towards +z.
  CHECK(project(Projection::kCylindrical, 2, {0, 1, 0.5f}).uv.x == Approx(0.25f));
  CHECK(project(Projection::kCylindrical, 2, {0, 1, 0.5f}).uv.y == Approx(0.25f));
  CHECK(project(Projection::kCylindrical, 0, {0.5f, 0, 1}).uv.x == Approx(0.25f));
  CHECK(project(Projection::kSpherical, 2, {0, 0, 3}).uv.y == Approx(0.0f));  // the pole on +z
  // Planar along y: the top seen from above, -z up the image (the cube's top face); along x: the
  // side seen from +x, y up and -z to the right. Both unmirrored.
  CHECK(project(Projection::kPlanar, 1, {-1, 5, -1}).uv == Vec2(0, 0));
  CHECK(project(Projection::kPlanar, 1, {1, 5, 1}).uv == Vec2(1, 1));
  CHECK(project(Projection::kPlanar, 0, {5, 1, 1}).uv == Vec2(0, 0));
  CHECK(project(Projection::kPlanar, 0, {5, -1, -1}).uv == Vec2(1, 1));
  // A cylinder's default axis is its own (z), and its z in [0, 1] spans the whole image: a
  // label's cylindrical (u, v) is the cylinder's own, at every point of its side.
  TextureMapping label;
  label.projection = Projection::kCylindrical;
  const AnalyticShape can{ShapeKind::kCylinder, 0,
                          *make_transform(compose_trs(Vec3(1, 2, 3), Vec3(-90, 0, 0), Vec3(0.5f, 0.5f, 2)))};
  for (const Vec2 aim : {Vec2(0.1f, 0.3f), Vec2(-0.2f, 0.8f), Vec2(0.15f, 1.7f)}) {
    Ray ray{Vec3(1 + aim.x, 2 + aim.y, 10), Vec3(0, 0, -1)};
    Hit hit;
    REQUIRE(intersect_shape(can, ray, hit));
    const SurfaceInteraction si = shape_surface(can, ray, hit);
    CHECK(si.shape_axis == 2);
    const MappedPoint p = map_point(label, si);
    CHECK(p.uv.x == Approx(si.texcoord[0].uv.x).margin(1e-5));
    CHECK(p.uv.y == Approx(si.texcoord[0].uv.y).margin(1e-5));
  }
  // On a sphere the default stays y; asked for, z.
  const AnalyticShape ball{ShapeKind::kSphere, 0, Transform{}};
  Ray down{Vec3(0, 5, 0.01f), Vec3(0, -1, 0)};
  Hit hit;
  REQUIRE(intersect_shape(ball, down, hit));
  const SurfaceInteraction top = shape_surface(ball, down, hit);
  CHECK(map_point(label, top).uv.y == Approx(0.0f).margin(1e-3));  // y = 1: the top of the image
  label.axis = ProjectionAxis::kZ;
  CHECK(map_point(label, top).uv.y == Approx(0.5f).margin(1e-2));  // z ~ 0: halfway
}

TEST_CASE("mapping: scale, rotation and offset in KHR_texture_transform's order", "[materials][uv]") {
  const SurfaceInteraction si = plane_hit(0.0f, -0.5f);  // natural uv (0.5, 0.25)
  TextureMapping m;
  m.scale = Vec2(2.0f, 4.0f);
  m.rotation_degrees = 90.0f;
  m.offset = Vec2(0.25f, 0.5f);
  const MappedPoint p = map_point(m, si);
  // scale: (1, 1); R(90) (1, 1) = (cos + sin, -sin + cos) = (1, -1); + offset = (1.25, -0.5).
  CHECK(p.uv.x == Approx(1.25f));
  CHECK(p.uv.y == Approx(-0.5f));
  // Tangents and gradients stay duals: moving along dP/du changes u by 1 and v by 0.
  CHECK(glm::dot(p.grad_u, p.dpdu) == Approx(1.0f));
  CHECK(glm::dot(p.grad_v, p.dpdu) == Approx(0.0f).margin(1e-6));
  CHECK(glm::dot(p.grad_v, p.dpdv) == Approx(1.0f));
  // u' = 4 v: along world X (where natural u grows at 1/2 per unit), u' does not change.
  CHECK(p.grad_u.x == Approx(0.0f).margin(1e-6));
  CHECK(p.grad_v.x == Approx(-1.0f));  // v' = -2 u: -2 * 0.5 per unit X
}

TEST_CASE("mapping: the rotation sign of KHR_texture_transform's own example", "[materials][uv]") {
  // "This example utilizes only the lower left quadrant of the source image, rotated clockwise 90 degrees":
  // offset [0, 1], rotation pi/2, scale [0.5, 0.5].
  TextureMapping m;
  m.offset = Vec2(0.0f, 1.0f);
  m.rotation_degrees = 90.0f;
  m.scale = Vec2(0.5f);
  for (const auto& [in, out] : {std::pair{Vec2(0, 0), Vec2(0, 1)}, std::pair{Vec2(1, 0), Vec2(0, 0.5f)},
                                std::pair{Vec2(0, 1), Vec2(0.5f, 1)}, std::pair{Vec2(1, 1), Vec2(0.5f, 0.5f)}}) {
    const Vec2 uv = transformed_uv(m, in);
    CHECK(uv.x == Approx(out.x).margin(1e-6));
    CHECK(uv.y == Approx(out.y).margin(1e-6));
  }
}

TEST_CASE("mapping: planar projection on a scaled sphere works in object space", "[materials][uv]") {
  AnalyticShape sphere;
  sphere.kind = ShapeKind::kSphere;
  sphere.transform = *make_transform(compose_trs({10, 0, 0}, {0, 0, 0}, {2, 2, 2}));
  Ray r;
  r.origin = Vec3(11, 1, 10);
  r.direction = Vec3(0, 0, -1);
  Hit h;
  REQUIRE(intersect_shape(sphere, r, h));
  const SurfaceInteraction si = shape_surface(sphere, r, h);
  TextureMapping m;
  m.projection = Projection::kPlanar;
  const MappedPoint p = map_point(m, si);
  CHECK(p.uv.x == Approx(0.75f));  // object x = 0.5
  CHECK(p.uv.y == Approx(0.25f));  // object y = 0.5
}

TEST_CASE("footprint: a ray cone's width in texture units", "[materials][mip]") {
  const SurfaceInteraction si = plane_hit(0.2f, 0.1f);  // u spans the plane's 2 units
  const MappedPoint p = map_point(TextureMapping{}, si);
  CHECK(uv_footprint(p, si.geometric_normal, {0, -1, 0}, 0.1f).width() == Approx(0.05f));
  // At 60 degrees from the normal the footprint stretches by 1 / cos 60 = 2 along the surface.
  const Vec3 slanted = glm::normalize(Vec3(std::sin(radians(60.0f)), -std::cos(radians(60.0f)), 0.0f));
  CHECK(uv_footprint(p, si.geometric_normal, slanted, 0.1f).width() == Approx(0.1f));
  CHECK(uv_footprint(p, si.geometric_normal, slanted, 0.0f).width() == 0.0f);
  // 0.05 of a 256-texel texture is 12.8 texels: mip level log2(12.8) = 3.68.
  CHECK(Texture(256, 256, std::vector<Vec3>(256 * 256)).mip_level(0.05f) == Approx(std::log2(12.8f)));
}

TEST_CASE("bump: a constant height map leaves the normal unchanged", "[materials][bump]") {
  const std::vector<Texture> textures{Texture(4, 4, std::vector<Vec3>(16, Vec3(0.7f)))};
  Material m;
  m.bump.height.texture = 0;
  m.bump.strength = 3.0f;
  const SurfaceInteraction si = plane_hit(0.3f, -0.6f);
  const EvaluatedSurface s = evaluate_surface(m, si, {0, -1, 0}, textures);
  CHECK(s.n == si.shading_normal);
}

TEST_CASE("bump: a linear ramp tilts the normal by the slope's angle", "[materials][bump]") {
  const std::vector<Texture> textures{ramp(64)};
  for (const float strength : {0.5f, 2.0f, -1.0f}) {
    for (const float scale : {1.0f, 3.0f}) {
      Material m;
      m.bump.height.texture = 0;
      m.bump.height.mapping.wrap = TextureWrap::kClamp;
      m.bump.strength = strength;
      // The plane scaled by `scale`: u spans 2 * scale units of X, so the height strength * u
      // rises strength / (2 scale) per unit X and the normal leans back by atan of that.
      const SurfaceInteraction si = plane_hit(0.1f * scale, 0.0f, scale);
      const EvaluatedSurface s = evaluate_surface(m, si, {0, -1, 0}, textures);
      const float expected = std::atan(std::fabs(strength) / (2.0f * scale)) * 180.0f / kPi;
      INFO("strength " << strength << ", scale " << scale);
      CHECK(degrees_between(s.n, {0, 1, 0}) == Approx(expected).epsilon(1e-4));
      CHECK(s.n.z == Approx(0.0f).margin(1e-6));   // no slope along v
      CHECK((s.n.x < 0.0f) == (strength > 0.0f));  // leans away from the rise
    }
  }
}

TEST_CASE("bump: the proposal's formula N + Bu (N x Ov) - Bv (N x Ou) on a unit frame", "[materials][bump]") {
  const Vec3 n(0, 0, 1);
  const float bu = 0.3f, bv = -0.2f;
  const auto proposal = [&](Vec3 ou, Vec3 ov) {
    return glm::normalize(n + bu * glm::cross(n, ov) - bv * glm::cross(n, ou));
  };
  const auto check = [](Vec3 a, Vec3 b) {
    CHECK(a.x == Approx(b.x));
    CHECK(a.y == Approx(b.y));
    CHECK(a.z == Approx(b.z));
  };
  // With unit tangents whose cross product is N, it is exactly the proposal's expression.
  check(blinn_bump(n, {1, 0, 0}, {0, 1, 0}, bu, bv), proposal({1, 0, 0}, {0, 1, 0}));
  // Our natural frames have u right and v down seen from outside, so Ou x Ov points inwards;
  // there the sign follows the frame, so that a larger height always rises outwards.
  const Vec3 inward = blinn_bump(n, {1, 0, 0}, {0, -1, 0}, bu, bv);
  const Vec3 mirrored = proposal({1, 0, 0}, {0, -1, 0});
  check(inward, Vec3(-mirrored.x, -mirrored.y, mirrored.z));
}

TEST_CASE("normal map: a flat texel leaves the normal unchanged, a tilted one tilts it", "[materials][normalmap]") {
  const Vec3 n(0, 1, 0), t(1, 0, 0);
  CHECK(tangent_space_normal(n, t, 1.0f, {0.5f, 0.5f, 1.0f}, 1.0f) == n);
  // (1, 0.5, 1) is (1, 0, 1) / sqrt 2 in tangent space: 45 degrees towards the tangent.
  const Vec3 towards_t = tangent_space_normal(n, t, 1.0f, {1.0f, 0.5f, 1.0f}, 1.0f);
  CHECK(degrees_between(towards_t, n) == Approx(45.0f));
  CHECK(towards_t.x > 0.0f);
  // y runs along cross(n, t) * handedness: here (0, 0, -1), flipped by handedness -1.
  CHECK(tangent_space_normal(n, t, 1.0f, {0.5f, 1.0f, 1.0f}, 1.0f).z < 0.0f);
  CHECK(tangent_space_normal(n, t, -1.0f, {0.5f, 1.0f, 1.0f}, 1.0f).z > 0.0f);
  // The scale multiplies x and y: halving it halves tan(tilt).
  CHECK(std::tan(radians(degrees_between(tangent_space_normal(n, t, 1.0f, {1.0f, 0.5f, 1.0f}, 0.5f), n))) ==
        Approx(0.5f));
}

TEST_CASE("normal map: through evaluate_surface, y points up the image", "[materials][normalmap]") {
  // On the plane seen from above, up the image is -Z (v runs towards +Z): a texel (0.5, 1, 1)
  // tilts the normal 45 degrees towards -Z.
  const std::vector<Texture> textures{Texture(2, 2, std::vector<Vec3>(4, Vec3(0.5f, 1.0f, 1.0f)))};
  Material m;
  m.normal_map.map.texture = 0;
  const EvaluatedSurface s = evaluate_surface(m, plane_hit(0.2f, 0.3f), {0, -1, 0}, textures);
  CHECK(degrees_between(s.n, {0, 1, 0}) == Approx(45.0f));
  CHECK(s.n.z < 0.0f);
  CHECK(s.n.x == Approx(0.0f).margin(1e-6));
}

TEST_CASE("texture: replaces kd, tinted by kd, switched off by the detail switches", "[materials][texture]") {
  const std::vector<Texture> textures{Texture(1, 1, {Vec3(0.2f, 0.4f, 0.6f)})};
  Material m;
  m.kd = Vec3(0.5f);
  m.texture.texture = 0;
  const SurfaceInteraction si = plane_hit(0.0f, 0.0f);
  CHECK(evaluate_surface(m, si, {0, -1, 0}, textures).diffuse == Vec3(0.1f, 0.2f, 0.3f));
  SurfaceDetailSwitches off;
  off.textures = false;
  CHECK(evaluate_surface(m, si, {0, -1, 0}, textures, 0.0f, off).diffuse == Vec3(0.5f));
}
