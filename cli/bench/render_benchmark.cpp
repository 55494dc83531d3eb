#include "cli/bench/render_benchmark.h"

namespace rt {

RenderBenchmark time_render(const Scene& scene, RenderSettings settings, unsigned threads, int repeats) {
  settings.threads = threads;
  Image image;
  RenderBenchmark result;
  std::vector<double> seconds;
  result.rays = render(scene, settings, image).rays;  // the warm-up
  for (int i = 0; i < std::max(1, repeats); ++i) seconds.push_back(render(scene, settings, image).seconds);
  result.seconds = summarise(seconds);
  return result;
}

}  // namespace rt
