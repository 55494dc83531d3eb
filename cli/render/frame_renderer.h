// Renders a command's frames one after another into their outputs: each frame once, or for a
// stereo camera each eye once (the left eye's random numbers a mono render's), the two images put
// together as the stereo mode asks or, for "pair", written to two outputs.
#pragma once

#include <optional>
#include <vector>

#include "cli/frames/frame_list.h"
#include "cli/frames/frame_output.h"
#include "cli/frames/render_metadata.h"
#include "cli/render/render_job.h"
#include "core/render/film.h"
#include "core/render/renderer.h"
#include "core/render/sample_sums.h"
#include "io/scene_loader.h"

namespace rt {

struct RenderTotals {
  RenderStats last;  // the last render's (the last eye's of a stereo frame)
  RayCounters rays;
  double seconds = 0.0;          // rendering, all frames
  double place_seconds = 0.0;    // placing animated frames (top-level BVHs)
  size_t refined = 0;            // pixels refined by adaptive anti-aliasing, all frames and eyes
  uint64_t samples = 0;          // camera samples the pixels average, all frames and eyes
  uint64_t resumed_samples = 0;  // of those, the ones --resume's file had (not traced here)
  int passes = 1;                // renders per frame: 2 in stereo
  uint64_t pixels_per_pass = 0;  // what each render computed: the image, or the window of it
  int time_passes = 0;           // --time: the last render's whole passes
  bool time_limited = false;     // --time stopped some render before all its samples
};

// What each frame's files hold beyond the picture: the part of the image rendered, and for EXR
// outputs the layers beside the colour and the metadata.
struct FrameContent {
  PixelWindow window;             // empty: the whole image
  std::vector<std::string> aovs;  // EXR layers: albedo, normal, depth, variance
  std::string denoiser;           // denoise each frame with this (an EXR keeps the raw one as "raw"); empty: no
  bool exr_float = false;         // full floats, not half
  RenderIdentity identity;        // the EXR metadata (cli/frames/render_metadata.h)
  // The path tracer: the sums of an earlier render to go on from (--resume), and whether the
  // EXR keeps this render's (so that it can be continued in turn).
  std::optional<SampleState> resume;
  bool keep_sums = false;
  std::shared_ptr<const ViewTransform> view;  // PNG and GIF frames through it (--view-transform); null: the tone curve
};

// `sinks`: one output, or two (left, right) for stereo mode "pair". An exit code if it must stop
// (Ctrl-C, a frame that cannot be written); the film holds the last render.
std::optional<int> render_frames(const RenderJob& job, const LoadedScene& loaded, const RenderSettings& settings,
                                 const StereoSettings& stereo, const FrameList& frames, const FrameContent& content,
                                 std::vector<FrameSink>& sinks, Film& film, RenderTotals& totals);

}  // namespace rt
