// The transmissive objects a ray is inside, innermost last: how refraction handles nested and
// touching glass (docs/rendering.md, "Refraction"). A camera ray starts in air (empty stack). Entering a
// transmissive surface pushes its material; the index on the far side of the surface is the
// material's and on the near side the innermost medium's (1 for air). Leaving removes the
// innermost entry of that material; the index outside is then the new innermost medium's. So a
// glass of water works when modelled as nested closed surfaces (water inside glass), and an air
// bubble is a surface with ior 1. Fixed capacity, copied by value down the ray tree: no allocation.
#pragma once

#include <cstdint>
#include <vector>

#include "core/material.h"
#include "materials/dispersion.h"

namespace rt {

class MediumStack {
 public:
  static constexpr int kCapacity = 8;  // deeper nesting forgets the outermost medium

  bool empty() const { return size_ == 0; }
  uint32_t innermost() const { return materials_[size_ - 1]; }  // requires !empty()

  MediumStack entered(uint32_t material) const {
    MediumStack s = *this;
    if (s.size_ == kCapacity) {
      for (int i = 1; i < kCapacity; ++i) s.materials_[i - 1] = s.materials_[i];
      --s.size_;
    }
    s.materials_[s.size_++] = material;
    return s;
  }

  // Leaving a material the ray was not known to be inside (an open mesh, a camera inside glass)
  // changes nothing.
  MediumStack left(uint32_t material) const {
    MediumStack s = *this;
    for (int i = s.size_ - 1; i >= 0; --i) {
      if (s.materials_[i] != material) continue;
      for (int j = i + 1; j < s.size_; ++j) s.materials_[j - 1] = s.materials_[j];
      --s.size_;
      break;
    }
    return s;
  }

 private:
  uint32_t materials_[kCapacity];  // [0, size_) in use; the rest is never read
  int size_ = 0;
};

// A transmissive surface crossed: the media beyond it and the indices on both sides. Entering:
// from the innermost medium into `medium`. Leaving: out of it, into what remains once it is
// removed. Whitted's refraction and the path tracer's dielectric both take it from here.
struct MediumCrossing {
  MediumStack beyond;
  float n_before = 1.0f, n_after = 1.0f;
};

// A material's index; at `wavelength_nm` (> 0: a path that carries one) its dispersed index
// (KHR_materials_dispersion).
inline float material_index(const Material& m, float wavelength_nm) {
  return wavelength_nm > 0.0f ? dispersed_ior(m.ior, m.pbr.layers.dispersion, wavelength_nm) : m.ior;
}

inline float medium_index(const MediumStack& media, const std::vector<Material>& materials,
                          float wavelength_nm = 0.0f) {
  return media.empty() ? 1.0f : material_index(materials[media.innermost()], wavelength_nm);
}

inline MediumCrossing cross_medium(const MediumStack& media, uint32_t medium, bool entering,
                                   const std::vector<Material>& materials, float wavelength_nm = 0.0f) {
  MediumCrossing c;
  c.beyond = entering ? media.entered(medium) : media.left(medium);
  c.n_before =
      entering ? medium_index(media, materials, wavelength_nm) : material_index(materials[medium], wavelength_nm);
  c.n_after = medium_index(c.beyond, materials, wavelength_nm);
  return c;
}

}  // namespace rt
