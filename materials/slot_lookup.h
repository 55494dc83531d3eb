// A material's texture slot read at a hit: its mapping, the mip level from the ray cone's
// footprint, and its filter (or the one the detail switches impose). Shared by the shading stage's
// files (evaluated_surface.cpp, evaluated_layers.cpp).
#pragma once

#include <vector>

#include "core/render_settings.h"
#include "core/texture/texture.h"
#include "materials/map_point.h"

namespace rt {

inline Vec3 slot_sample(const TextureSlot& slot, const std::vector<Texture>& textures, Vec2 uv,
                        const UvFootprint& footprint, SurfaceDetailSwitches detail) {
  const TextureFilter filter = detail.override_filter ? detail.filter : slot.mapping.filter;
  return textures[slot.texture].sample(uv, slot.mapping.wrap, filter, footprint);
}

inline Vec3 slot_at(const TextureSlot& slot, const SurfaceInteraction& si, const std::vector<Texture>& textures,
                    Vec3 direction, float cone_width, SurfaceDetailSwitches detail) {
  const MappedPoint p = map_point(slot.mapping, si);
  return slot_sample(slot, textures, p.uv, uv_footprint(p, si.geometric_normal, direction, cone_width), detail);
}

}  // namespace rt
