// 8-bit RGB images as files hold them: the encoded form of a rendered Image, and what golden
// tests and image diffs compare.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rt {

struct Rgb8Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgb;  // row-major, 3 bytes per pixel, row 0 at the top
};

// Reads PNG (or any format stb_image reads) as 8-bit RGB.
std::optional<Rgb8Image> read_rgb8(const std::string& path, std::string& error);

// Writes a PNG through a temporary file and an atomic rename.
bool write_png(const std::string& path, const Rgb8Image& image, std::string& error);

}  // namespace rt
