#include "io/gltf_images.h"

#include <cctype>

#include <tiny_gltf.h>

#include "io/input_file.h"
#include "io/texture_file.h"

namespace rt {

using std::to_string;

std::string percent_decoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    const auto hex = [&](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) && hex(uri[i + 2])) {
      out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

ImageDecoder::ImageDecoder(const tinygltf::Model& model, const std::string& base_dir, const LoadLimits& limits,
                           ImportedModel& out)
    : model_(model), base_dir_(base_dir), limits_(limits), out_(out), decoded_(model.images.size(), kNoTexture - 1) {}

TextureSlot ImageDecoder::slot(int index, int texcoord, const std::string& where) {
  TextureSlot slot;
  slot.mapping.uv_set = texcoord == 1 ? 1u : 0u;
  if (texcoord < 0 || texcoord > 1)
    out_.warnings.push_back(where + ": TEXCOORD_" + to_string(texcoord) + " is not supported; TEXCOORD_0 used");
  if (index < 0 || static_cast<size_t>(index) >= model_.textures.size()) {
    out_.warnings.push_back(where + ": texture " + to_string(index) + " does not exist; ignored");
    return slot;
  }
  const tinygltf::Texture& texture = model_.textures[static_cast<size_t>(index)];
  if (texture.sampler >= 0 && static_cast<size_t>(texture.sampler) < model_.samplers.size()) {
    const int wrap = model_.samplers[static_cast<size_t>(texture.sampler)].wrapS;
    slot.mapping.wrap = wrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? TextureWrap::kClamp
                        : wrap == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? TextureWrap::kMirror
                                                                        : TextureWrap::kRepeat;
  }
  if (texture.source < 0 || static_cast<size_t>(texture.source) >= model_.images.size()) {
    out_.warnings.push_back(where + ": texture " + to_string(index) + " has no image; ignored");
    return slot;
  }
  slot.texture = decode(static_cast<size_t>(texture.source), where);
  return slot;
}

uint32_t ImageDecoder::decode(size_t image_index, const std::string& where) {
  uint32_t& done = decoded_[image_index];
  if (done != kNoTexture - 1) return done;
  done = kNoTexture;
  const tinygltf::Image& image = model_.images[image_index];
  std::string name = "image " + to_string(image_index), error;
  std::vector<unsigned char> bytes = image.image;
  if (bytes.empty() && !image.uri.empty()) {
    const std::string path = resolve_path(base_dir_, percent_decoded(image.uri));
    name = "\"" + path + "\"";
    auto file = read_input_bytes(path, limits_.gltf_total_bytes, error);
    if (!file) {
      out_.warnings.push_back(where + ": cannot read " + name + " (" + error + "); ignored");
      return done;
    }
    out_.files.push_back(path);
    bytes = std::move(*file);
  }
  auto texture = decode_texture(bytes, name, TextureEncoding::kLinear, limits_.texture_texels, error);
  if (!texture) {
    out_.warnings.push_back(where + ": " + error + "; ignored");
    return done;
  }
  done = static_cast<uint32_t>(out_.textures.size());
  out_.textures.push_back(std::move(*texture));
  return done;
}

}  // namespace rt
