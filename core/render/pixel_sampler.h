// Pixel samplers choose where in a pixel camera rays go and how their radiance is combined.
// An open, coarse set behind a small interface (one call per pixel). Adaptive corner
// subdivision joins "centre" and "uniform" here later.
#pragma once

#include <memory>

#include "core/render/integrator.h"

namespace rt {

struct PixelContext {
  const Scene& scene;
  const RenderSettings& settings;
  const Integrator& integrator;
  RayCounters& counters;
  uint32_t frame = 0;
};

class PixelSampler {
 public:
  virtual ~PixelSampler() = default;
  virtual Vec3 pixel(int x, int y, PixelContext& ctx) const = 0;
};

std::unique_ptr<PixelSampler> make_pixel_sampler(const RenderSettings& settings);

}  // namespace rt
