#include "io/image/png_file.h"

#include "core/render_settings.h"
#include "io/base/atomic_file.h"
#include "io/base/input_file.h"
#include "io/image/image_header.h"
#include "io/image/png_encoder.h"
#include "io/image/png_jpeg_decoder.h"

namespace rt {

std::optional<Rgb8Image> read_png(const std::string& path, std::string& error) {
  constexpr uint64_t kMaxFileBytes = uint64_t{256} << 20;
  const auto bytes = read_input_bytes(path, kMaxFileBytes, error);
  if (!bytes) return std::nullopt;
  auto header = read_image_header(bytes->data(), bytes->size(), error);
  if (header && header->format != ImageFormat::kPng) error = "expected a PNG image, found a JPEG image";
  if (!header || header->format != ImageFormat::kPng) return std::nullopt;
  if (uint64_t{header->width} * header->height > kMaxPixels) {
    error = "expected a PNG of at most " + std::to_string(kMaxPixels) + " pixels, found " +
            std::to_string(header->width) + " x " + std::to_string(header->height);
    return std::nullopt;
  }
  header->sixteen_bit = false;  // read as 8 bits a sample
  const auto image = decode_png_jpeg(bytes->data(), bytes->size(), *header, 3, error);
  if (!image) {
    error = "cannot decode the PNG: " + error;
    return std::nullopt;
  }
  const size_t samples = static_cast<size_t>(image->width) * static_cast<size_t>(image->height) * 3;
  return Rgb8Image{image->width, image->height, ZeroedVector<uint8_t>(image->bytes(), image->bytes() + samples)};
}

bool write_png(const std::string& path, const Rgb8Image& image, std::string& error, unsigned threads) {
  return write_png(path, rows_of(image), error, threads);
}

bool write_png(const std::string& path, const Rgb8Rows& rows, std::string& error, unsigned threads) {
  const std::vector<uint8_t> png = encode_png(rows, threads);
  if (png.empty()) {
    error = "PNG encoding failed";
    return false;
  }
  return write_file_atomically(path, png, error);
}

}  // namespace rt
