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
//     transmission 1 - a (ior 1); texture and vertex alpha a cutout (cutout.blend): a probability
//     per ray when path traced, cut below 0.5 by Whitted
//   KHR_materials_transmission                           -> transmission, transmission_texture
//   KHR_materials_ior                                    -> ior (default 1.5)
//   KHR_materials_volume attenuation                     -> absorption = -ln(colour) / distance
//   KHR_materials_unlit                                  -> unlit
//   KHR_materials_clearcoat, _sheen, _specular, _anisotropy, _iridescence, _dispersion
//                                                        -> pbr.layers (core/material_layers.h)
//   doubleSided false                                    -> single_sided: back faces let rays through
#pragma once

#include <string>
#include <vector>

#include "core/material.h"

namespace tinygltf {
struct Material;
}

namespace rt {

class ImageDecoder;

// `where` names the material in messages and `at` is its pointer ("/materials/2"): unusable
// textures are warnings there (the image decoder reports them).
Material import_material(const tinygltf::Material& m, ImageDecoder& images, const std::string& where,
                         const std::string& at);

}  // namespace rt
