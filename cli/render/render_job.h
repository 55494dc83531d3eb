// A render request, typed and checked: everything `rtcli render`'s options ask for beyond the
// render settings, read once from the option struct (cli/render/render_command.h) before the
// scene is loaded, so that nothing below the command sees option text. Names are checked against
// the render pipeline's tables, frame lists and shares parsed, the output's kind known, and the
// options that cannot go together refused (the ones that depend on the scene, its size or its
// camera, are checked by the plan: cli/render/render_plan.h).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/common/progress_bar.h"
#include "cli/frames/frame_list.h"
#include "cli/frames/frame_output.h"
#include "cli/frames/render_share.h"
#include "cli/render/render_command.h"
#include "core/pixel_window.h"
#include "core/stereo.h"
#include "io/image/view_transform.h"

namespace rt {

// The choices that shape the pixels without being render settings (rtcli:settings records them:
// cli/render/settings_text.h). Empty: the scene's own.
struct PixelChoices {
  std::string camera;      // a glTF camera by name
  std::string background;  // "R,G,B" or one number, as given
  std::string ambient;
  std::string environment;           // "FILE,intensity,rotate" as given
  std::string animation;             // a model on its own: one of its animations
  std::optional<float> fps;          // a model on its own: its timeline's rate
  std::optional<StereoMode> stereo;  // replacing the camera's mode
};

struct RenderJob {
  std::string scene;
  FrameList frames;           // as asked (--frame, --frames)
  bool frames_given = false;  // false: the scene's timeline decides (the first frame, or all for an animation)
  std::string output;         // the file, or the pattern of numbered files (default <scene name>.png or .gif)
  OutputKind kind = OutputKind::kPng;
  std::string stats;  // --stats: the render's figures as JSON to this file; empty: none
  // The part of the render this process does (cli/frames/render_share.h); the crop is checked
  // against the image's size by the plan.
  std::optional<PixelWindow> crop;
  std::optional<Share> tile, chunk;
  bool skip_existing = false;
  // EXR output: the layers beside the colour (albedo, normal, depth: cli/render/aov_layers.h),
  // full floats or half.
  std::vector<std::string> aovs;
  bool exr_float = false;
  // --denoise: the denoiser's name, empty for none (cli/render/render_plan.h says where it runs).
  std::string denoiser;
  double time_limit = 0.0;  // --time: seconds per frame (0: none)
  std::string resume;       // --resume: the EXR of the render to continue; empty: none
  // Images written beside a PNG: --aa-debug's two, --samples-debug's one.
  bool aa_debug = false, samples_debug = false;
  bool dither = false;  // GIF frames: Floyd-Steinberg error diffusion
  bool quiet = false;
  ProgressStyle progress = ProgressStyle::kAuto;  // --progress (auto: the bar on a terminal unless quiet)
  PixelChoices choices;
  // --view-transform: PNG and GIF frames through an OpenColorIO view instead of the tone curve;
  // null: the tone curve (and for "standard" without a config, which is the same sRGB encoding).
  std::shared_ptr<const ViewTransform> view;
};

// The job the command asks for; nothing, after printing why (exit code 2), when an option is not
// understood or options do not go together.
std::optional<RenderJob> make_render_job(const RenderCommand& cmd, const EnvironmentLookup& env);

}  // namespace rt
