// PNG files: the one module that reads (stb_image) and writes (io/png_encoder.h) them.
#pragma once

#include <optional>
#include <string>

#include "io/rgb8_image.h"

namespace rt {

// Reads a PNG (or any format stb_image reads) as 8-bit RGB: a regular file of at most 256 MiB
// (io/input_file.h).
std::optional<Rgb8Image> read_png(const std::string& path, std::string& error);

// Writes a PNG through a temporary file and an atomic rename (io/atomic_file.h), encoding on up
// to `threads` threads (the file's bytes do not depend on it).
bool write_png(const std::string& path, const Rgb8Image& image, std::string& error, unsigned threads = 1);

}  // namespace rt
