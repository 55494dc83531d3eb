// Texture image files (PNG, JPEG) through stb_image: 8- or 16-bit, grey, grey + alpha, RGB or
// RGBA, decoded to linear RGB. Colour textures are stored sRGB-encoded and decoded; height and
// normal maps hold data, not colour, and are read as they are; kAlpha reads the alpha channel
// (1 where there is none) into all three channels, for glTF's alpha masks.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/texture/texture.h"

namespace rt {

enum class TextureEncoding { kSrgb, kLinear, kAlpha };

// A file that is missing, unreadable, not an image, zero-sized or over `max_texels` (checked from
// its header, before decoding) gives nullopt and an error saying what was found.
std::optional<Texture> load_texture(const std::string& path, TextureEncoding encoding, uint64_t max_texels,
                                    std::string& error);

// The same from an image already in memory (a glTF buffer view or data URI); `path` names it in errors.
std::optional<Texture> decode_texture(const std::vector<unsigned char>& bytes, const std::string& path,
                                      TextureEncoding encoding, uint64_t max_texels, std::string& error);

}  // namespace rt
