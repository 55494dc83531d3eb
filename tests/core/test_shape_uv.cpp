// Natural texture coordinates of every analytic shape at known points (poles, seams, caps, cube
// faces), and their tangent frames: orthogonal, u right and v down seen from outside (so images
// read unmirrored), and equal to finite differences of the surface position.
#include <catch2/catch.hpp>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>

#include "core/material.h"
#include "core/shapes/analytic_shape.h"
#include "core/shapes/cone.h"
#include "core/shapes/cube.h"
#include "core/shapes/cylinder.h"

using namespace rt;

namespace {

struct Known {
  ShapeKind kind;
  uint32_t part;
  Vec3 p;
  Vec2 uv;
  const char* where;
};

// The point moved back onto the surface of `kind` (part), after a small step off it.
Vec3 onto_surface(ShapeKind kind, uint32_t part, Vec3 p) {
  switch (kind) {
    case ShapeKind::kSphere: return glm::normalize(p);
    case ShapeKind::kPlane: return Vec3(p.x, 0.0f, p.z);
    case ShapeKind::kCube: p[static_cast<int>(part / 2)] = (part & 1u) ? -1.0f : 1.0f; return p;
    case ShapeKind::kCylinder:
      if (part == kCylinderSide) return Vec3(glm::normalize(Vec2(p)), p.z);
      return Vec3(p.x, p.y, part == kCylinderTop ? 1.0f : 0.0f);
    case ShapeKind::kCone:
      if (part == kConeSide) return Vec3(p.z * glm::normalize(Vec2(p)), p.z);
      return Vec3(p.x, p.y, 1.0f);
  }
  return p;
}

const Known kKnown[] = {
    {ShapeKind::kSphere, 0, {0, 0, 1}, {0.0f, 0.5f}, "sphere: +Z on the equator, the seam"},
    {ShapeKind::kSphere, 0, {1, 0, 0}, {0.25f, 0.5f}, "sphere: +X"},
    {ShapeKind::kSphere, 0, {0, 0, -1}, {0.5f, 0.5f}, "sphere: -Z"},
    {ShapeKind::kSphere, 0, {-1, 0, 0}, {0.75f, 0.5f}, "sphere: -X"},
    {ShapeKind::kSphere, 0, {0, 1, 0}, {0.0f, 0.0f}, "sphere: north pole"},
    {ShapeKind::kSphere, 0, {0, -1, 0}, {0.0f, 1.0f}, "sphere: south pole"},
    {ShapeKind::kPlane, 0, {-1, 0, -1}, {0.0f, 0.0f}, "plane: far left corner"},
    {ShapeKind::kPlane, 0, {1, 0, 1}, {1.0f, 1.0f}, "plane: near right corner"},
    {ShapeKind::kCube, 4, {0, 0, 1}, {0.5f, 0.5f}, "cube +Z: centre"},
    {ShapeKind::kCube, 4, {-1, 1, 1}, {0.0f, 0.0f}, "cube +Z: top left"},
    {ShapeKind::kCube, 5, {1, 1, -1}, {0.0f, 0.0f}, "cube -Z: top left"},
    {ShapeKind::kCube, 0, {1, 1, 1}, {0.0f, 0.0f}, "cube +X: top left"},
    {ShapeKind::kCube, 1, {-1, 1, -1}, {0.0f, 0.0f}, "cube -X: top left"},
    {ShapeKind::kCube, 2, {-1, 1, -1}, {0.0f, 0.0f}, "cube +Y: top left (far side)"},
    {ShapeKind::kCube, 3, {-1, -1, 1}, {0.0f, 0.0f}, "cube -Y: top left (near side)"},
    {ShapeKind::kCube, 0, {1, -1, -1}, {1.0f, 1.0f}, "cube +X: bottom right"},
    {ShapeKind::kCylinder, kCylinderSide, {1, 0, 1}, {0.0f, 0.0f}, "cylinder side: +X at the top, the seam"},
    {ShapeKind::kCylinder, kCylinderSide, {0, 1, 0}, {0.25f, 1.0f}, "cylinder side: +Y at the base"},
    {ShapeKind::kCylinder, kCylinderTop, {-1, 1, 1}, {0.0f, 0.0f}, "cylinder top cap"},
    {ShapeKind::kCylinder, kCylinderBase, {1, 1, 0}, {0.0f, 0.0f}, "cylinder base cap"},
    {ShapeKind::kCone, kConeSide, {0, 0.5f, 0.5f}, {0.75f, 0.5f}, "cone side: +Y half way"},
    {ShapeKind::kCone, kConeSide, {-1, 0, 1}, {0.5f, 1.0f}, "cone side: -X at the base"},
    {ShapeKind::kCone, kConeBase, {-1, 1, 1}, {0.0f, 0.0f}, "cone base cap"},
};

}  // namespace

TEST_CASE("natural uv: each shape at known points", "[shapes][uv]") {
  for (const Known& k : kKnown) {
    INFO(k.where);
    const SurfacePatch s = object_space_patch(k.kind, k.p, k.part);
    CHECK(s.uv.x == Approx(k.uv.x).margin(1e-6));
    CHECK(s.uv.y == Approx(k.uv.y).margin(1e-6));
  }
  // Just west of the sphere's seam, u is nearly 1: the seam is where u wraps.
  CHECK(object_space_patch(ShapeKind::kSphere, glm::normalize(Vec3(-1e-3f, 0, 1)), 0).uv.x ==
        Approx(1.0f).margin(1e-3));
}

TEST_CASE("natural uv: tangent frames are orthogonal, read unmirrored and match finite differences", "[shapes][uv]") {
  for (const Known& k : kKnown) {
    INFO(k.where);
    // Moved a little towards an interior point, off poles, seams and edges, so that a small step
    // stays on the same part.
    const Vec3 p = onto_surface(k.kind, k.part, glm::mix(k.p, Vec3(0.3f, 0.4f, 0.5f), 0.3f));
    const SurfacePatch s = object_space_patch(k.kind, p, k.part);
    const Vec3 t = glm::normalize(s.dpdu), b = glm::normalize(s.dpdv);
    CHECK(glm::dot(t, b) == Approx(0.0f).margin(1e-5));
    CHECK(glm::dot(t, s.normal) == Approx(0.0f).margin(1e-5));
    CHECK(glm::dot(b, s.normal) == Approx(0.0f).margin(1e-5));
    CHECK(glm::dot(glm::cross(s.dpdu, s.dpdv), s.normal) < 0.0f);  // right x down points into the surface
    const float e = 1e-3f;
    for (int axis = 0; axis < 2; ++axis) {
      const Vec3 step = axis == 0 ? s.dpdu : s.dpdv;
      const Vec2 du = object_space_patch(k.kind, onto_surface(k.kind, k.part, p + e * step), k.part).uv -
                      object_space_patch(k.kind, onto_surface(k.kind, k.part, p - e * step), k.part).uv;
      CHECK(du[axis] / (2.0f * e) == Approx(1.0f).epsilon(2e-3));
      CHECK(du[1 - axis] / (2.0f * e) == Approx(0.0f).margin(2e-3));
    }
  }
}

TEST_CASE(
    "shape uv: a shape's (u, v) frame and box position are made only where the material reads them, the rest the same",
    "[uv]") {
  for (const ShapeKind kind :
       {ShapeKind::kSphere, ShapeKind::kCube, ShapeKind::kPlane, ShapeKind::kCylinder, ShapeKind::kCone}) {
    INFO("shape kind " << static_cast<int>(kind));
    AnalyticShape shape;
    shape.kind = kind;
    shape.transform = *make_transform(glm::translate(Mat4(1.0f), Vec3(0.5f, -1.0f, 2.0f)) *
                                      glm::rotate(Mat4(1.0f), 0.4f, glm::normalize(Vec3(1.0f, 2.0f, 0.5f))) *
                                      glm::scale(Mat4(1.0f), Vec3(2.0f, 1.5f, 1.0f)));
    // From above and in front, at a point inside the shape's box (the cone's and cylinder's z runs 0-1).
    const Vec3 target = shape.transform.point_to_world(Vec3(0.2f, 0.0f, kind == ShapeKind::kCone ? 0.6f : 0.3f));
    Ray ray;
    ray.origin = target + shape.transform.vector_to_world(Vec3(0.3f, 4.0f, 0.5f));
    ray.direction = glm::normalize(target - ray.origin);
    Hit hit;
    REQUIRE(intersect_shape(shape, ray, hit));
    const SurfaceInteraction with = shape_surface(shape, ray, hit, true);
    const SurfaceInteraction without = shape_surface(shape, ray, hit, false);
    // Everything but the texture coordinates and the box position (which only a texture's
    // projection reads) to the bit.
    CHECK(without.position == with.position);
    CHECK(without.position_error == with.position_error);
    CHECK(without.geometric_normal == with.geometric_normal);
    CHECK(without.shading_normal == with.shading_normal);
    CHECK(without.object_position == SurfaceInteraction{}.object_position);
    CHECK(without.object_from_world == SurfaceInteraction{}.object_from_world);
    CHECK(without.shape_axis == SurfaceInteraction{}.shape_axis);
    CHECK(with.object_from_world != SurfaceInteraction{}.object_from_world);
    CHECK(with.object_position != SurfaceInteraction{}.object_position);
    CHECK(without.material == with.material);
    CHECK(without.front_face == with.front_face);
    CHECK(with.texcoord[0].uv != Vec2(0.0f));
    CHECK(with.texcoord[0].dpdu != UvFrame{}.dpdu);
    CHECK(without.texcoord[0].uv == UvFrame{}.uv);
    CHECK(without.texcoord[0].dpdu == UvFrame{}.dpdu);
  }
  // Material::reads_texcoords: a texture in any slot, or anisotropy (its direction is dP/du).
  Material plain;
  CHECK_FALSE(plain.reads_texcoords());
  Material textured;
  textured.pbr.layers.sheen.color_texture.texture = 0;
  CHECK(textured.reads_texcoords());
  Material brushed;
  brushed.pbr.layers.anisotropy.strength = 0.5f;
  CHECK(brushed.reads_texcoords());
}

TEST_CASE("shape uv: the normal made without the (u, v) frame is the frame's normal to the bit", "[uv]") {
  struct Part {
    ShapeKind kind;
    uint32_t part;
  };
  const Part parts[] = {{ShapeKind::kSphere, 0},
                        {ShapeKind::kPlane, 0},
                        {ShapeKind::kCube, 0},
                        {ShapeKind::kCube, 1},
                        {ShapeKind::kCube, 2},
                        {ShapeKind::kCube, 3},
                        {ShapeKind::kCube, 4},
                        {ShapeKind::kCube, 5},
                        {ShapeKind::kCube, 6},
                        {ShapeKind::kCylinder, kCylinderSide},
                        {ShapeKind::kCylinder, kCylinderBase},
                        {ShapeKind::kCylinder, kCylinderTop},
                        {ShapeKind::kCone, kConeSide},
                        {ShapeKind::kCone, kConeBase}};
  uint32_t state = 12345u;
  const auto next = [&] {  // in [-1.25, 1.25): points a little off the surface too, and the seams' signs
    state = state * 1664525u + 1013904223u;
    return 2.5f * static_cast<float>(state >> 8) / 16777216.0f - 1.25f;
  };
  for (const Part& k : parts) {
    INFO("shape kind " << static_cast<int>(k.kind) << ", part " << k.part);
    for (int i = 0; i < 2000; ++i) {
      Vec3 p(next(), next(), next());
      if (i % 2 == 0 && k.part < 6) p = onto_surface(k.kind, k.part, p);  // part 6: no cube face
      if (i % 7 == 0) p.y = i % 3 == 0 ? -0.0f : 0.0f;                    // on the seams of atan2
      const Vec3 made = object_space_normal(k.kind, p, k.part);
      const Vec3 framed = object_space_patch(k.kind, p, k.part).normal;
      // Bits, not values: -0 and +0 too.
      REQUIRE(std::memcmp(&made, &framed, sizeof(Vec3)) == 0);
    }
  }
}
