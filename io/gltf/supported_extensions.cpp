#include "io/gltf/supported_extensions.h"

namespace rt {

const std::vector<std::string>& supported_gltf_extensions() {
  // Where each is read: quantized attributes like any other component type (io/gltf/accessor.cpp),
  // lights in io/gltf/lights.cpp, instancing in io/gltf/loader.cpp, the material and texture-info
  // extensions in io/gltf/materials.cpp.
  static const std::vector<std::string> names{"KHR_mesh_quantization",      "KHR_lights_punctual",
                                              "EXT_mesh_gpu_instancing",    "KHR_materials_emissive_strength",
                                              "KHR_materials_ior",          "KHR_materials_transmission",
                                              "KHR_materials_volume",       "KHR_materials_unlit",
                                              "KHR_materials_clearcoat",    "KHR_materials_sheen",
                                              "KHR_materials_specular",     "KHR_materials_anisotropy",
                                              "KHR_materials_iridescence",  "KHR_materials_dispersion",
                                              "KHR_draco_mesh_compression", "EXT_meshopt_compression",
                                              "KHR_meshopt_compression",    "EXT_texture_webp",
                                              "KHR_texture_transform"};
  return names;
}

}  // namespace rt
