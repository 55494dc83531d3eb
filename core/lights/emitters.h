// Surfaces that give off light, as the path tracer's light sampling sees them: every triangle of
// every placed mesh whose material has an emission, in world space, drawn with probability
// proportional to its area x its emission's weight (the mean of its colour factor). The density
// per unit area of a point is then weight / total, the same on every triangle of one material,
// so that a BSDF ray meeting an emissive surface finds its light-sampling density from the
// material alone (multiple importance sampling needs both). Analytic shapes and CSG solids with
// an emission are not in the table: BSDF rays alone find them (docs/rendering.md, "Path tracing").
#pragma once

#include <cstdint>
#include <vector>

#include "core/accel/bvh.h"
#include "core/scene_assets.h"

namespace rt {

// The weight of an emission colour for drawing emitters: its mean over the channels.
inline float emission_weight(Vec3 emission) { return (emission.x + emission.y + emission.z) * (1.0f / 3.0f); }

struct EmitterSample {
  Vec3 point{0.0f};
  Hit hit;               // as if a ray had met the point: for Scene::surface, which gives its emission
  float area_pdf = 0.0f;  // density per unit area
};

class Emitters {
 public:
  Emitters() = default;
  // The emissive triangles of the BVH's mesh instances.
  Emitters(const Bvh& bvh, const SceneAssets& assets);

  bool empty() const { return triangles_.empty(); }
  size_t size() const { return triangles_.size(); }
  // Whether sample() can draw points of top-level primitive `prim` (an emissive mesh instance).
  bool draws(uint32_t prim) const { return prim < drawn_.size() && drawn_[prim] != 0; }
  // The density per unit area of sample() at a point of a drawn primitive whose material emits
  // `emission` (its factor, before any texture).
  float area_pdf(Vec3 emission) const { return total_ > 0.0f ? emission_weight(emission) / total_ : 0.0f; }
  // A point: u_pick chooses the triangle, u the point on it (uniform by area).
  EmitterSample sample(float u_pick, Vec2 u) const;

 private:
  struct Triangle {
    Vec3 p0, e1, e2;  // world space: p0 + b1 e1 + b2 e2
    uint32_t prim = 0, index = 0;
    float weight = 0.0f;  // area x emission weight
  };
  std::vector<Triangle> triangles_;
  std::vector<float> cdf_;  // running sums of the weights
  float total_ = 0.0f;
  std::vector<uint8_t> drawn_;  // by top-level primitive id
};

}  // namespace rt
