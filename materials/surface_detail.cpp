#include "materials/surface_detail.h"

namespace rt {

Vec3 blinn_bump(Vec3 n, Vec3 dpdu, Vec3 dpdv, float hu, float hv) {
  const Vec3 spanned = glm::cross(dpdu, dpdv);
  const float area = glm::length(spanned);
  if (!(area > 0.0f) || !std::isfinite(area)) return n;
  const float side = glm::dot(spanned, n) < 0.0f ? -1.0f : 1.0f;
  const Vec3 tilted = n + side * (hu * glm::cross(n, dpdv) - hv * glm::cross(n, dpdu)) / area;
  const float len = glm::length(tilted);
  return len > 0.0f && std::isfinite(len) ? tilted / len : n;
}

Vec2 height_gradient(const BumpMap& bump, const std::vector<Texture>& textures, Vec2 uv, const UvFootprint& footprint,
                     TextureFilter filter) {
  const Texture& map = textures[bump.height.texture];
  const TextureMapping& m = bump.height.mapping;
  const float eu =
      std::max(bump.epsilon > 0.0f ? bump.epsilon : 1.0f / static_cast<float>(map.width()), 0.5f * footprint.width());
  const float ev =
      std::max(bump.epsilon > 0.0f ? bump.epsilon : 1.0f / static_cast<float>(map.height()), 0.5f * footprint.width());
  // The four points at one mip level (the footprint's), in one lookup.
  const std::array<Vec3, 4> t = map.sample_cross(uv, Vec2(eu, ev), m.wrap, filter, map.filter_level(filter, footprint));
  const auto height = [&](size_t k) { return (t[k].x + t[k].y + t[k].z) / 3.0f; };
  const float bu = (height(0) - height(1)) / (2.0f * eu);
  const float bv = (height(2) - height(3)) / (2.0f * ev);
  return bump.strength * Vec2(bu, bv);
}

Vec3 tangent_space_normal(Vec3 n, Vec3 tangent, float handedness, Vec3 texel, float scale) {
  Vec3 t = tangent - glm::dot(tangent, n) * n;
  const float len = glm::length(t);
  if (!(len > 1e-8f) || !std::isfinite(len)) return n;
  t /= len;
  const Vec3 b = glm::cross(n, t) * (handedness < 0.0f ? -1.0f : 1.0f);
  const Vec3 local = 2.0f * texel - Vec3(1.0f);
  const Vec3 tilted = scale * local.x * t + scale * local.y * b + local.z * n;
  const float tl = glm::length(tilted);
  return tl > 0.0f && std::isfinite(tl) ? tilted / tl : n;
}

}  // namespace rt
