#include <webp/decode.h>

#include "io/image/png_jpeg_decoder.h"

namespace rt {

std::optional<DecodedImage> decode_webp(const unsigned char* bytes, size_t size, const ImageHeader& header,
                                        int channels, std::string& error) {
  int width = 0, height = 0;
  uint8_t* pixels =
      channels == 4 ? WebPDecodeRGBA(bytes, size, &width, &height) : WebPDecodeRGB(bytes, size, &width, &height);
  if (!pixels) {
    error = "its WebP data is damaged";
    return std::nullopt;
  }
  DecodedImage image;
  image.data = std::unique_ptr<void, void (*)(void*)>(pixels, &WebPFree);
  if (width != static_cast<int>(header.width) || height != static_cast<int>(header.height)) {
    error = "its WebP data does not match its header's size";
    return std::nullopt;
  }
  image.width = width;
  image.height = height;
  image.channels = channels;
  return image;
}

}  // namespace rt
