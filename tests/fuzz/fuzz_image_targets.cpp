// The fuzz targets of files that hold light and pixels: environment images (.hdr and .exr, as a
// scene's background loads them) and EXR tiles as rtcli merge reads them.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include "cli/frames/exr_denoise.h"
#include "cli/frames/tile_merge.h"
#include "cli/render/sample_state.h"
#include "core/lights/environment.h"
#include "core/rng.h"
#include "io/image/environment_file.h"
#include "io/image/exr_file.h"
#include "io/image/hdr_file.h"
#include "tests/fuzz/fuzz_targets.h"

namespace rt::fuzz {

namespace {

// An environment made of a decoded image: its texels finite and >= 0, its sampling giving unit
// directions with positive, finite densities and finite radiance, at the poles too.
std::string check_environment(const HdrImage& image, const std::string& what) {
  if (image.width < 1 || image.height < 1 ||
      image.texels.size() != static_cast<size_t>(image.width) * static_cast<size_t>(image.height))
    return "a decoded " + what + " image has no texels or the wrong number";
  for (const Vec3& t : image.texels)
    if (!is_finite(t) || std::min({t.x, t.y, t.z}) < 0.0f) return "a decoded " + what + " texel is not finite and >= 0";
  const Environment env(std::make_shared<const EnvironmentImage>(image.width, image.height, image.texels), 1.0f, 33.0f);
  return check_environment_sampling(env, image.texels.size());
}

}  // namespace

std::string check_environment_sampling(const Environment& env, uint64_t seed) {
  Rng rng(seed);
  for (int k = 0; k < 64; ++k) {
    Vec3 d, radiance;
    float pdf = 0.0f;
    if (!env.sample(Vec2(rng.next_float(), rng.next_float()), d, radiance, pdf)) break;
    if (!is_finite(d) || std::fabs(glm::length(d) - 1.0f) > 1e-3f)
      return "an environment sample's direction is not unit";
    if (!(pdf > 0.0f) || !std::isfinite(pdf)) return "an environment sample's density is not positive and finite";
    if (!is_finite(radiance)) return "an environment sample's radiance is not finite";
    if (!is_finite(env.radiance(d)) || !std::isfinite(env.pdf(d)))
      return "radiance or pdf at a sampled direction is not finite";
  }
  for (const Vec3 d : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(1e-30f, 1, 0), Vec3(0, 0, -1)})
    if (!is_finite(env.radiance(d)) || !std::isfinite(env.pdf(d))) return "radiance or pdf at a pole is not finite";
  return "";
}

std::string environment_image(const uint8_t* data, size_t size) {
  std::string error;
  auto image = decode_hdr(std::span<const unsigned char>(data, size), uint64_t{1} << 20, error);
  if (!image) return error.empty() ? "decode_hdr failed without saying why" : "";
  return check_environment(*image, ".hdr");
}

std::string environment_exr(const uint8_t* data, size_t size) {
  // The loader reads a file, as a scene's background names one: through the bounded reader, then
  // the structure walk and OpenEXR's RGBA interface, with a texel budget.
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("rtcli-fuzz-env-" + std::to_string(::getpid()) + ".exr");
  write_bytes(path, data, size);
  LoadLimits limits;
  limits.texture_texels = uint64_t{1} << 20;
  limits.scene_texels = uint64_t{1} << 21;
  LimitUsage usage;
  std::string error;
  const auto env = load_environment_image(path.string(), limits, usage, error);
  std::filesystem::remove(path);
  if (!env) return error.empty() ? "load_environment_image failed without saying why" : "";
  if (usage.texels > limits.texture_texels) return "an environment image took more texels than its limit";
  return check_environment_sampling(Environment(env, 1.0f, 33.0f), size);
}

std::string exr_tile(const uint8_t* data, size_t size) {
  // OpenEXR reads files: the bytes go to one of this process's own.
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("rtcli-fuzz-exr-" + std::to_string(::getpid()) + ".exr");
  write_bytes(path, data, size);
  std::string error;
  const auto image = read_exr(path.string(), uint64_t{1} << 20, error);
  if (image) {
    if (!image->window.inside(image->width, image->height) || image->window.empty())
      return "an EXR read with its data window outside its image";
    for (const ExrLayer& l : image->layers)
      if (l.values.size() != image->window.pixels() * l.channels.size()) return "an EXR layer with the wrong size";
    // render --resume: the sample sums, with and without the first hit's layers.
    for (const bool layers : {false, true}) {
      std::string why;
      const auto state = read_sample_state(*image, layers, 65535, why);
      if (!state && why.empty()) return "read_sample_state failed without saying why";
      if (state && state->size() != image->window.pixels()) return "sample sums of the wrong size";
    }
  } else if (error.empty()) {
    return "read_exr failed without saying why";
  }
  std::vector<std::string> problems;
  const auto merged = merge_tiles({path.string()}, problems, uint64_t{1} << 20);
  if (!merged && problems.empty()) return "merge failed without saying why";
  if (merged && (!image || image->window != PixelWindow::whole(image->width, image->height)))
    return "merge of one tile succeeded but the tile is not the whole image";
  if (merged) {  // rtcli merge --denoise: the layers checked, then the whole image denoised
    ExrImage denoised = *merged;
    std::string denoise_error;
    if (!denoise_exr(denoised, "feature", 1, denoise_error) && denoise_error.empty())
      return "denoise failed without saying why";
  }
  std::filesystem::remove(path);
  return "";
}

}  // namespace rt::fuzz
