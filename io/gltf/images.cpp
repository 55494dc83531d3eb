#include "io/gltf/images.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <set>

#include <tiny_gltf.h>

#include "core/parallel_for.h"
#include "core/thread_count.h"
#include "io/base/input_file.h"
#include "io/gltf/file.h"
#include "io/gltf/values.h"
#include "io/image/image_header.h"

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

namespace {

// The image a texture shows: EXT_texture_webp's source where the texture names one (rtcli decodes
// WebP), else the core `source` (the fallback a file without the extension's support reads).
int texture_source(const tinygltf::Texture& texture) {
  const auto it = texture.extensions.find("EXT_texture_webp");
  if (it != texture.extensions.end() && it->second.IsObject()) {
    const tinygltf::Value& source = it->second.Get("source");
    if (source.IsInt()) return source.Get<int>();
  }
  return texture.source;
}

}  // namespace

ImageDecoder::ImageDecoder(const tinygltf::Model& model, const std::string& base_dir, const LoadLimits& limits,
                           LimitUsage& usage, ImportedModel& out, Reporter& report)
    : model_(model), base_dir_(base_dir), limits_(limits), usage_(usage), out_(out), report_(report) {}

TextureSlot ImageDecoder::slot(const GltfTextureRef& ref, TextureEncoding encoding, const std::string& where) {
  TextureSlot slot;
  int texcoord = ref.texcoord;
  if (ref.transform) {
    read_transform(*ref.transform, slot.mapping, where, ref.pointer + "/extensions/KHR_texture_transform");
    if (ref.transform->Has("texCoord") && ref.transform->Get("texCoord").IsInt())
      texcoord = ref.transform->Get("texCoord").GetNumberAsInt();  // overrides the textureInfo's
  }
  slot.mapping.uv_set = texcoord == 1 ? 1u : 0u;
  if (texcoord < 0 || texcoord > 1)
    report_.warning(ref.pointer + "/texCoord",
                    where + ": TEXCOORD_" + to_string(texcoord) + " is not supported; TEXCOORD_0 used");
  if (ref.index < 0 || static_cast<size_t>(ref.index) >= model_.textures.size()) {
    report_.warning(ref.pointer + "/index", where + ": texture " + to_string(ref.index) + " does not exist; ignored");
    return slot;
  }
  const tinygltf::Texture& texture = model_.textures[static_cast<size_t>(ref.index)];
  read_sampler(texture.sampler, slot.mapping);
  const int source = texture_source(texture);
  if (source < 0 || static_cast<size_t>(source) >= model_.images.size()) {
    report_.warning("/textures/" + to_string(ref.index) + "/source",
                    where + ": texture " + to_string(ref.index) + " has no image; ignored");
    return slot;
  }
  slot.texture = decode(source_of(static_cast<size_t>(source)), encoding, where);
  return slot;
}

// glTF samplers (docs/scene-format.md, "glTF materials"): wrapS is u's wrap mode, wrapT v's.
// Without mipmaps in minFilter, magFilter picks nearest or bilinear; with them (or no sampler),
// trilinear, unless magFilter is NEAREST (pixel art).
void ImageDecoder::read_sampler(int index, TextureMapping& mapping) {
  if (index < 0 || static_cast<size_t>(index) >= model_.samplers.size()) return;
  const tinygltf::Sampler& sampler = model_.samplers[static_cast<size_t>(index)];
  const auto wrap = [](int mode) {
    return mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? TextureWrap::kClamp
           : mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? TextureWrap::kMirror
                                                           : TextureWrap::kRepeat;
  };
  mapping.wrap = WrapModes(wrap(sampler.wrapS), wrap(sampler.wrapT));
  const bool nearest = sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
  const bool mipmapped =
      sampler.minFilter != TINYGLTF_TEXTURE_FILTER_NEAREST && sampler.minFilter != TINYGLTF_TEXTURE_FILTER_LINEAR;
  mapping.filter = nearest ? TextureFilter::kNearest : mipmapped ? TextureFilter::kTrilinear : TextureFilter::kBilinear;
}

void ImageDecoder::read_transform(const tinygltf::Value& t, TextureMapping& mapping, const std::string& where,
                                  const std::string& at) {
  const auto pair = [&](const char* key, Vec2& out) {
    if (!t.Has(key)) return;
    const auto v = gltf_numbers(t, key, 2);
    if (v) out = Vec2((*v)[0], (*v)[1]);
    else report_.warning(at + "/" + key, where + ": KHR_texture_transform " + key + " is not two numbers; ignored");
  };
  pair("offset", mapping.offset);
  pair("scale", mapping.scale);
  if (const auto radians = gltf_number(t, "rotation")) mapping.rotation_degrees = *radians * (180.0f / kPi);
}

std::span<const unsigned char> ImageDecoder::view_bytes(int index) const {
  // check_buffer_views has put every view inside its buffer; checked again in a form that cannot overflow.
  if (index < 0 || static_cast<size_t>(index) >= model_.bufferViews.size()) return {};
  const tinygltf::BufferView& view = model_.bufferViews[static_cast<size_t>(index)];
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model_.buffers.size()) return {};
  const std::vector<unsigned char>& data = model_.buffers[static_cast<size_t>(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) return {};
  return std::span<const unsigned char>(data).subspan(view.byteOffset, view.byteLength);
}

ImageDecoder::Source ImageDecoder::source_of(size_t image_index) const {
  const tinygltf::Image& image = model_.images[image_index];
  const std::string name = "image " + to_string(image_index);
  const std::string at = "/images/" + to_string(image_index);
  if (image.bufferView >= 0)
    return {"view " + to_string(image.bufferView),
            name + " (buffer view " + to_string(image.bufferView) + ")",
            view_bytes(image.bufferView),
            "",
            "",
            at};
  if (!image.image.empty()) return {name, name, image.image, "", "", at};
  if (!image.uri.empty()) return file_source(image.uri, at + "/uri");
  return {"", name, {}, "", "", at};
}

ImageDecoder::Source ImageDecoder::file_source(const std::string& uri, const std::string& pointer) const {
  const std::string path = resolve_path(base_dir_, percent_decoded(uri));
  return {"file " + path, "\"" + path + "\"", {}, path, uri, pointer};
}

bool ImageDecoder::fit_in_budget() {
  std::set<std::string> seen;
  uint64_t needed = 0;
  size_t counted = 0;
  for (const tinygltf::Texture& texture : model_.textures) {
    const int index = texture_source(texture);
    if (index < 0 || static_cast<size_t>(index) >= model_.images.size()) continue;
    const Source source = source_of(static_cast<size_t>(index));
    if (source.key.empty() || !seen.insert(source.key).second) continue;
    std::optional<std::vector<unsigned char>> file;
    std::span<const unsigned char> bytes = source.bytes;
    if (!source.path.empty()) {
      // A file outside the folder or unreadable is reported when its texture is decoded.
      std::string ignored;
      if (limits_.outside_files || is_inside_folder(source.path, base_dir_))
        file = read_input_bytes(source.path, kMaxTextureFileBytes, ignored);
      if (file) bytes = *file;
    }
    std::string ignored;  // so is a broken image
    const auto header = read_image_header(bytes.data(), bytes.size(), ignored);
    if (!header || uint64_t{header->width} * header->height > limits_.texture_texels) continue;
    needed += Texture::texels_with_mip_levels(header->width, header->height);
    ++counted;
  }
  const uint64_t left = usage_.texels >= limits_.scene_texels ? 0 : limits_.scene_texels - usage_.texels;
  if (needed <= left) return true;
  report_.over_limit("/images", "its textures' " + to_string(counted) + " images need " + to_string(needed) +
                                    " texels with their mip levels (read from their headers), more than the " +
                                    to_string(left) + " left of the scene's texture budget of " +
                                    to_string(limits_.scene_texels) + " texels");
  failed_ = true;
  return false;
}

uint32_t ImageDecoder::decode(const Source& source, TextureEncoding encoding, const std::string& where) {
  if (failed_) return kNoTexture;
  if (source.key.empty()) {
    report_.warning(source.pointer, where + ": " + source.name + " has no data; ignored");
    return kNoTexture;
  }
  const auto key = std::make_pair(source.key, encoding);
  if (const auto it = decoded_.find(key); it != decoded_.end()) return it->second;
  uint32_t texture = kNoTexture;
  if (source.path.empty() && source.bytes.empty()) {
    report_.warning(source.pointer, where + ": " + source.name + " holds no image; ignored");
  } else if (source.path.empty()) {
    texture = claim({}, source.bytes, source, encoding, where);
  } else if (auto file = read_file(source, where)) {
    texture = claim(std::move(*file), {}, source, encoding, where);
  }
  if (!failed_) decoded_.emplace(key, texture);
  return texture;
}

TextureSlot ImageDecoder::file_slot(const std::string& uri, const std::string& where, const std::string& at) {
  TextureSlot slot;
  slot.texture = decode(file_source(uri, at), TextureEncoding::kLinear, where);
  return slot;
}

// In the model's folder or below (links resolved) unless the caller allows more: a downloaded
// model must not show the user's other files in its render.
std::optional<std::vector<unsigned char>> ImageDecoder::read_file(const Source& source, const std::string& where) {
  if (!limits_.outside_files && !is_inside_folder(source.path, base_dir_)) {
    report_.error(source.pointer, where + ": " + outside_folder_message(source.uri, base_dir_));
    failed_ = true;
    return std::nullopt;
  }
  std::string error;
  auto file = read_input_bytes(source.path, kMaxTextureFileBytes, error);
  if (!file) {
    report_.warning(source.pointer, where + ": cannot read " + source.name + " (" + error + "); ignored");
    return std::nullopt;
  }
  if (std::find(out_.files.begin(), out_.files.end(), source.path) == out_.files.end())
    out_.files.push_back(source.path);
  return file;
}

uint32_t ImageDecoder::claim(std::vector<unsigned char> file, std::span<const unsigned char> bytes,
                             const Source& source, TextureEncoding encoding, const std::string& where) {
  Claimed c{std::move(file), bytes, ImageHeader{}, source, encoding, where};
  if (!c.file.empty()) c.bytes = c.file;
  TextureError error;
  const auto header = claim_texture(c.bytes, source.name, limits_, usage_, error);
  if (!header) {
    if (error.over_budget) {
      report_.over_limit(source.pointer, where + ": " + error.message);
      failed_ = true;
    } else {
      report_.warning(source.pointer, where + ": " + error.message + "; ignored");
    }
    return kNoTexture;
  }
  c.header = *header;
  claimed_.push_back(std::move(c));
  return static_cast<uint32_t>(claimed_.size() - 1);
}

void ImageDecoder::finish(std::vector<Material>& materials, unsigned threads) {
  std::vector<std::optional<Texture>> textures(claimed_.size());
  std::vector<TextureError> errors(claimed_.size());
  parallel_for(claimed_.size(), resolve_thread_count(threads), 1, [&](unsigned, size_t i) {
    const Claimed& c = claimed_[i];
    textures[i] = decode_claimed_texture(c.bytes, c.header, c.source.name, c.encoding, errors[i]);
  });
  // In the order they were claimed, as decoding them one by one would have numbered them.
  std::vector<uint32_t> place(claimed_.size(), kNoTexture);
  for (size_t i = 0; i < claimed_.size(); ++i) {
    const Claimed& c = claimed_[i];
    if (!textures[i]) {
      report_.warning(c.source.pointer, c.where + ": " + errors[i].message + "; ignored");
      usage_.texels -= Texture::texels_with_mip_levels(c.header.width, c.header.height);
      continue;
    }
    place[i] = static_cast<uint32_t>(out_.textures.size());
    out_.textures.push_back(std::move(*textures[i]));
  }
  for (Material& m : materials)
    for (TextureSlot* slot : m.texture_slots())
      if (slot->present()) slot->texture = slot->texture < place.size() ? place[slot->texture] : kNoTexture;
  claimed_.clear();
  decoded_.clear();
}

}  // namespace rt
