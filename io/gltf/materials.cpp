#include "io/gltf/materials.h"

#include <cmath>

#include <tiny_gltf.h>

#include "io/gltf/images.h"
#include "io/gltf/values.h"

namespace rt {
namespace {

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name) {
  const auto it = extensions.find(name);
  return it != extensions.end() && it->second.IsObject() ? &it->second : nullptr;
}

GltfTextureRef texture_ref(int index, int texcoord, const tinygltf::ExtensionMap& extensions, std::string pointer) {
  return GltfTextureRef{index, texcoord, extension(extensions, "KHR_texture_transform"), std::move(pointer)};
}

Vec3 clamped01(Vec3 v) { return glm::clamp(v, Vec3(0.0f), Vec3(1.0f)); }

}  // namespace

Material import_material(const tinygltf::Material& m, ImageDecoder& images, const std::string& where,
                         const std::string& at) {
  const auto& pbr = m.pbrMetallicRoughness;
  Material out;
  float alpha = 1.0f;
  if (pbr.baseColorFactor.size() == 4) {
    out.kd = clamped01(Vec3(static_cast<float>(pbr.baseColorFactor[0]), static_cast<float>(pbr.baseColorFactor[1]),
                            static_cast<float>(pbr.baseColorFactor[2])));
    alpha = std::clamp(static_cast<float>(pbr.baseColorFactor[3]), 0.0f, 1.0f);
  } else {
    out.kd = Vec3(1.0f);
  }
  out.pbr.enabled = true;
  out.pbr.metallic = static_cast<float>(pbr.metallicFactor);
  out.pbr.roughness = static_cast<float>(pbr.roughnessFactor);
  const auto& base = pbr.baseColorTexture;
  if (base.index >= 0)
    out.texture = images.slot(
        texture_ref(base.index, base.texCoord, base.extensions, at + "/pbrMetallicRoughness/baseColorTexture"),
        TextureEncoding::kSrgb, where + " baseColorTexture");
  const auto& mr = pbr.metallicRoughnessTexture;
  if (mr.index >= 0)
    out.pbr.texture = images.slot(
        texture_ref(mr.index, mr.texCoord, mr.extensions, at + "/pbrMetallicRoughness/metallicRoughnessTexture"),
        TextureEncoding::kLinear, where + " metallicRoughnessTexture");
  const auto& normal = m.normalTexture;
  if (normal.index >= 0) {
    out.normal_map.map =
        images.slot(texture_ref(normal.index, normal.texCoord, normal.extensions, at + "/normalTexture"),
                    TextureEncoding::kLinear, where + " normalTexture");
    out.normal_map.scale = static_cast<float>(normal.scale);
  }

  // Emission: the factor, scaled by KHR_materials_emissive_strength, times the texture.
  if (m.emissiveFactor.size() == 3)
    out.emission = Vec3(static_cast<float>(m.emissiveFactor[0]), static_cast<float>(m.emissiveFactor[1]),
                        static_cast<float>(m.emissiveFactor[2]));
  if (const auto* strength = extension(m.extensions, "KHR_materials_emissive_strength"))
    out.emission *= std::max(0.0f, gltf_number(*strength, "emissiveStrength").value_or(1.0f));
  out.emission = glm::max(out.emission, Vec3(0.0f));
  if (!is_finite(out.emission)) out.emission = Vec3(0.0f);
  const auto& emissive = m.emissiveTexture;
  if (emissive.index >= 0 && out.emission != Vec3(0.0f))
    out.emission_texture =
        images.slot(texture_ref(emissive.index, emissive.texCoord, emissive.extensions, at + "/emissiveTexture"),
                    TextureEncoding::kSrgb, where + " emissiveTexture");

  // Refraction: transmission with its index, and the volume's absorption inside.
  bool ior_given = false;
  if (const auto* ior = extension(m.extensions, "KHR_materials_ior")) {
    const float value = gltf_number(*ior, "ior").value_or(1.5f);
    out.ior = value >= 1.0f ? value : 1.5f;  // the extension allows 0 (a special case we do not model)
    ior_given = true;
  }
  if (const auto* t = extension(m.extensions, "KHR_materials_transmission")) {
    out.transmission = Vec3(std::clamp(gltf_number(*t, "transmissionFactor").value_or(0.0f), 0.0f, 1.0f));
    // transmissionTexture: a textureInfo whose red channel scales the factor (linear data).
    const tinygltf::Value& info = t->Get("transmissionTexture");
    const auto index = info.IsObject() ? gltf_number(info, "index") : std::nullopt;
    if (index && *index >= 0 && out.transmissive()) {
      const auto texcoord = gltf_number(info, "texCoord");
      tinygltf::ExtensionMap extensions;
      const tinygltf::Value& ext = info.Get("extensions");
      if (ext.IsObject())
        for (const std::string& key : ext.Keys()) extensions[key] = ext.Get(key);
      out.transmission_texture =
          images.slot(texture_ref(static_cast<int>(*index), texcoord ? static_cast<int>(*texcoord) : 0, extensions,
                                  at + "/extensions/KHR_materials_transmission/transmissionTexture"),
                      TextureEncoding::kLinear, where + " transmissionTexture");
    }
  }
  if (const auto* v = extension(m.extensions, "KHR_materials_volume")) {
    const float distance = gltf_number(*v, "attenuationDistance").value_or(kInfinity);
    const auto given = gltf_numbers(*v, "attenuationColor", 3);
    const Vec3 color = given ? Vec3((*given)[0], (*given)[1], (*given)[2]) : Vec3(1.0f);
    const Vec3 c = glm::clamp(color, Vec3(1e-6f), Vec3(1.0f));
    if (distance > 0.0f && std::isfinite(distance)) out.absorption = -glm::log(c) / distance;
  }

  // Alpha.
  if (m.alphaMode == "MASK" || m.alphaMode == "BLEND") {
    out.cutout.enabled = true;
    out.cutout.blend = m.alphaMode == "BLEND";
    out.cutout.cutoff = m.alphaMode == "MASK" ? static_cast<float>(m.alphaCutoff) : 0.5f;
    out.cutout.factor = m.alphaMode == "MASK" ? alpha : 1.0f;
    if (base.index >= 0) {
      out.cutout.texture = images.slot(
          texture_ref(base.index, base.texCoord, base.extensions, at + "/pbrMetallicRoughness/baseColorTexture"),
          TextureEncoding::kAlpha, where + " baseColorTexture (alpha)");
      out.cutout.texture.mapping.filter = out.texture.mapping.filter;
    }
    if (m.alphaMode == "BLEND" && alpha < 1.0f) {
      out.transmission_is_coverage = 1.0f - alpha > max_component(out.transmission);
      out.transmission = glm::max(out.transmission, Vec3(1.0f - alpha));
      if (!ior_given && !extension(m.extensions, "KHR_materials_transmission")) out.ior = 1.0f;  // see-through, unbent
    }
  }

  if (extension(m.extensions, "KHR_materials_unlit")) out.unlit = true;
  out.single_sided = !m.doubleSided;  // glTF's default: single-sided
  return out;
}

}  // namespace rt
