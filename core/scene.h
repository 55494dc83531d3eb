// The immutable, render-ready scene. io/ builds it; the renderer and every thread only read it.
#pragma once

#include <vector>

#include "core/accel/bvh.h"
#include "core/camera.h"
#include "core/lights/light.h"
#include "core/material.h"
#include "core/mesh.h"
#include "core/texture/texture.h"

namespace rt {

struct Scene {
  Camera camera;
  Vec3 background{0.0f};  // radiance of rays that hit nothing
  Vec3 ambient{0.0f};     // ambient light, multiplied by each material's kd
  std::vector<Material> materials;
  std::vector<Texture> textures;  // what materials' texture slots index, each file loaded once
  std::vector<Light> lights;
  std::vector<TriangleMesh> meshes;           // world space, for surface details of triangle hits
  std::vector<uint32_t> mesh_first_triangle;  // primitive id of each mesh's first triangle
  Bvh bvh;                                    // all triangles of all meshes, then all analytic shapes

  bool intersect(Ray& ray, Hit& hit) const { return bvh.intersect(ray, hit); }
  bool occluded(const Ray& ray) const { return bvh.occluded(ray); }
  // The material index of primitive `prim`.
  uint32_t material_of(uint32_t prim) const;

  // The full surface record of a hit returned by intersect().
  SurfaceInteraction surface(const Ray& ray, const Hit& hit) const;
};

}  // namespace rt
