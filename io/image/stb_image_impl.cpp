// stb_image (Debian's libstb-dev header) compiled into rtcli with PNG only, its functions static
// to this file: io/image/png_jpeg_decoder.h is the one way in. See that header.
#include <climits>

#include "io/image/png_data_check.h"
#include "io/image/png_jpeg_decoder.h"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#include <stb_image.h>

namespace rt {

std::optional<DecodedImage> decode_png(const unsigned char* bytes, size_t size, const ImageHeader& header, int channels,
                                       std::string& error) {
  if (size > static_cast<size_t>(INT_MAX)) {
    error = "the file is larger than the decoder reads (2 GiB)";
    return std::nullopt;
  }
  if (!png_data_fits(bytes, size, header, error)) return std::nullopt;
  DecodedImage image;
  image.channels = channels;
  image.sixteen_bit = header.sixteen_bit;
  int in_file = 0;
  const int n = static_cast<int>(size);
  void* data =
      image.sixteen_bit
          ? static_cast<void*>(stbi_load_16_from_memory(bytes, n, &image.width, &image.height, &in_file, channels))
          : static_cast<void*>(stbi_load_from_memory(bytes, n, &image.width, &image.height, &in_file, channels));
  image.data = std::unique_ptr<void, void (*)(void*)>(data, [](void* p) { stbi_image_free(p); });
  if (!data) {
    const char* reason = stbi_failure_reason();
    error = reason ? reason : "the decoder gave no reason";
    return std::nullopt;
  }
  // The pixels are exactly what the header announced: what the caller counted and allocates for.
  if (static_cast<uint32_t>(image.width) != header.width || static_cast<uint32_t>(image.height) != header.height) {
    error = "the decoded image is " + std::to_string(image.width) + " x " + std::to_string(image.height) +
            ", not the header's " + std::to_string(header.width) + " x " + std::to_string(header.height);
    return std::nullopt;
  }
  return image;
}

}  // namespace rt
