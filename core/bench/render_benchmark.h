// The time of a whole render (camera rays, shading, shadows), as `rtcli bench` reports it.
#pragma once

#include "core/render_settings.h"
#include "core/scene.h"

namespace rt {

// Best of `repeats` renders of `scene` with `settings` on `threads` threads, in seconds.
double best_render_seconds(const Scene& scene, RenderSettings settings, unsigned threads, int repeats = 3);

}  // namespace rt
