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
  int tile_size = 32;        // pixels per tile side; the image never depends on it
};

}  // namespace rt
