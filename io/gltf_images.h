// The images of a glTF file's materials, each decoded once per encoding into
// ImportedModel::textures: from a data URI, a buffer view or a file beside the model
// (percent-encoded URIs, "%20" a space). An image that cannot be used is a warning and leaves
// the slot empty: the model still renders.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "io/gltf_loader.h"
#include "io/texture_file.h"

namespace tinygltf {
class Model;
class Value;
}  // namespace tinygltf

namespace rt {

// "%20" -> " ": glTF URIs are percent-encoded.
std::string percent_decoded(const std::string& uri);

// A glTF textureInfo, as the material refers to a texture.
struct GltfTextureRef {
  int index = -1;
  int texcoord = 0;
  const tinygltf::Value* transform = nullptr;  // its KHR_texture_transform object, if any
};

class ImageDecoder {
 public:
  ImageDecoder(const tinygltf::Model& model, const std::string& base_dir, const LoadLimits& limits, ImportedModel& out);

  // The slot for a material's texture: its image decoded as `encoding` (colour is sRGB, normal
  // and metallic-roughness maps are data, alpha masks read the alpha channel), its UV set, its
  // sampler's wrap and filter modes and its KHR_texture_transform.
  TextureSlot slot(const GltfTextureRef& ref, TextureEncoding encoding, const std::string& where);
  // A data slot for an image file beside the glTF file (rtcli's extras), decoded once.
  TextureSlot file_slot(const std::string& uri, const std::string& where);

 private:
  uint32_t decode(size_t image_index, TextureEncoding encoding, const std::string& where);
  uint32_t decode_bytes(std::vector<unsigned char> bytes, const std::string& uri, TextureEncoding encoding,
                        std::string& name, const std::string& where);
  void read_sampler(int sampler, TextureMapping& mapping);
  void read_transform(const tinygltf::Value& transform, TextureMapping& mapping, const std::string& where);

  const tinygltf::Model& model_;
  const std::string& base_dir_;
  const LoadLimits& limits_;
  ImportedModel& out_;
  // Per image and encoding: its texture, kNoTexture if unusable, kNoTexture - 1 if not tried.
  std::vector<std::array<uint32_t, 3>> decoded_;
  std::map<std::string, uint32_t> files_;  // file_slot's, by URI
};

}  // namespace rt
