#include "io/png_file.h"

#include <stb_image.h>

#include "io/atomic_file.h"
#include "io/input_file.h"
#include "io/png_encoder.h"

namespace rt {

std::optional<Rgb8Image> read_png(const std::string& path, std::string& error) {
  constexpr uint64_t kMaxFileBytes = uint64_t{256} << 20;
  const auto bytes = read_input_bytes(path, kMaxFileBytes, error);
  if (!bytes) return std::nullopt;
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load_from_memory(bytes->data(), static_cast<int>(bytes->size()), &w, &h, &channels, 3);
  if (!data) {
    error = std::string("cannot read image: ") + (stbi_failure_reason() ? stbi_failure_reason() : "unknown error");
    return std::nullopt;
  }
  Rgb8Image image{w, h, std::vector<uint8_t>(data, data + static_cast<size_t>(w) * static_cast<size_t>(h) * 3)};
  stbi_image_free(data);
  return image;
}

bool write_png(const std::string& path, const Rgb8Image& image, std::string& error, unsigned threads) {
  const std::vector<uint8_t> png = encode_png(image, threads);
  if (png.empty()) {
    error = "PNG encoding failed";
    return false;
  }
  return write_file_atomically(path, png, error);
}

}  // namespace rt
