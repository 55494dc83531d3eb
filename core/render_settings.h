// How to render a scene: everything that is not the scene itself. The scene file's "render"
// block fills it; command-line options override it.
#pragma once

#include <cstdint>
#include <string>

namespace rt {

enum class PixelSamplerKind { kCentre, kUniform };

struct RenderSettings {
  int width = 640;
  int height = 480;
  int max_depth = 5;     // bounces after the camera ray (reflection/refraction), >= 0
  uint64_t seed = 0;     // keys every random stream, with frame, pixel and sample index
  unsigned threads = 0;  // 0 = one per hardware thread
  std::string integrator = "whitted";
  PixelSamplerKind sampler = PixelSamplerKind::kCentre;
  int samples_per_axis = 1;  // uniform sampler: n x n samples per pixel
  bool jitter = false;       // uniform sampler: a keyed random point in each cell, not its centre
  int tile_size = 32;        // pixels per tile side; the image never depends on it
  int glossy_samples = 8;    // the proposal's glossy_count: rays per glossy reflection
  bool glossy = true;        // false (--no-glossy): glossy surfaces reflect as perfect mirrors
  int shadow_samples = 16;   // the proposal's shadow_count: shadow rays per area light and point
};

// Limits on what settings may ask for (README.md, "Limits"). The film holds 12 bytes a pixel
// (linear RGB floats), so the pixel count bounds memory: 2^26 pixels (8192 x 8192) is 768 MiB.
inline constexpr int kMaxImageSide = 16384;
inline constexpr uint64_t kMaxPixels = uint64_t{1} << 26;
inline constexpr int kMaxSamplesPerAxis = 16;
inline constexpr int kMaxRecursionDepth = 64;
inline constexpr int kMaxGlossySamples = 256;
inline constexpr int kMaxShadowSamples = 1024;
// Past this many camera rays per frame a render takes minutes to hours: warned about, not refused.
inline constexpr uint64_t kCameraRaysWarning = uint64_t{1} << 30;

inline uint64_t pixel_count(const RenderSettings& s) {
  return static_cast<uint64_t>(s.width) * static_cast<uint64_t>(s.height);
}
// Camera rays one frame traces: pixels times samples per pixel.
inline uint64_t camera_rays_per_frame(const RenderSettings& s) {
  const auto n = static_cast<uint64_t>(s.sampler == PixelSamplerKind::kUniform ? s.samples_per_axis : 1);
  return pixel_count(s) * n * n;
}

}  // namespace rt
