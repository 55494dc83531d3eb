// Texture image files, PNG, JPEG or WebP (io/image/image_header.h says why no other format): 8- or 16-bit,
// grey, grey + alpha, RGB or RGBA, decoded to linear RGB. Colour textures are stored
// sRGB-encoded and decoded; height and normal maps hold data, not colour, and are read as they
// are; kAlpha reads the alpha channel (1 where there is none) into all three channels, for glTF's
// alpha masks. The header is read and checked against the limits before any decoding.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/texture/texture.h"
#include "io/base/load_options.h"
#include "io/image/image_header.h"

namespace rt {

enum class TextureEncoding { kSrgb, kLinear, kAlpha };

// The largest texture file read.
inline constexpr uint64_t kMaxTextureFileBytes = uint64_t{256} << 20;

struct TextureError {
  std::string message;       // names the file and says what was found
  bool over_budget = false;  // the image is fine, but the scene's texel budget has no room for it
};

// A file that is missing, unreadable, not a PNG, JPEG or WebP, broken, or too big for what is left of
// the limits (LoadLimits::texture_texels for the image, scene_texels after usage.texels for it
// and its mip levels, checked from its header) gives nullopt and an error that names `path` and
// says what was found. A texture made adds its texels to usage.texels.
std::optional<Texture> load_texture(const std::string& path, TextureEncoding encoding, const LoadLimits& limits,
                                    LimitUsage& usage, TextureError& error);

// The same from an image already in memory (a glTF buffer view or data URI); `name` names it
// in errors. It is claim_texture, then decode_claimed_texture.
std::optional<Texture> decode_texture(std::span<const unsigned char> bytes, const std::string& name,
                                      TextureEncoding encoding, const LoadLimits& limits, LimitUsage& usage,
                                      TextureError& error);

// In two steps, so that images can be decoded on many threads: the header read and its texels
// counted against the limits and taken from them (in order, on one thread), ...
std::optional<ImageHeader> claim_texture(std::span<const unsigned char> bytes, const std::string& name,
                                         const LoadLimits& limits, LimitUsage& usage, TextureError& error);
// ... then the decoding, which touches nothing shared.
std::optional<Texture> decode_claimed_texture(std::span<const unsigned char> bytes, const ImageHeader& header,
                                              const std::string& name, TextureEncoding encoding, TextureError& error);

}  // namespace rt
