#include "core/scene_assets.h"

namespace rt {

void SceneAssets::add_mask(uint32_t mesh, uint32_t material, bool stochastic_blend) {
  const Material& m = materials[material];
  if (mask(mesh, material)) return;
  // Coverage that cannot vary and reaches the cutoff everywhere needs no test: drawn solid.
  const bool varies = m.cutout.texture.present() || !meshes[mesh].mesh.colors.empty();
  const bool masked = m.cutout.enabled && (varies || m.cutout.factor < m.cutout.cutoff);
  const bool single_sided = m.single_sided && !m.transmissive();
  if (!masked && !single_sided) return;
  MaskedPlacement p;
  p.mesh = mesh;
  p.material = material;
  p.cutout.masked = masked;
  p.cutout.single_sided = single_sided;
  p.cutout.mesh = &meshes[mesh].mesh;
  if (m.cutout.texture.present()) {
    p.cutout.texture = &textures[m.cutout.texture.texture];
    p.cutout.mapping = m.cutout.texture.mapping;
  }
  p.cutout.factor = m.cutout.factor;
  p.cutout.cutoff = m.cutout.cutoff;
  p.cutout.stochastic = m.cutout.blend && stochastic_blend;
  masks.push_back(p);
}

const AlphaCutout* SceneAssets::mask(uint32_t mesh, uint32_t material) const {
  for (const MaskedPlacement& p : masks)
    if (p.mesh == mesh && p.material == material) return &p.cutout;
  return nullptr;
}

}  // namespace rt
