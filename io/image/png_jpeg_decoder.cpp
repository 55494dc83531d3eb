#include "io/image/png_jpeg_decoder.h"

namespace rt {

std::optional<DecodedImage> decode_png_jpeg(const unsigned char* bytes, size_t size, const ImageHeader& header,
                                            int channels, std::string& error) {
  switch (header.format) {
    case ImageFormat::kPng: return decode_png(bytes, size, header, channels, error);
    case ImageFormat::kJpeg: return decode_jpeg(bytes, size, header, channels, error);
    case ImageFormat::kWebp: return decode_webp(bytes, size, header, channels, error);
  }
  return std::nullopt;
}

}  // namespace rt
