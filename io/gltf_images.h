// The images of a glTF file's materials, each decoded once into ImportedModel::textures: from a
// data URI, a buffer view or a file beside the model (percent-encoded URIs, "%20" a space). An
// image that cannot be used is a warning and leaves the slot empty: the model still renders.
#pragma once

#include <string>
#include <vector>

#include "io/gltf_loader.h"

namespace tinygltf {
class Model;
}

namespace rt {

// "%20" -> " ": glTF URIs are percent-encoded.
std::string percent_decoded(const std::string& uri);

class ImageDecoder {
 public:
  ImageDecoder(const tinygltf::Model& model, const std::string& base_dir, const LoadLimits& limits, ImportedModel& out);

  // A data texture slot (normal maps are data, not colour) for glTF texture `index`: its image,
  // UV set and sampler wrap mode.
  TextureSlot slot(int index, int texcoord, const std::string& where);

 private:
  uint32_t decode(size_t image_index, const std::string& where);

  const tinygltf::Model& model_;
  const std::string& base_dir_;
  const LoadLimits& limits_;
  ImportedModel& out_;
  std::vector<uint32_t> decoded_;  // per image: its texture, kNoTexture if unusable, kNoTexture - 1 if not tried
};

}  // namespace rt
