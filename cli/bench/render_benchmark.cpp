#include "cli/bench/render_benchmark.h"

namespace rt {

RenderStats best_render(const Scene& scene, RenderSettings settings, unsigned threads, int repeats) {
  settings.threads = threads;
  Image image;
  RenderStats best;
  best.seconds = kInfinity;
  for (int repeat = 0; repeat < repeats; ++repeat) {
    const RenderStats stats = render(scene, settings, image);
    if (stats.seconds < best.seconds) best = stats;
  }
  return best;
}

}  // namespace rt
