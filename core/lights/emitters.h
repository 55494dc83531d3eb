// Surfaces that give off light, as the path tracer's light sampling sees them: every emissive
// surface of the scene in one table, drawn with probability proportional to its area x its
// emission's weight (the mean of its colour factor):
//  - each triangle of a placed mesh whose material emits, in world space;
//  - each analytic shape whose material emits, a point drawn uniformly by area in its object
//    space and placed by its transform (its weight uses its approximate world area: the choice
//    only needs to be proportional, the density of a point is worked out exactly);
//  - each analytic operand of a CSG solid whose material emits, drawn as the shape is, a point
//    kept only where it lies on the solid's boundary (a point inside another operand, or cut
//    away, is no sample: unbiased, the density is that of the operand's whole surface).
// CSG operands that are meshes are not in the table: BSDF rays alone find them.
//
// The density per unit area of a point is its entry's probability / its area: the same on every
// triangle of one material (weight / total), so that a BSDF ray meeting an emissive surface
// finds its light-sampling density from the hit alone (multiple importance sampling needs both).
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
  Hit hit;                // as if a ray had met the point: for Scene::surface, which gives its emission
  float area_pdf = 0.0f;  // density per unit area; 0: no point (one a CSG solid cuts away)
};

class Emitters {
 public:
  Emitters() = default;
  // The emissive triangles, shapes and CSG operands of the BVH's primitives.
  Emitters(const Bvh& bvh, const SceneAssets& assets);

  bool empty() const { return entries_.empty(); }
  // The sum of area x emission weight over every entry: pi times it is their power.
  float total_weight() const { return total_; }
  size_t size() const { return entries_.size(); }
  // A point: u_pick chooses the entry, u the point on it. `bvh` is the one the table was built from.
  EmitterSample sample(const Bvh& bvh, float u_pick, Vec2 u) const;
  // The density per unit area with which sample() draws the point of `hit` (a hit of `bvh`,
  // whose surface there has the unit geometric normal `normal`); 0 when it never draws it.
  float area_pdf(const Bvh& bvh, const Hit& hit, Vec3 normal) const;

 private:
  enum class Kind : uint8_t { kTriangle, kShape, kCsgOperand };
  struct Entry {
    Kind kind = Kind::kTriangle;
    uint32_t prim = 0;
    uint32_t index = 0;   // a triangle's in its mesh; a CSG operand's surface in its solid
    Vec3 p0, e1, e2;      // a triangle in world space: p0 + b1 e1 + b2 e2
    float weight = 0.0f;  // area x emission weight
  };
  // Where a primitive's entries are (a mesh's triangles, a CSG solid's operands: contiguous).
  struct Drawn {
    uint32_t first = 0, count = 0;
    float emission_weight = 0.0f;  // a mesh instance's material's
  };
  void add(const Entry& e);
  float shape_area_pdf(const Entry& e, const AnalyticShape& shape, Vec3 normal) const;
  const AnalyticShape& shape_of(const Bvh& bvh, const Entry& e) const;

  std::vector<Entry> entries_;
  std::vector<float> cdf_;  // running sums of the weights
  float total_ = 0.0f;
  std::vector<Drawn> drawn_;  // by top-level primitive id
};

}  // namespace rt
