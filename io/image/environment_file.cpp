#include "io/image/environment_file.h"

#include "io/base/input_file.h"
#include "io/image/exr_file.h"
#include "io/image/hdr_file.h"

namespace rt {
namespace {

// The largest environment file read: a 16k x 8k float EXR is about 1.5 GB, more than a render
// needs; 512 MiB holds an 8k x 4k one.
constexpr uint64_t kMaxEnvironmentFileBytes = uint64_t{512} << 20;

bool is_exr(const std::vector<unsigned char>& b) {
  return b.size() >= 4 && b[0] == 0x76 && b[1] == 0x2f && b[2] == 0x31 && b[3] == 0x01;
}

std::optional<HdrImage> decode_exr(const std::vector<unsigned char>& bytes, const std::string& path,
                                   uint64_t max_texels, std::string& error) {
  const std::optional<ExrImage> exr = read_exr_rgb(bytes, path, max_texels, error);
  if (!exr) return std::nullopt;
  HdrImage image;
  image.width = exr->width;
  image.height = exr->height;
  const std::vector<float>& v = exr->layers.front().values;
  image.texels.resize(v.size() / 3);
  for (size_t i = 0; i < image.texels.size(); ++i) image.texels[i] = Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  return image;
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
  else if (is_exr(*bytes)) image = decode_exr(*bytes, path, max_texels, why);
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
