// `rtcli render --stats FILE`: what a render cost, as JSON beside its image, for the gallery
// (docs/) and for scripts: time, rays by kind, rays per pixel, the settings that shaped them.
#pragma once

#include <string>
#include <vector>

#include "cli/frames/frame_list.h"
#include "cli/render/frame_renderer.h"
#include "core/accel/isa.h"
#include "core/render_settings.h"
#include "core/stereo.h"

namespace rt {

struct RenderStatsInput {
  std::string scene;
  std::vector<std::string> outputs;  // the files written
  const RenderSettings& settings;
  const StereoSettings& stereo;
  const FrameList& frames;
  const RenderTotals& totals;
  double load_seconds = 0.0;
  Isa isa = Isa::kSse;      // whose BVH kernels traced the rays
  double time_limit = 0.0;  // --time (0: none)
};

// The JSON text (docs/command-line.md, "--stats" lists the keys).
std::string render_stats_json(const RenderStatsInput& in);

// Writes it through a temporary file; false with `error` when it cannot.
bool write_render_stats(const std::string& path, const RenderStatsInput& in, std::string& error);

}  // namespace rt
