#include "io/texture_file.h"

#include <stb_image.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <memory>

#include "core/color.h"
#include "io/input_file.h"

namespace rt {
namespace {

constexpr uint64_t kMaxFileBytes = uint64_t{256} << 20;

std::string stb_reason() { return stbi_failure_reason() ? stbi_failure_reason() : "unknown error"; }

struct StbFree {
  void operator()(void* p) const { stbi_image_free(p); }
};

// Width and height from a PNG file's IHDR chunk (it must come first), or false if there is none.
bool png_header_size(const std::vector<unsigned char>& b, int& w, int& h) {
  static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (b.size() < 24 || !std::equal(kSignature, kSignature + 8, b.begin()) || std::memcmp(&b[12], "IHDR", 4) != 0)
    return false;
  const auto be32 = [&](size_t i) {
    return (uint32_t{b[i]} << 24) | (uint32_t{b[i + 1]} << 16) | (uint32_t{b[i + 2]} << 8) | uint32_t{b[i + 3]};
  };
  const uint32_t width = be32(16), height = be32(20);
  if (width > 0x7fffffffu || height > 0x7fffffffu) return false;
  w = static_cast<int>(width);
  h = static_cast<int>(height);
  return true;
}

}  // namespace

std::optional<Texture> load_texture(const std::string& path, TextureEncoding encoding, uint64_t max_texels,
                                    std::string& error) {
  const auto bytes = read_input_bytes(path, kMaxFileBytes, error);
  if (!bytes) {
    error = "cannot read \"" + path + "\": " + error;
    return std::nullopt;
  }
  return decode_texture(*bytes, path, encoding, max_texels, error);
}

std::optional<Texture> decode_texture(const std::vector<unsigned char>& bytes, const std::string& path,
                                      TextureEncoding encoding, uint64_t max_texels, std::string& error) {
  if (bytes.size() > kMaxFileBytes) {
    error = "cannot read \"" + path + "\" as an image: it is larger than " + format_bytes(kMaxFileBytes);
    return std::nullopt;
  }
  const auto* data = bytes.data();
  const int size = static_cast<int>(bytes.size());
  int w = 0, h = 0, channels = 0;
  const bool known = stbi_info_from_memory(data, size, &w, &h, &channels);
  // stb_image refuses empty and enormous PNG files without saying their size; the header does.
  if (!known && !png_header_size(bytes, w, h)) {
    error = "cannot read \"" + path + "\" as an image (PNG or JPEG): " + stb_reason();
    return std::nullopt;
  }
  const uint64_t texels = static_cast<uint64_t>(w) * static_cast<uint64_t>(h);
  if (!known || w <= 0 || h <= 0 || texels > max_texels) {
    error = "expected an image of 1 to " + std::to_string(max_texels) + " texels, found " + std::to_string(w) + " x " +
            std::to_string(h) + " in \"" + path + "\"";
    return std::nullopt;
  }

  std::vector<Vec3> linear(static_cast<size_t>(texels));
  // stb_image converts any layout to the channels asked for (alpha 1 where the file has none).
  const bool alpha = encoding == TextureEncoding::kAlpha;
  const int wanted = alpha ? 4 : 3;
  const auto step = static_cast<size_t>(wanted);
  if (stbi_is_16_bit_from_memory(data, size)) {
    const std::unique_ptr<uint16_t, StbFree> pixels(stbi_load_16_from_memory(data, size, &w, &h, &channels, wanted));
    if (!pixels) {
      error = "cannot decode \"" + path + "\": " + stb_reason();
      return std::nullopt;
    }
    for (size_t i = 0; i < linear.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const float v = static_cast<float>(pixels.get()[step * i + static_cast<size_t>(alpha ? 3 : c)]) / 65535.0f;
        linear[i][c] = encoding == TextureEncoding::kSrgb ? srgb_decode(v) : v;
      }
  } else {
    const std::unique_ptr<stbi_uc, StbFree> pixels(stbi_load_from_memory(data, size, &w, &h, &channels, wanted));
    if (!pixels) {
      error = "cannot decode \"" + path + "\": " + stb_reason();
      return std::nullopt;
    }
    std::array<float, 256> decode{};  // one entry per 8-bit code
    for (int v = 0; v < 256; ++v) {
      const float f = static_cast<float>(v) / 255.0f;
      decode[static_cast<size_t>(v)] = encoding == TextureEncoding::kSrgb ? srgb_decode(f) : f;
    }
    for (size_t i = 0; i < linear.size(); ++i)
      for (int c = 0; c < 3; ++c) linear[i][c] = decode[pixels.get()[step * i + static_cast<size_t>(alpha ? 3 : c)]];
  }
  return Texture(w, h, std::move(linear));
}

}  // namespace rt
