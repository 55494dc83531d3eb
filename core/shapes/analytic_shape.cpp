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

SurfaceInteraction shape_surface(const AnalyticShape& shape, const Ray& ray, const Hit& hit) {
  const Ray object_ray = to_object_ray(shape, ray);
  const Vec3 p_object = object_ray.at(hit.t);
  const SurfacePatch patch = object_space_patch(shape.kind, p_object, hit.part);
  SurfaceInteraction si;
  si.position = shape.transform.point_to_world(p_object);
  si.geometric_normal = shape.transform.normal_to_world_unit(patch.normal);
  si.shading_normal = si.geometric_normal;
  si.texcoord[0] =
      UvFrame{patch.uv, shape.transform.vector_to_world(patch.dpdu), shape.transform.vector_to_world(patch.dpdv)};
  si.texcoord[1] = si.texcoord[0];
  si.object_position = p_object;
  si.object_from_world = Mat3(shape.transform.to_object);
  if (shape.kind == ShapeKind::kCylinder || shape.kind == ShapeKind::kCone) {
    // Their z runs over [0, 1]: stretched to [-1, 1] like every other shape's box.
    si.object_position.z = 2.0f * p_object.z - 1.0f;
    si.object_from_world =
        Mat3(Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 0.0f, 2.0f)) * si.object_from_world;
    si.shape_axis = 2;
  }
  si.material = shape.material;
  si.front_face = glm::dot(ray.direction, si.geometric_normal) < 0.0f;
  return si;
}

}  // namespace rt
