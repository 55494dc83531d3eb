// glTF's alpha MASK where rays are traced: a mesh placed with a cut-out material is not there
// where its coverage falls below the cutoff, so closest-hit and any-hit both skip that point and
// camera, reflection and shadow rays all see through it. Traversal asks covers() for each
// triangle crossing of such an instance, and only of such instances.
#pragma once

#include <cstdint>

#include "core/mesh.h"
#include "core/texture/texture.h"
#include "core/texture/texture_slot.h"

namespace rt {

struct AlphaCutout {
  const TriangleMesh* mesh = nullptr;
  const Texture* texture = nullptr;  // coverage in every channel (an alpha channel); null: none
  TextureMapping mapping;            // its UV set, KHR_texture_transform and wrap mode
  float factor = 1.0f;               // baseColorFactor's alpha
  float cutoff = 0.5f;

  // Whether the surface is there at barycentrics (b1, b2) of `triangle`: factor x texture
  // (bilinear on the finest level, or nearest) x the COLOR_0 alpha >= cutoff.
  bool covers(uint32_t triangle, float b1, float b2) const;
};

}  // namespace rt
