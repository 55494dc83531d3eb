// Reducing an 8-bit RGB image to at most 256 colours for GIF: Heckbert's median cut (1982) picks
// a palette for this image alone, then each pixel takes its nearest palette colour, optionally
// with Floyd-Steinberg error diffusion (dithering trades banding in gradients for fine noise).
// An image of 256 colours or fewer keeps them exactly.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "io/image/rgb8_image.h"

namespace rt {

struct IndexedImage {
  int width = 0;
  int height = 0;
  std::vector<std::array<uint8_t, 3>> palette;  // 1 to 256 colours
  std::vector<uint8_t> indices;                 // row-major, one palette index per pixel
};

IndexedImage quantise(const Rgb8Image& image, bool dither, int max_colors = 256);

// The palette as the median cut chooses it (what quantise() uses), for tests.
std::vector<std::array<uint8_t, 3>> median_cut_palette(const Rgb8Image& image, int max_colors);

}  // namespace rt
