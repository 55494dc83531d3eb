#include "io/image/environment_file.h"

#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfRgbaFile.h>

#include <exception>

#include "io/base/input_file.h"
#include "io/image/hdr_file.h"

namespace rt {
namespace {

// The largest environment file read: a 16k x 8k float EXR is about 1.5 GB, more than a render
// needs; 512 MiB holds an 8k x 4k one.
constexpr uint64_t kMaxEnvironmentFileBytes = uint64_t{512} << 20;

bool is_exr(const std::vector<unsigned char>& b) {
  return b.size() >= 4 && b[0] == 0x76 && b[1] == 0x2f && b[2] == 0x31 && b[3] == 0x01;
}

std::optional<HdrImage> read_exr(const std::string& path, uint64_t max_texels, std::string& error) {
  try {
    Imf::RgbaInputFile file(path.c_str());
    const Imath::Box2i window = file.dataWindow();
    const long width = static_cast<long>(window.max.x) - window.min.x + 1;
    const long height = static_cast<long>(window.max.y) - window.min.y + 1;
    if (width < 1 || height < 1 || static_cast<uint64_t>(width) * static_cast<uint64_t>(height) > max_texels) {
      error = "expected at most " + std::to_string(max_texels) + " texels, found " + std::to_string(width) + " x " +
              std::to_string(height);
      return std::nullopt;
    }
    Imf::Array2D<Imf::Rgba> pixels(height, width);
    file.setFrameBuffer(&pixels[0][0] - window.min.x - static_cast<long>(window.min.y) * width, 1,
                        static_cast<size_t>(width));
    file.readPixels(window.min.y, window.max.y);
    HdrImage image;
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    image.texels.resize(static_cast<size_t>(width) * static_cast<size_t>(height));
    for (long y = 0; y < height; ++y)
      for (long x = 0; x < width; ++x) {
        const Imf::Rgba& p = pixels[y][x];
        image.texels[static_cast<size_t>(y * width + x)] =
            Vec3(static_cast<float>(p.r), static_cast<float>(p.g), static_cast<float>(p.b));
      }
    return image;
  } catch (const std::exception& e) {
    error = std::string("OpenEXR could not read it: ") + e.what();
    return std::nullopt;
  }
}

}  // namespace

std::shared_ptr<const EnvironmentImage> load_environment_image(const std::string& path, const LoadLimits& limits,
                                                               LimitUsage& usage, std::string& error) {
  std::string why;
  const auto bytes = read_input_bytes(path, kMaxEnvironmentFileBytes, why);
  if (!bytes) {
    error = "cannot read \"" + path + "\": " + why;
    return nullptr;
  }
  const uint64_t left = usage.texels >= limits.scene_texels ? 0 : limits.scene_texels - usage.texels;
  const uint64_t max_texels = std::min(limits.texture_texels, left);
  std::optional<HdrImage> image;
  if (looks_like_hdr(*bytes)) image = decode_hdr(*bytes, max_texels, why);
  else if (is_exr(*bytes)) image = read_exr(path, max_texels, why);
  else why = "expected a Radiance .hdr or an OpenEXR .exr image";
  if (!image) {
    error = why + " in \"" + path + "\"";
    return nullptr;
  }
  // Negative, infinite or NaN texels would poison every sum: they are light that cannot be.
  for (Vec3& t : image->texels)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(t[c]) || t[c] < 0.0f) t[c] = 0.0f;
  usage.texels += image->texels.size();
  return std::make_shared<const EnvironmentImage>(image->width, image->height, std::move(image->texels));
}

}  // namespace rt
