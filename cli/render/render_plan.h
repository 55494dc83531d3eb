// What this process renders, decided once the scene is loaded: which frames (--chunk and
// --skip-existing take some away), which part of the image (--crop, --tile), and what each
// frame's EXR file holds beside the colour (--aov, --exr-float, the metadata).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/frames/frame_list.h"
#include "cli/frames/frame_output.h"
#include "cli/render/frame_renderer.h"
#include "cli/render/render_job.h"
#include "core/stereo.h"
#include "io/scene_loader.h"

namespace rt {

struct RenderPlan {
  FrameList frames;  // may be empty: nothing left to do (`skipped` says why)
  FrameContent content;
  std::string skipped;  // the message when frames were left out or nothing is left
};

// `frames`: all the job asks for; `patterns`: the outputs (one, or each eye's). Nothing, after
// printing why, for a part that does not fit the image or options that do not go with the
// scene's camera.
std::optional<RenderPlan> plan_render(const RenderJob& job, const std::vector<std::string>& patterns,
                                      const FrameList& frames, const RenderSettings& settings,
                                      const StereoSettings& stereo, const LoadedScene& loaded);

}  // namespace rt
