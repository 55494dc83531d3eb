// PNG, JPEG and WebP decoding. PNG by Debian's stb_image, compiled here with every other format left
// out (io/image/stb_image_impl.cpp); JPEG by Debian's libjpeg-turbo (io/image/jpeg_decoder.cpp), because
// stb_image 2.27's JPEG decoder reads out of bounds on broken Huffman data (fuzzing found it;
// fixed upstream in 2.28, not in Debian 12). No other decoder is reachable, whatever a file
// holds. The caller has read the header (io/image/image_header.h) and checked its size against the
// limits; the decoded image must match it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "io/image/image_header.h"

namespace rt {

class DecodedImage {
 public:
  int width = 0, height = 0;
  int channels = 0;  // per pixel, as asked for: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
  bool sixteen_bit = false;

  // Sample `c` of pixel `i` (row-major) in [0, 1].
  float sample(size_t i, int c) const {
    const size_t k = i * static_cast<size_t>(channels) + static_cast<size_t>(c);
    return sixteen_bit ? static_cast<float>(static_cast<const uint16_t*>(data.get())[k]) / 65535.0f
                       : static_cast<float>(static_cast<const uint8_t*>(data.get())[k]) / 255.0f;
  }
  // 8-bit samples (not for a 16-bit image).
  const uint8_t* bytes() const { return static_cast<const uint8_t*>(data.get()); }

  std::unique_ptr<void, void (*)(void*)> data{nullptr, nullptr};
};

// Decodes the image `header` describes into `channels` samples a pixel, 3 (RGB) or 4 (RGBA;
// alpha 1 where the file has none): 16 bits for a 16-bit PNG, 8 otherwise. nullopt and the
// decoder's reason in `error` when the data is corrupt.
std::optional<DecodedImage> decode_png_jpeg(const unsigned char* bytes, size_t size, const ImageHeader& header,
                                            int channels, std::string& error);

// The two decoders behind it.
std::optional<DecodedImage> decode_png(const unsigned char* bytes, size_t size, const ImageHeader& header, int channels,
                                       std::string& error);
std::optional<DecodedImage> decode_jpeg(const unsigned char* bytes, size_t size, const ImageHeader& header,
                                        int channels, std::string& error);
// WebP (glTF's EXT_texture_webp) by Debian's libwebp (BSD-3-Clause), io/image/webp_decoder.cpp.
std::optional<DecodedImage> decode_webp(const unsigned char* bytes, size_t size, const ImageHeader& header,
                                        int channels, std::string& error);

}  // namespace rt
