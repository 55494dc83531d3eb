// Shipped scenes under each pixel sampler and both integrators, for tests that render the same
// pixels two ways and compare them (a window and the whole image; display codes and linear
// colour). Adaptive anti-aliasing shares lattice samples across tile borders; glossy.json draws
// random numbers per pixel; the path tracer, its own sampler.
#pragma once

#include <string>
#include <utility>

#include "core/render_settings.h"
#include "io/scene_loader.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

namespace rt::test {

struct RenderCase {
  const char* scene;
  const char* integrator;
  const char* antialias;
};

inline constexpr RenderCase kRenderCases[] = {{"scenes/antialias.json", "whitted", "adaptive"},
                                              {"scenes/glossy.json", "whitted", "uniform"},
                                              {"scenes/primitives.json", "whitted", "none"},
                                              {"scenes/cornell_box.json", "path", "none"}};

// The case's scene, and its settings at width x height (4 samples a pixel for the path tracer).
inline std::pair<LoadedScene, RenderSettings> load_render_case(const RenderCase& c, int width, int height) {
  LoadedScene s = load_scene_file(source_path(c.scene));
  RenderSettings settings = s.settings;
  settings.width = width;
  settings.height = height;
  settings.integrator = c.integrator;
  settings.antialias.mode = c.antialias;
  settings.path.samples_per_pixel = 4;
  return {std::move(s), settings};
}

}  // namespace rt::test
