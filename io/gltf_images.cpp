#include "io/gltf_images.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <tiny_gltf.h>

#include "io/gltf_values.h"
#include "io/input_file.h"

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
    : model_(model),
      base_dir_(base_dir),
      limits_(limits),
      out_(out),
      decoded_(model.images.size(), {kNoTexture - 1, kNoTexture - 1, kNoTexture - 1}) {}

TextureSlot ImageDecoder::slot(const GltfTextureRef& ref, TextureEncoding encoding, const std::string& where) {
  TextureSlot slot;
  int texcoord = ref.texcoord;
  if (ref.transform) {
    read_transform(*ref.transform, slot.mapping, where);
    if (ref.transform->Has("texCoord") && ref.transform->Get("texCoord").IsInt())
      texcoord = ref.transform->Get("texCoord").GetNumberAsInt();  // overrides the textureInfo's
  }
  slot.mapping.uv_set = texcoord == 1 ? 1u : 0u;
  if (texcoord < 0 || texcoord > 1)
    out_.warnings.push_back(where + ": TEXCOORD_" + to_string(texcoord) + " is not supported; TEXCOORD_0 used");
  if (ref.index < 0 || static_cast<size_t>(ref.index) >= model_.textures.size()) {
    out_.warnings.push_back(where + ": texture " + to_string(ref.index) + " does not exist; ignored");
    return slot;
  }
  const tinygltf::Texture& texture = model_.textures[static_cast<size_t>(ref.index)];
  read_sampler(texture.sampler, slot.mapping);
  if (texture.source < 0 || static_cast<size_t>(texture.source) >= model_.images.size()) {
    out_.warnings.push_back(where + ": texture " + to_string(ref.index) + " has no image; ignored");
    return slot;
  }
  slot.texture = decode(static_cast<size_t>(texture.source), encoding, where);
  return slot;
}

// glTF samplers (README, "glTF materials"): wrapS decides the wrap mode (ours is one for both
// axes). Without mipmaps in minFilter, magFilter picks nearest or bilinear; with them (or no
// sampler), trilinear, unless magFilter is NEAREST (pixel art).
void ImageDecoder::read_sampler(int index, TextureMapping& mapping) {
  if (index < 0 || static_cast<size_t>(index) >= model_.samplers.size()) return;
  const tinygltf::Sampler& sampler = model_.samplers[static_cast<size_t>(index)];
  mapping.wrap = sampler.wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? TextureWrap::kClamp
                 : sampler.wrapS == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? TextureWrap::kMirror
                                                                          : TextureWrap::kRepeat;
  const bool nearest = sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
  const bool mipmapped =
      sampler.minFilter != TINYGLTF_TEXTURE_FILTER_NEAREST && sampler.minFilter != TINYGLTF_TEXTURE_FILTER_LINEAR;
  mapping.filter = nearest ? TextureFilter::kNearest : mipmapped ? TextureFilter::kTrilinear : TextureFilter::kBilinear;
}

void ImageDecoder::read_transform(const tinygltf::Value& t, TextureMapping& mapping, const std::string& where) {
  const auto pair = [&](const char* key, Vec2& out) {
    if (!t.Has(key)) return;
    const auto v = gltf_numbers(t, key, 2);
    if (v) out = Vec2((*v)[0], (*v)[1]);
    else out_.warnings.push_back(where + ": KHR_texture_transform " + key + " is not two numbers; ignored");
  };
  pair("offset", mapping.offset);
  pair("scale", mapping.scale);
  if (const auto radians = gltf_number(t, "rotation")) mapping.rotation_degrees = *radians * (180.0f / kPi);
}

uint32_t ImageDecoder::decode(size_t image_index, TextureEncoding encoding, const std::string& where) {
  uint32_t& done = decoded_[image_index][static_cast<size_t>(encoding)];
  if (done != kNoTexture - 1) return done;
  const tinygltf::Image& image = model_.images[image_index];
  std::string name = "image " + to_string(image_index);
  std::vector<unsigned char> bytes = image.image;
  if (bytes.empty() && image.bufferView >= 0 && static_cast<size_t>(image.bufferView) < model_.bufferViews.size()) {
    // check_buffer_views has put every view inside its buffer; checked again in a form that cannot overflow.
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<size_t>(image.bufferView)];
    if (view.buffer >= 0 && static_cast<size_t>(view.buffer) < model_.buffers.size()) {
      const std::vector<unsigned char>& data = model_.buffers[static_cast<size_t>(view.buffer)].data;
      if (view.byteOffset <= data.size() && view.byteLength <= data.size() - view.byteOffset)
        bytes.assign(data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset),
                     data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset + view.byteLength));
    }
    if (bytes.empty()) {
      out_.warnings.push_back(where + ": image " + to_string(image_index) + "'s buffer view holds no image; ignored");
      done = kNoTexture;
      return done;
    }
  }
  done = decode_bytes(std::move(bytes), image.uri, encoding, name, where);
  return done;
}

TextureSlot ImageDecoder::file_slot(const std::string& uri, const std::string& where) {
  TextureSlot slot;
  const auto found = files_.find(uri);
  if (found != files_.end()) {
    slot.texture = found->second;
    return slot;
  }
  std::string name = "\"" + uri + "\"";
  slot.texture = files_[uri] = decode_bytes({}, uri, TextureEncoding::kLinear, name, where);
  return slot;
}

// The image's own bytes, or (when empty) the file its URI names beside the model.
uint32_t ImageDecoder::decode_bytes(std::vector<unsigned char> bytes, const std::string& uri, TextureEncoding encoding,
                                    std::string& name, const std::string& where) {
  std::string error;
  if (bytes.empty() && !uri.empty()) {
    const std::string path = resolve_path(base_dir_, percent_decoded(uri));
    name = "\"" + path + "\"";
    auto file = read_input_bytes(path, limits_.gltf_total_bytes, error);
    if (!file) {
      out_.warnings.push_back(where + ": cannot read " + name + " (" + error + "); ignored");
      return kNoTexture;
    }
    if (std::find(out_.files.begin(), out_.files.end(), path) == out_.files.end()) out_.files.push_back(path);
    bytes = std::move(*file);
  }
  auto texture = decode_texture(bytes, name, encoding, limits_.texture_texels, error);
  if (!texture) {
    out_.warnings.push_back(where + ": " + error + "; ignored");
    return kNoTexture;
  }
  out_.textures.push_back(std::move(*texture));
  return static_cast<uint32_t>(out_.textures.size() - 1);
}

}  // namespace rt
