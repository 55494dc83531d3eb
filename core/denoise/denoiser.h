// Denoising a rendered image with what the render knows about its first hits: the features of
// every pixel (albedo, normal, depth: core/render/aovs.h) and the variance of its mean. A denoiser
// is a pure function of those images, run once the whole image is there (after a tiled render's
// merge), so a denoised image is as deterministic as the render. The table names the denoisers
// rtcli has: its own feature-guided filter now, OpenImageDenoise where a packaged one exists.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "core/image.h"
#include "core/name_table.h"

namespace rt {

// One image and its features, all the same size, row-major.
struct DenoiseInput {
  const Image& color;                  // linear radiance
  const Image& albedo;                 // the first hit's diffuse colour; black where nothing was met
  const Image& normal;                 // the first hit's shading normal; zero where nothing was met
  const Image& emission;               // what the first thing met emits (lights, the background): kept as it is
  const std::vector<float>& depth;     // along the camera ray; Aovs::kFarAway where nothing was met
  const std::vector<float>& variance;  // of each pixel's mean luminance; all 0 if unknown
};

class Denoiser {
 public:
  virtual ~Denoiser() = default;
  // The denoised colour, on up to `threads` threads; the same for any thread count.
  virtual Image denoise(const DenoiseInput& input, unsigned threads) const = 0;
};

struct DenoiserKind {
  std::unique_ptr<Denoiser> (*make)();
};
// The name table: --denoiser (and what --denoise uses: the first).
const NameTable<DenoiserKind>& denoisers();

std::unique_ptr<Denoiser> make_denoiser(std::string_view name);

}  // namespace rt
