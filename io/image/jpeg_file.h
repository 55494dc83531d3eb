// JPEG files written (renders for the gallery's large photographs), by libjpeg-turbo, the library
// that already decodes JPEG textures (io/image/jpeg_decoder.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/image/rgb8_image.h"

namespace rt {

// Baseline JPEG of an sRGB image at `quality` (1 to 100), 4:2:0 chroma; empty if libjpeg fails
// (`error` says why).
std::vector<uint8_t> encode_jpeg(const Rgb8Image& image, int quality, std::string& error);

// Writes it through a temporary file and an atomic rename (io/base/atomic_file.h).
bool write_jpeg(const std::string& path, const Rgb8Image& image, std::string& error, int quality = 92);

}  // namespace rt
