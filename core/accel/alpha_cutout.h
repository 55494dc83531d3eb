// Where a mesh placed with a material is not there, tested while rays are traced, only for the
// instances that need it:
//  - glTF's alpha MASK: where coverage falls below the cutoff, closest-hit and any-hit both skip
//    the point, so camera, reflection and shadow rays all see through it (covers());
//  - glTF's alpha BLEND, path traced: each ray keeps the point with probability = coverage, by a
//    hash of the ray and the triangle (stochastic transparency: the mean is the blend, and the
//    image still depends only on the rays, never on which thread traced them);
//  - glTF's doubleSided false: the back of each triangle is skipped by closest-hit queries (camera,
//    reflection, refraction, glossy rays), not by shadow rays, so a single-sided closed mesh
//    still casts its whole shadow (front_facing()).
#pragma once

#include <cstdint>

#include "core/mesh.h"
#include "core/ray.h"
#include "core/texture/texture.h"
#include "core/texture/texture_slot.h"

namespace rt {

struct AlphaCutout {
  const TriangleMesh* mesh = nullptr;
  const Texture* texture = nullptr;  // coverage in every channel (an alpha channel); null: none
  TextureMapping mapping;            // its UV set, KHR_texture_transform and wrap mode
  float factor = 1.0f;               // baseColorFactor's alpha
  float cutoff = 0.5f;
  bool masked = false;        // the alpha test applies
  bool stochastic = false;    // coverage is a probability per ray (BLEND, path traced), not cut
  bool single_sided = false;  // closest-hit queries skip back faces

  // Whether `ray` (in object space) finds the surface at barycentrics (b1, b2) of `triangle`:
  // coverage = factor x texture (bilinear on the finest level, or nearest) x the COLOR_0 alpha;
  // there if coverage >= cutoff, or, when stochastic, if coverage > a number in [0, 1) hashed
  // from the ray and the triangle.
  bool covers(uint32_t triangle, float b1, float b2, const Ray& ray) const;
  // Whether a ray along object-space `direction` meets the front of `triangle`, the side its
  // vertices run counter-clockwise seen from. In object space, so a mirroring transform (which
  // glTF says turns the world's winding) changes nothing. True unless single_sided.
  bool front_facing(uint32_t triangle, Vec3 direction) const;
};

}  // namespace rt
