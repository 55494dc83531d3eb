#include "cli/render/render_plan.h"

#include <algorithm>
#include <cstdio>

#include "cli/common/report.h"
#include "cli/frames/render_metadata.h"
#include "cli/frames/render_share.h"
#include "cli/render/aov_layers.h"
#include "cli/render/resume_plan.h"
#include "cli/render/settings_text.h"
#include "core/render/band_split.h"
#include "core/render/integrator.h"

namespace rt {
namespace {

// A stereo camera renders two views: one file of one view cannot hold them.
bool check_stereo(const RenderJob& job, const StereoSettings& stereo) {
  if (stereo.enabled() && (is_exr(job.kind) || job.crop || job.tile))
    return fail(std::string(is_exr(job.kind) ? "EXR output"
                            : job.crop       ? "--crop"
                                             : "--tile") +
                " renders one view; it does not go with a stereo camera (--stereo none renders the left eye's view)");
  return true;
}

}  // namespace

std::optional<RenderPlan> plan_render(const RenderJob& job, const std::vector<std::string>& patterns,
                                      const FrameList& frames, const RenderSettings& settings,
                                      const StereoSettings& stereo, const LoadedScene& loaded) {
  if (!check_stereo(job, stereo)) return std::nullopt;
  const OutputKind kind = job.kind;
  RenderPlan plan;
  plan.frames = frames;
  std::string error;
  if (job.crop) {
    if (!crop_fits(*job.crop, settings.width, settings.height, error)) return fail(error), std::nullopt;
    plan.content.window = *job.crop;
  }
  if (job.tile) {
    const Share& share = *job.tile;
    if (share.count > settings.height)
      return fail("--tile " + share_text(share) + ": " + std::to_string(share.count) + " bands of rows for an image " +
                  std::to_string(settings.height) + " rows high; give at most one band a row"),
             std::nullopt;
    plan.content.window = cost_balanced_bands(loaded.scene, settings, share.count,
                                              static_cast<uint32_t>(loaded.frame))[static_cast<size_t>(share.index)];
    plan.content.identity.tile = share_text(share);
  }
  if (job.chunk) {
    const Share& share = *job.chunk;
    plan.frames = frames.chunk(share.index, share.count);
    if (plan.frames.frames.empty())
      plan.skipped =
          "chunk " + share_text(share) + " of " + std::to_string(frames.count()) + " frames has none to render";
  }
  plan.content.aovs = job.aovs;
  plan.content.exr_float = job.exr_float;
  plan.content.view = job.view;
  if (!job.denoiser.empty()) {
    // A part of the image written as EXR is denoised once the parts are merged (a filter near a
    // tile's edge needs the pixels beyond it): it carries what the denoiser reads instead.
    if (!plan.content.window.empty() && is_exr(kind)) {
      for (const std::string& layer : denoise_layers())
        if (std::find(plan.content.aovs.begin(), plan.content.aovs.end(), layer) == plan.content.aovs.end())
          plan.content.aovs.push_back(layer);
    } else {
      plan.content.denoiser = job.denoiser;
    }
  }
  if (is_exr(kind) || !job.resume.empty()) {
    RenderIdentity& id = plan.content.identity;
    id.scene = job.scene;
    id.scene_hash = hash_files(loaded.inputs);
    id.settings = settings_text(settings, job.choices, stereo.mode);
    id.seed = settings.seed;
    id.display = settings.display;
    id.fps = loaded.graph.timeline.fps;
  }
  // The path tracer's EXR keeps each pixel's sums, for a later --resume.
  plan.content.keep_sums = is_exr(kind) && integrator_samples_pixels(settings.integrator) && !stereo.enabled();
  if (!job.resume.empty()) {
    if (plan.frames.count() != 1) return fail("--resume continues one frame's render: give --frame N"), std::nullopt;
    const PixelWindow window =
        plan.content.window.empty() ? PixelWindow{0, 0, settings.width, settings.height} : plan.content.window;
    const bool layers = !plan.content.aovs.empty() || !plan.content.denoiser.empty();
    plan.content.resume =
        resume_state(job.resume, plan.content.identity, plan.frames.frames[0], window, settings, layers);
    if (!plan.content.resume) return std::nullopt;
  }
  if (job.skip_existing) {
    FrameList left;
    ExpectedExr expected;
    expected.layers = plan.content.aovs;
    if (!plan.content.denoiser.empty()) expected.layers.push_back("raw");
    expected.full_float = plan.content.exr_float;
    const PixelWindow window =
        plan.content.window.empty() ? PixelWindow{0, 0, settings.width, settings.height} : plan.content.window;
    for (const int f : plan.frames.frames) {
      bool done = true;
      if (is_exr(kind)) expected.attributes = render_attributes(plan.content.identity, f, window);
      for (const std::string& pattern : patterns)
        done = done && output_is_complete(is_sequence(kind) ? sequence_path(pattern, f) : pattern, kind, expected);
      if (!done) left.frames.push_back(f);
    }
    const int skipped = plan.frames.count() - left.count();
    if (skipped > 0)
      plan.skipped = std::to_string(skipped) + " of " + std::to_string(plan.frames.count()) +
                     (skipped == 1 ? " frame's" : " frames'") + " output" + (skipped == 1 ? " is" : "s are") +
                     " already there and complete (--skip-existing)";
    plan.frames = left;
  }
  return plan;
}

}  // namespace rt
