// glTF materials onto ours (docs/scene-format.md, "glTF materials"): the metallic-roughness model is kept and
// converted per shading point (materials/pbr_to_phong.h); the rest maps as follows.
//   baseColorFactor, baseColorTexture (sRGB), COLOR_0  -> kd (their product; pbr.enabled)
//   metallicRoughnessTexture (G roughness, B metallic)   -> pbr.texture
//   normalTexture                                        -> normal_map
//   emissiveFactor x KHR_materials_emissive_strength,
//     emissiveTexture (sRGB)                             -> emission, emission_texture
//   occlusionTexture                                     -> ignored: traced shadows do its work
//   alphaMode MASK, alphaCutoff                          -> cutout (every ray passes where cut)
//   alphaMode BLEND                                      -> the factor's alpha a becomes unbent
//     transmission 1 - a (ior 1); texture and vertex alpha cut out below 0.5
//   KHR_materials_transmission                           -> transmission (texture ignored)
//   KHR_materials_ior                                    -> ior (default 1.5)
//   KHR_materials_volume attenuation                     -> absorption = -ln(colour) / distance
//   KHR_materials_unlit                                  -> unlit
//   doubleSided false                                    -> single_sided: back faces let rays through
#pragma once

#include <string>
#include <vector>

#include "core/material.h"
#include "io/base/reporter.h"

namespace tinygltf {
struct Material;
}

namespace rt {

class ImageDecoder;

// `where` names the material in messages and `at` is its pointer ("/materials/2"): what it uses
// but rtcli does not (a transmission texture) and unusable textures are warnings there.
Material import_material(const tinygltf::Material& m, ImageDecoder& images, const std::string& where,
                         const std::string& at, Reporter& report);

}  // namespace rt
