#include "core/shapes/analytic_shape.h"

#include "core/shapes/cone.h"
#include "core/shapes/cube.h"
#include "core/shapes/cylinder.h"
#include "core/shapes/plane.h"
#include "core/shapes/sphere.h"

namespace rt {

Aabb object_bounds(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::kSphere:
    case ShapeKind::kCube: return {Vec3(-1.0f), Vec3(1.0f)};
    case ShapeKind::kPlane: return {Vec3(-1.0f, 0.0f, -1.0f), Vec3(1.0f, 0.0f, 1.0f)};
    case ShapeKind::kCylinder:
    case ShapeKind::kCone: return {Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, 1.0f, 1.0f)};
  }
  return {};
}

Aabb world_bounds(const AnalyticShape& shape) {
  return transform_bounds(shape.transform.to_world, object_bounds(shape.kind));
}

bool intersect_object_space(ShapeKind kind, const Ray& r, Hit& hit) {
  switch (kind) {
    case ShapeKind::kSphere: return intersect_sphere(r, hit);
    case ShapeKind::kCube: return intersect_cube(r, hit);
    case ShapeKind::kPlane: return intersect_plane(r, hit);
    case ShapeKind::kCylinder: return intersect_cylinder(r, hit);
    case ShapeKind::kCone: return intersect_cone(r, hit);
  }
  return false;
}

SurfacePatch object_space_patch(ShapeKind kind, Vec3 p, uint32_t part) {
  switch (kind) {
    case ShapeKind::kSphere: return sphere_patch(p, part);
    case ShapeKind::kCube: return cube_patch(p, part);
    case ShapeKind::kPlane: return plane_patch(p, part);
    case ShapeKind::kCylinder: return cylinder_patch(p, part);
    case ShapeKind::kCone: return cone_patch(p, part);
  }
  return {};
}

namespace {

// Inlined into shape_surface: the call to object_space_patch, its 11-float record, and the point
// passed in a register loaded whole from onto_surface's narrow stores, cost reflection.json 1.4%.
[[gnu::always_inline]] inline Vec3 normal_at(ShapeKind kind, Vec3 p, uint32_t part) {
  switch (kind) {
    case ShapeKind::kSphere: return glm::normalize(p);  // as sphere_patch makes it
    case ShapeKind::kCube: return cube_normal(cube_face(part));
    case ShapeKind::kPlane: return Vec3(0.0f, 1.0f, 0.0f);
    case ShapeKind::kCylinder: return cylinder_normal(p, part);
    case ShapeKind::kCone: return cone_normal(p, part);
  }
  return SurfacePatch{}.normal;
}

// The direction of the object's normal at the hit, of any length: the world's normal is
// normalised after the transform. A sphere's is the point as the ray found it: putting the point
// back on the surface (onto_surface) moves it along that very direction, so the normal need not
// wait for the square root and division that costs, nor for a second pair to make it unit
// (refraction.json 0.97x the time). Its bits differ from those of the point put back by a
// rounding or two. (A cylinder side's radial part, the same way: no faster, measured.)
[[gnu::always_inline]] inline Vec3 normal_direction(ShapeKind kind, Vec3 found, Vec3 p, uint32_t part) {
  if (kind == ShapeKind::kSphere) return found;
  return normal_at(kind, p, part);
}

// The hit point put back on the surface, and its error bound, zero on a flat face. Not inlined:
// inlined into shape_surface, it cost refraction.json 1.7% more instructions (callgrind).
[[gnu::noinline]] Vec3 onto_surface(ShapeKind kind, Vec3& p, uint32_t part) {
  const auto faces_at = [&](int axis, float value) {  // a flat face: exactly on it, no error
    p[axis] = value;
    return Vec3(0.0f);
  };
  switch (kind) {
    case ShapeKind::kSphere: {
      const float length = glm::length(p);
      if (length > 0.0f) p /= length;
      return float_gamma(5) * abs3(p);
    }
    case ShapeKind::kCube: return faces_at(static_cast<int>(part < 6 ? part / 2 : 0), part % 2 == 0 ? 1.0f : -1.0f);
    case ShapeKind::kPlane: return faces_at(1, 0.0f);
    case ShapeKind::kCylinder:
    case ShapeKind::kCone: {
      const bool side = part == (kind == ShapeKind::kCylinder ? uint32_t{kCylinderSide} : uint32_t{kConeSide});
      if (!side) return faces_at(2, kind == ShapeKind::kCone || part == kCylinderTop ? 1.0f : 0.0f);
      // Radius 1 on the cylinder, z on the cone (whose apex is at the origin).
      const float radius = kind == ShapeKind::kCylinder ? 1.0f : std::max(p.z, 0.0f);
      const float r = std::sqrt(p.x * p.x + p.y * p.y);
      if (r > 0.0f) {
        p.x *= radius / r;
        p.y *= radius / r;
      }
      return float_gamma(6) * Vec3(std::fabs(p.x), std::fabs(p.y), kind == ShapeKind::kCone ? std::fabs(p.z) : 0.0f);
    }
  }
  return float_gamma(7) * abs3(p);
}

}  // namespace

Vec3 object_space_normal(ShapeKind kind, Vec3 p, uint32_t part) { return normal_at(kind, p, part); }

SurfaceInteraction shape_surface(const AnalyticShape& shape, const Ray& ray, const Hit& hit, bool texcoords) {
  const Ray object_ray = to_object_ray(shape, ray);
  Vec3 p_object = object_ray.at(hit.t);
  const Vec3 p_found = p_object;
  // The hit point as the ray found it is only as good as t; put back on the surface it is within
  // a few ulps of it (pbrt-v4's reprojection), which keeps rays leaving it close (core/ray.h).
  const Vec3 object_error = onto_surface(shape.kind, p_object, hit.part);
  SurfaceInteraction si;
  const Vec3 normal = normal_direction(shape.kind, p_found, p_object, hit.part);
  if (texcoords) {
    const SurfacePatch patch = object_space_patch(shape.kind, p_object, hit.part);
    si.texcoord[0] =
        UvFrame{patch.uv, shape.transform.vector_to_world(patch.dpdu), shape.transform.vector_to_world(patch.dpdv)};
    si.texcoord[1] = si.texcoord[0];
  }
  // A point on a flat face is exact: its bound carries no input error (the same floats, fewer of them).
  si.position_error = object_error == Vec3(0.0f)
                          ? transformed_point_error(shape.transform.to_world, p_object)
                          : transformed_point_error(shape.transform.to_world, p_object, object_error);
  si.position = shape.transform.point_to_world(p_object);
  si.geometric_normal = shape.transform.normal_to_world_unit(normal);
  si.shading_normal = si.geometric_normal;
  si.material = shape.material;
  si.front_face = glm::dot(ray.direction, si.geometric_normal) < 0.0f;
  // Only a texture's projection reads where the hit is in the shape's box (materials/map_point.cpp),
  // and a material with a texture asks for texcoords.
  if (!texcoords) return si;
  si.object_position = p_object;
  si.object_from_world = Mat3(shape.transform.to_object);
  if (shape.kind == ShapeKind::kCylinder || shape.kind == ShapeKind::kCone) {
    // Their z runs over [0, 1]: stretched to [-1, 1] like every other shape's box.
    si.object_position.z = 2.0f * p_object.z - 1.0f;
    si.object_from_world =
        Mat3(Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 0.0f, 2.0f)) * si.object_from_world;
    si.shape_axis = 2;
  }
  return si;
}

}  // namespace rt
