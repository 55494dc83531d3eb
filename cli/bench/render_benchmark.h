// The time of a whole render (camera rays, shading, shadows, secondary rays), as `rtcli bench`
// reports it.
#pragma once

#include "core/render/renderer.h"

namespace rt {

// The fastest of `repeats` renders of `scene` with `settings` on `threads` threads: its time and
// rays by kind (the same for every repeat: the image is deterministic).
RenderStats best_render(const Scene& scene, RenderSettings settings, unsigned threads, int repeats = 3);

}  // namespace rt
