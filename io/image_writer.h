// Writing a rendered Image as an 8-bit sRGB PNG. Tone mapping rule: each linear channel is
// clamped to [0, 1] (NaN counts as 0), encoded with the sRGB transfer function and rounded to
// the nearest of 256 levels. The file is written under a temporary name in the same folder and
// renamed into place, so a failure never leaves a half-written file over a good one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"
#include "io/rgb8_image.h"

namespace rt {

uint8_t encode_srgb8(float linear);
Rgb8Image encode_srgb8(const Image& image);

bool write_png(const std::string& path, const Image& image, std::string& error);

// Writes bytes to `path` through a temporary file and an atomic rename.
bool write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes, std::string& error);

}  // namespace rt
