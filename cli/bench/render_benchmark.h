// The time of a whole render (camera rays, shading, shadows, secondary rays), as `rtcli bench`
// reports it.
#pragma once

#include "cli/bench/timing.h"
#include "core/render/renderer.h"

namespace rt {

struct RenderBenchmark {
  Timing seconds;    // the render loop's own time, as RenderStats reports it
  RayCounters rays;  // the same on every run: the image is deterministic
};

// `repeats` renders of `scene` with `settings` on `threads` threads, after a warm-up.
RenderBenchmark time_render(const Scene& scene, RenderSettings settings, unsigned threads, int repeats);

}  // namespace rt
