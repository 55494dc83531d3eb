// How to render a scene: everything that is not the scene itself. The scene file's "render"
// block fills it; command-line options override it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/name_table.h"
#include "core/sampling.h"
#include "core/texture/texture.h"
#include "core/tone_map.h"

namespace rt {

// Where the adaptive sampler places the rays of a cell (docs/rendering.md, "Anti-aliasing").
enum class SamplePositions { kCorners, kCentres };
inline constexpr NameEntry<SamplePositions> kSamplePositionEntries[] = {
    {"corners", SamplePositions::kCorners, "cell corners, shared with the neighbours"},
    {"centres", SamplePositions::kCentres, "the centres of each cell's quarters"}};
inline constexpr NameTable<SamplePositions> kSamplePositions{kSamplePositionEntries};

// The names render.sampler and --sampler take (core/sampling.h).
inline constexpr NameEntry<SampleSequence> kSampleSequenceEntries[] = {
    {"sobol", SampleSequence::kSobol,
     "Owen-scrambled Sobol points: each pixel's samples cover every pair of dimensions evenly"},
    {"independent", SampleSequence::kIndependent, "an independent hash for every number (rtcli before 0.9)"}};
inline constexpr NameTable<SampleSequence> kSampleSequences{kSampleSequenceEntries};

// render.antialias: which pixel sampler, and its parameters (each read by its own mode only).
struct AntialiasSettings {
  std::string mode = "adaptive";  // a name in the pixel sampler table: none, uniform, adaptive
  int samples = 1;                // uniform: samples x samples rays per pixel
  bool jitter = false;            // uniform: a keyed random point in each cell, not its centre
  float threshold = 0.1f;         // adaptive: split a cell whose corners differ by more (displayed values)
  int max_depth = 3;              // adaptive: splits at most; a pixel becomes up to 2^d x 2^d cells
  SamplePositions positions = SamplePositions::kCorners;
};

// Switches for comparisons (docs/rendering.md, "Textures, bump and normal maps", shows the bump
// scene both ways and measures what textures and bumps cost).
struct SurfaceDetailSwitches {
  bool textures = true;          // false (--no-textures): colour and specular textures are not read
  bool bumps = true;             // false (--no-bumps): bump and normal maps leave the normal as it is
  bool override_filter = false;  // --texture-filter: every texture uses `filter` instead of its own
  TextureFilter filter = TextureFilter::kTrilinear;
};

// The path tracer's own settings (docs/rendering.md, "Path tracing"); max_depth above is shared.
struct PathSettings {
  int samples_per_pixel = 64;  // render.samples_per_pixel / --spp: the most camera samples of a pixel
  // render.noise_threshold / --noise-threshold: a pixel stops once its estimated relative error
  // is below this (0: off, every pixel takes samples_per_pixel).
  float noise_threshold = 0.0f;
  // render.clamp: the largest value (max channel) one camera sample may add; 0: off. Biased.
  float clamp = 0.0f;
  // How lights that both strategies can find (rect lights, emissive meshes) are found: both,
  // combined by multiple importance sampling (the default), or one alone. Every choice converges
  // to the same image; the test of MIS renders all three (tests/render/test_path_tracer.cpp).
  enum class Strategy { kMis, kLights, kBsdf };
  Strategy strategy = Strategy::kMis;
};

struct RenderSettings {
  int width = 640;
  int height = 480;
  int max_depth = 5;                                // bounces after the camera ray (reflection/refraction), >= 0
  uint64_t seed = 0;                                // keys every random stream, with frame, pixel and sample index
  SampleSequence sampler = SampleSequence::kSobol;  // render.sampler / --sampler
  unsigned threads = 0;                             // 0 = one per CPU the process may use (core/thread_count.h)
  std::string integrator = "whitted";
  AntialiasSettings antialias;
  int tile_size = 32;       // pixels per tile side; the image never depends on it
  int glossy_samples = 8;   // the proposal's glossy_count: rays per glossy reflection
  bool glossy = true;       // false (--no-glossy): glossy surfaces reflect as perfect mirrors
  int shadow_samples = 16;  // the proposal's shadow_count: shadow rays per area light and point
  // At a hit below the camera ray (reflection, refraction, glossy), an area light takes
  // shadow_samples times the hit's weight in the pixel, at least one (secondary_shadow_samples);
  // false ("full"): every hit takes shadow_samples.
  bool scale_secondary_shadows = true;
  SurfaceDetailSwitches detail;
  // Linear radiance to display: exposure in stops and the tone curve (core/tone_map.h).
  DisplayTransform display;
  PathSettings path;
};

// Limits on what settings may ask for (docs/errors-and-limits.md, "Limits"). The film holds 12 bytes a pixel
// (linear RGB floats), so the pixel count bounds memory: 2^26 pixels (8192 x 8192) is 768 MiB.
inline constexpr int kMaxImageSide = 16384;
inline constexpr uint64_t kMaxPixels = uint64_t{1} << 26;
inline constexpr int kMaxSamplesPerAxis = 16;
inline constexpr int kMaxAdaptiveDepth = 4;  // 16 x 16 cells, like the largest uniform grid
inline constexpr int kMaxRecursionDepth = 64;
inline constexpr int kMaxGlossySamples = 256;
inline constexpr int kMaxShadowSamples = 1024;
inline constexpr int kMaxSamplesPerPixel = 65535;  // the film's sample count is 16 bits
// Past this many camera rays per frame a render takes minutes to hours: warned about, not refused.
inline constexpr uint64_t kCameraRaysWarning = uint64_t{1} << 30;

// The names render.secondary_shadows and --secondary-shadows take: whether shadow rays at
// secondary hits are scaled (RenderSettings::scale_secondary_shadows).
inline constexpr NameEntry<bool> kSecondaryShadowEntries[] = {
    {"full", false, "all shadow_samples at every hit"},
    {"scaled", true, "shadow rays at reflected, refracted and glossy hits scaled by their weight in the pixel"}};
inline constexpr NameTable<bool> kSecondaryShadows{kSecondaryShadowEntries};

// Shadow samples of an area light at a hit of weight `weight` in its pixel (1 for a camera ray's
// hit; a mirror's reflectivity, times 1/n under a glossy split into n rays, for the hits below):
// ceil(samples * weight), between 1 and samples. The samples a pixel's ray tree takes then follow
// what each hit adds to the pixel, as the glossy split already makes its rays do.
inline int secondary_shadow_samples(int samples, float weight) {
  // A camera ray's hit (weight 1) and a single sample keep theirs: what the rule below gives them,
  // without its ceil (baseline x86-64 has no rounding instruction: a branchy sequence of
  // conversions, a tenth of direct lighting's own time on reflection.json).
  if (samples <= 1 || weight >= 1.0f) return samples;
  const float scaled = std::ceil(static_cast<float>(samples) * weight);
  return scaled >= static_cast<float>(samples) ? samples : std::max(1, static_cast<int>(scaled));
}

// --preview, the draft for looking at a scene while editing it: one camera ray through each
// pixel's centre (no anti-aliasing, so no adaptive refinement), and a quarter of the shadow and
// glossy samples, at most 4 of each. The image keeps its size, camera, depth and lights.
inline RenderSettings preview_settings(RenderSettings s) {
  s.antialias.mode = "none";
  s.shadow_samples = std::clamp((s.shadow_samples + 3) / 4, 1, 4);
  s.glossy_samples = std::clamp((s.glossy_samples + 3) / 4, 1, 4);
  return s;
}

inline uint64_t pixel_count(const RenderSettings& s) {
  return static_cast<uint64_t>(s.width) * static_cast<uint64_t>(s.height);
}
// The most camera rays one frame can trace: pixels times the most rays a pixel can take
// (adaptive: every cell split down to max_depth).
inline uint64_t max_camera_rays_per_frame(const RenderSettings& s) {
  const AntialiasSettings& aa = s.antialias;
  uint64_t per_pixel = 1;
  if (aa.mode == "uniform") {
    per_pixel = static_cast<uint64_t>(aa.samples) * static_cast<uint64_t>(aa.samples);
  } else if (aa.mode == "adaptive") {
    const uint64_t cells = uint64_t{1} << aa.max_depth;
    if (aa.positions == SamplePositions::kCorners) {
      per_pixel = (cells + 1) * (cells + 1);
    } else {
      per_pixel = 0;  // four centres per cell, at every level a cell is split
      for (uint64_t level = 1; level <= cells; level *= 2) per_pixel += 4 * level * level;
    }
  }
  return pixel_count(s) * per_pixel;
}

}  // namespace rt
