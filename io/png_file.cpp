#include "io/png_file.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include "io/atomic_file.h"
#include "io/input_file.h"

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

bool write_png(const std::string& path, const Rgb8Image& image, std::string& error) {
  std::vector<uint8_t> png;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const auto* bytes = static_cast<const uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
  };
  if (!stbi_write_png_to_func(append, &png, image.width, image.height, 3, image.rgb.data(), image.width * 3)) {
    error = "PNG encoding failed";
    return false;
  }
  return write_file_atomically(path, png, error);
}

}  // namespace rt
