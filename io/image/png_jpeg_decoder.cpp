#include "io/image/png_jpeg_decoder.h"

namespace rt {

std::optional<DecodedImage> decode_png_jpeg(const unsigned char* bytes, size_t size, const ImageHeader& header,
                                            int channels, std::string& error) {
  return header.format == ImageFormat::kPng ? decode_png(bytes, size, header, channels, error)
                                            : decode_jpeg(bytes, size, header, channels, error);
}

}  // namespace rt
