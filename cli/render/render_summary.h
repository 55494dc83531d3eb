// The lines `rtcli render` prints when it is done: what was rendered, in how long, how many rays
// of each kind and how fast, the samples per pixel (or the anti-aliasing's refinement), the files.
#pragma once

#include <string>
#include <vector>

#include "cli/frames/frame_list.h"
#include "cli/render/frame_renderer.h"
#include "cli/render/render_job.h"
#include "core/accel/isa.h"
#include "core/render_settings.h"

namespace rt {

void print_summary(const RenderJob& job, const RenderSettings& settings, const FrameList& frames, const RenderTotals& t,
                   double load_seconds, const std::vector<std::string>& written, Isa isa_used);

}  // namespace rt
