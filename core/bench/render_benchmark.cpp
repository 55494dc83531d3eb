#include "core/bench/render_benchmark.h"

#include <algorithm>

#include "core/render/renderer.h"

namespace rt {

double best_render_seconds(const Scene& scene, RenderSettings settings, unsigned threads, int repeats) {
  settings.threads = threads;
  Image image;
  double best = kInfinity;
  for (int repeat = 0; repeat < repeats; ++repeat) best = std::min(best, render(scene, settings, image).seconds);
  return best;
}

}  // namespace rt
