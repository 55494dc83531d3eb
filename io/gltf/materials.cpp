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
float clamped01(float v) { return std::clamp(v, 0.0f, 1.0f); }

// A textureInfo inside a material extension (tinygltf parses only the core ones): its index,
// texCoord and own extensions (KHR_texture_transform). No slot when absent.
TextureSlot extension_texture(const tinygltf::Value& ext, const char* key, const char* extension_name,
                              ImageDecoder& images, TextureEncoding encoding, const std::string& where,
                              const std::string& at) {
  const tinygltf::Value& info = ext.Get(key);
  const auto index = info.IsObject() ? gltf_number(info, "index") : std::nullopt;
  if (!index || *index < 0) return {};
  const auto texcoord = gltf_number(info, "texCoord");
  tinygltf::ExtensionMap extensions;
  const tinygltf::Value& own = info.Get("extensions");
  if (own.IsObject())
    for (const std::string& name : own.Keys()) extensions[name] = own.Get(name);
  return images.slot(texture_ref(static_cast<int>(*index), texcoord ? static_cast<int>(*texcoord) : 0, extensions,
                                 at + "/extensions/" + extension_name + "/" + key),
                     encoding, where + " " + key);
}

Vec3 color_of(const tinygltf::Value& ext, const char* key, Vec3 otherwise) {
  const auto given = gltf_numbers(ext, key, 3);
  return given ? clamped01(Vec3((*given)[0], (*given)[1], (*given)[2])) : otherwise;
}

// The layered extensions (core/material_layers.h), each factor clamped to what the specification allows.
void import_layers(const tinygltf::ExtensionMap& extensions, ImageDecoder& images, const std::string& where,
                   const std::string& at, PbrLayers& out) {
  const auto texture = [&](const tinygltf::Value& ext, const char* key, const char* name, TextureEncoding e) {
    return extension_texture(ext, key, name, images, e, where, at);
  };
  constexpr auto kLinear = TextureEncoding::kLinear;
  if (const auto* e = extension(extensions, "KHR_materials_clearcoat")) {
    const char* name = "KHR_materials_clearcoat";
    ClearcoatLayer& c = out.clearcoat;
    c.factor = clamped01(gltf_number(*e, "clearcoatFactor").value_or(0.0f));
    c.roughness = clamped01(gltf_number(*e, "clearcoatRoughnessFactor").value_or(0.0f));
    if (c.factor > 0.0f) {
      c.texture = texture(*e, "clearcoatTexture", name, kLinear);
      c.roughness_texture = texture(*e, "clearcoatRoughnessTexture", name, kLinear);
      c.normal_map.map = texture(*e, "clearcoatNormalTexture", name, kLinear);
      const tinygltf::Value& info = e->Get("clearcoatNormalTexture");
      if (info.IsObject()) c.normal_map.scale = gltf_number(info, "scale").value_or(1.0f);
    }
  }
  if (const auto* e = extension(extensions, "KHR_materials_sheen")) {
    const char* name = "KHR_materials_sheen";
    SheenLayer& s = out.sheen;
    s.color = color_of(*e, "sheenColorFactor", Vec3(0.0f));
    s.roughness = clamped01(gltf_number(*e, "sheenRoughnessFactor").value_or(0.0f));
    if (s.color != Vec3(0.0f)) {
      s.color_texture = texture(*e, "sheenColorTexture", name, TextureEncoding::kSrgb);
      s.roughness_texture = texture(*e, "sheenRoughnessTexture", name, TextureEncoding::kAlpha);
    }
  }
  if (const auto* e = extension(extensions, "KHR_materials_specular")) {
    const char* name = "KHR_materials_specular";
    SpecularLayer& s = out.specular;
    s.factor = clamped01(gltf_number(*e, "specularFactor").value_or(1.0f));
    // The colour may exceed 1 (F0 is clamped after the ior's reflectance scales it).
    const auto given = gltf_numbers(*e, "specularColorFactor", 3);
    if (given) s.color = glm::clamp(Vec3((*given)[0], (*given)[1], (*given)[2]), Vec3(0.0f), Vec3(1e3f));
    if (!is_finite(s.color)) s.color = Vec3(1.0f);
    s.texture = texture(*e, "specularTexture", name, TextureEncoding::kAlpha);
    s.color_texture = texture(*e, "specularColorTexture", name, TextureEncoding::kSrgb);
  }
  if (const auto* e = extension(extensions, "KHR_materials_anisotropy")) {
    AnisotropyLayer& a = out.anisotropy;
    a.strength = clamped01(gltf_number(*e, "anisotropyStrength").value_or(0.0f));
    const float rotation = gltf_number(*e, "anisotropyRotation").value_or(0.0f);
    a.rotation = std::isfinite(rotation) ? std::remainder(rotation, 2.0f * kPi) : 0.0f;
    if (a.strength > 0.0f) a.texture = texture(*e, "anisotropyTexture", "KHR_materials_anisotropy", kLinear);
  }
  if (const auto* e = extension(extensions, "KHR_materials_iridescence")) {
    const char* name = "KHR_materials_iridescence";
    IridescenceLayer& i = out.iridescence;
    i.factor = clamped01(gltf_number(*e, "iridescenceFactor").value_or(0.0f));
    const float ior = gltf_number(*e, "iridescenceIor").value_or(1.3f);
    i.ior = std::isfinite(ior) && ior >= 1.0f ? std::min(ior, 10.0f) : 1.3f;
    const auto thickness = [&](const char* key, float otherwise) {
      const float t = gltf_number(*e, key).value_or(otherwise);
      return std::isfinite(t) ? std::clamp(t, 0.0f, 1e5f) : otherwise;
    };
    i.thickness_min = thickness("iridescenceThicknessMinimum", 100.0f);
    i.thickness_max = thickness("iridescenceThicknessMaximum", 400.0f);
    if (i.factor > 0.0f) {
      i.texture = texture(*e, "iridescenceTexture", name, kLinear);
      i.thickness_texture = texture(*e, "iridescenceThicknessTexture", name, kLinear);
    }
  }
  if (const auto* e = extension(extensions, "KHR_materials_dispersion")) {
    const float d = gltf_number(*e, "dispersion").value_or(0.0f);
    out.dispersion = std::isfinite(d) ? std::clamp(d, 0.0f, 100.0f) : 0.0f;
  }
}

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
    if (out.transmissive())
      out.transmission_texture = extension_texture(*t, "transmissionTexture", "KHR_materials_transmission", images,
                                                   TextureEncoding::kLinear, where, at);
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

  import_layers(m.extensions, images, where, at, out.pbr.layers);
  if (extension(m.extensions, "KHR_materials_unlit")) out.unlit = true;
  out.single_sided = !m.doubleSided;  // glTF's default: single-sided
  return out;
}

}  // namespace rt
