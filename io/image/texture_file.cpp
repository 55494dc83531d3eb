#include "io/image/texture_file.h"

#include <array>

#include "core/color.h"
#include "io/base/input_file.h"
#include "io/image/image_header.h"
#include "io/image/png_jpeg_decoder.h"

namespace rt {
namespace {

using std::to_string;

// The header's size against the limits: the image alone, then with its mip levels within what
// the scene's earlier textures left.
bool fits(const ImageHeader& h, const std::string& name, const LoadLimits& limits, const LimitUsage& usage,
          TextureError& error) {
  const uint64_t texels = uint64_t{h.width} * h.height;
  if (texels > limits.texture_texels) {
    error.message = "expected an image of at most " + to_string(limits.texture_texels) + " texels in " + name +
                    ", found " + to_string(h.width) + " x " + to_string(h.height) + " (" + to_string(texels) + ")";
    return false;
  }
  const uint64_t needed = Texture::texels_with_mip_levels(h.width, h.height);
  const uint64_t left = usage.texels >= limits.scene_texels ? 0 : limits.scene_texels - usage.texels;
  if (needed > left) {
    error.over_budget = true;
    error.message =
        name + " (" + to_string(h.width) + " x " + to_string(h.height) + ", " + to_string(needed) +
        " texels with its mip levels) does not fit in the scene's texture budget: " + to_string(usage.texels) +
        " of its " + to_string(limits.scene_texels) + " texels are taken by the textures loaded before it";
    return false;
  }
  return true;
}

}  // namespace

std::optional<Texture> load_texture(const std::string& path, TextureEncoding encoding, const LoadLimits& limits,
                                    LimitUsage& usage, TextureError& error) {
  const auto bytes = read_input_bytes(path, kMaxTextureFileBytes, error.message);
  if (!bytes) {
    error.message = "cannot read \"" + path + "\": " + error.message;
    return std::nullopt;
  }
  return decode_texture(*bytes, "\"" + path + "\"", encoding, limits, usage, error);
}

std::optional<ImageHeader> claim_texture(std::span<const unsigned char> bytes, const std::string& name,
                                         const LoadLimits& limits, LimitUsage& usage, TextureError& error) {
  if (bytes.size() > kMaxTextureFileBytes) {
    error.message = "cannot read " + name + " as an image: it is larger than " + format_bytes(kMaxTextureFileBytes);
    return std::nullopt;
  }
  std::string why;
  const auto header = read_image_header(bytes.data(), bytes.size(), why);
  if (!header) {
    error.message = why + " in " + name;
    return std::nullopt;
  }
  if (!fits(*header, name, limits, usage, error)) return std::nullopt;
  usage.texels += Texture::texels_with_mip_levels(header->width, header->height);
  return header;
}

std::optional<Texture> decode_claimed_texture(std::span<const unsigned char> bytes, const ImageHeader& header,
                                              const std::string& name, TextureEncoding encoding, TextureError& error) {
  std::string why;
  // The decoder converts any layout to the channels asked for (alpha 1 where the file has none).
  const bool alpha = encoding == TextureEncoding::kAlpha;
  auto image = decode_png_jpeg(bytes.data(), bytes.size(), header, alpha ? 4 : 3, why);
  if (!image) {
    error.message = "cannot decode " + name + ": " + why;
    return std::nullopt;
  }
  std::vector<Vec3> linear(static_cast<size_t>(header.width) * header.height);
  const auto channel = [&](int c) { return alpha ? 3 : c; };
  if (image->sixteen_bit) {
    for (size_t i = 0; i < linear.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const float v = image->sample(i, channel(c));
        linear[i][c] = encoding == TextureEncoding::kSrgb ? srgb_decode(v) : v;
      }
  } else {
    std::array<float, 256> decode{};  // one entry per 8-bit code
    for (int v = 0; v < 256; ++v) {
      const float f = static_cast<float>(v) / 255.0f;
      decode[static_cast<size_t>(v)] = encoding == TextureEncoding::kSrgb ? srgb_decode(f) : f;
    }
    const uint8_t* samples = image->bytes();
    const size_t step = static_cast<size_t>(image->channels);
    for (size_t i = 0; i < linear.size(); ++i)
      for (int c = 0; c < 3; ++c) linear[i][c] = decode[samples[step * i + static_cast<size_t>(channel(c))]];
  }
  image.reset();  // the decoder's pixels go before the mip levels are made: a lower peak
  return Texture(static_cast<int>(header.width), static_cast<int>(header.height), std::move(linear));
}

std::optional<Texture> decode_texture(std::span<const unsigned char> bytes, const std::string& name,
                                      TextureEncoding encoding, const LoadLimits& limits, LimitUsage& usage,
                                      TextureError& error) {
  const auto header = claim_texture(bytes, name, limits, usage, error);
  if (!header) return std::nullopt;
  return decode_claimed_texture(bytes, *header, name, encoding, error);
}

}  // namespace rt
