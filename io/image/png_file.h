// PNG files: the one module that reads (io/image/png_jpeg_decoder.h) and writes (io/image/png_encoder.h) them.
#pragma once

#include <optional>
#include <string>

#include "io/image/rgb8_image.h"

namespace rt {

// Reads a PNG as 8-bit RGB (16-bit samples rounded): a regular file of at most 256 MiB
// (io/base/input_file.h) and at most kMaxPixels pixels (the largest image rtcli renders).
std::optional<Rgb8Image> read_png(const std::string& path, std::string& error);

// Writes a PNG through a temporary file and an atomic rename (io/base/atomic_file.h), encoding on up
// to `threads` threads (the file's bytes do not depend on it).
bool write_png(const std::string& path, const Rgb8Image& image, std::string& error, unsigned threads = 1);
// The same from rows made as the encoder needs them (io/image/rgb8_image.h).
bool write_png(const std::string& path, const Rgb8Rows& rows, std::string& error, unsigned threads = 1);

}  // namespace rt
