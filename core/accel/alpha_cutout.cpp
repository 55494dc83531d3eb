#include "core/accel/alpha_cutout.h"

#include <bit>

#include "core/rng.h"

namespace rt {

bool AlphaCutout::front_facing(uint32_t triangle, Vec3 direction) const {
  if (!single_sided) return true;
  const Vec3& p0 = mesh->positions[mesh->indices[3 * triangle]];
  const Vec3& p1 = mesh->positions[mesh->indices[3 * triangle + 1]];
  const Vec3& p2 = mesh->positions[mesh->indices[3 * triangle + 2]];
  const float facing = glm::dot(glm::cross(p1 - p0, p2 - p0), direction);
  return facing < 0.0f;
}

namespace {

// A number in [0, 1) that only this ray meeting this triangle draws.
float ray_key(const Ray& ray, uint32_t triangle) {
  uint64_t h = mix64(triangle);
  for (int i = 0; i < 3; ++i) {
    h = mix64(h ^ std::bit_cast<uint32_t>(ray.origin[i]));
    h = mix64(h ^ std::bit_cast<uint32_t>(ray.direction[i]));
  }
  return static_cast<float>(h >> 40) * 0x1p-24f;
}

}  // namespace

bool AlphaCutout::covers(uint32_t triangle, float b1, float b2, const Ray& ray) const {
  if (!masked) return true;
  const uint32_t i0 = mesh->indices[3 * triangle], i1 = mesh->indices[3 * triangle + 1],
                 i2 = mesh->indices[3 * triangle + 2];
  const float b0 = 1.0f - b1 - b2;
  float coverage = factor;
  if (!mesh->colors.empty()) coverage *= b0 * mesh->colors[i0].w + b1 * mesh->colors[i1].w + b2 * mesh->colors[i2].w;
  if (texture) {
    const std::vector<Vec2>& uvs = mapping.uv_set == 1 && !mesh->uvs1.empty() ? mesh->uvs1 : mesh->uvs;
    // Without UVs a triangle reads (0, 0), (1, 0), (1, 1), as mesh_surface gives shading.
    const Vec2 uv = uvs.empty() ? Vec2(b1 + b2, b2) : b0 * uvs[i0] + b1 * uvs[i1] + b2 * uvs[i2];
    const Vec2 at = transformed_uv(mapping, uv);
    coverage *= mapping.filter == TextureFilter::kNearest ? texture->nearest(at, mapping.wrap).x
                                                          : texture->bilinear(at, mapping.wrap).x;
  }
  return stochastic ? coverage > ray_key(ray, triangle) : coverage >= cutoff;
}

}  // namespace rt
