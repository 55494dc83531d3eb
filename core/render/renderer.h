// The render entry point: reads a Scene and settings, writes one Film (or just its Image).
// Tiles are handed to worker threads from a shared counter. A pixel's value depends only on
// the scene, the settings and the keys of its samples, so the image is the same for any thread
// count, tile size and tile order.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "core/image.h"
#include "core/pixel_window.h"
#include "core/render/film.h"
#include "core/render/ray_counters.h"
#include "core/render/sample_sums.h"
#include "core/render_settings.h"
#include "core/scene.h"
#include "core/thread_count.h"

namespace rt {

struct RenderProgress {
  uint64_t pixels_done = 0;
  uint64_t pixels_total = 0;
  uint64_t rays = 0;  // traced so far, all kinds
  double seconds = 0.0;
};

struct RenderStats {
  double seconds = 0.0;
  RayCounters rays;
  unsigned threads = 1;
  bool cancelled = false;     // stopped by RenderControl::cancel: the image is incomplete
  int passes = 0;             // progressive (RenderControl::time_limit): the whole passes rendered
  bool time_limited = false;  // the time limit stopped it before every pixel had all its samples
  PixelTotals pixels;         // over the film's pixels as rendered (with or without Film::samples)
};

// Samples a pixel takes per pass of a progressive render (a camera-ray packet's worth).
inline constexpr int kPassSamples = 8;

using ProgressCallback = std::function<void(const RenderProgress&)>;

struct RenderControl {
  // Called from the calling thread about ten times a second and once at the end.
  ProgressCallback progress;
  // When it becomes true, every worker stops before its next pixel (Ctrl-C in the CLI).
  const std::atomic<bool>* cancel = nullptr;
  // Seconds the render may take (0: no limit; render --time). A sampler that adds samples in
  // passes (the path tracer's) then renders whole passes until the next would end past it; the
  // film holds the best image so far. Other samplers ignore it.
  double time_limit = 0.0;
  // Called on the calling thread after each whole pass of such a sampler, with the film so far and
  // the samples a pixel has had by then (a pixel the noise threshold stopped has fewer): a live
  // preview's refinement (rtcli watch). Its presence makes a render run in passes, as a time limit
  // does; without one, until every pixel has all its samples. Other samplers never call it.
  std::function<void(const Film&, int samples)> pass_done;
};

// Whose eyes look: a camera other than the scene's (one eye of a stereo pair), and the eye's key
// (0: the left eye or a mono render, 1: the right eye); which pixels of the image are rendered
// (empty: all of them); and whether the film gathers the first hit's layers too (aovs.h: albedo,
// normal, distance, in the same pass as the colour).
struct RenderView {
  const Camera* camera = nullptr;
  uint32_t eye = 0;
  PixelWindow window;
  bool aovs = false;
  // The path tracer: go on from an earlier render's sums of the same window (render --resume),
  // and/or keep the sums in Film::sums for a later one. A render of the same scene and
  // settings with more samples then gives the bits one render of them all gives.
  const SampleState* resume_from = nullptr;
  bool keep_sums = false;
  // Whether the film keeps each pixel's sample count and refinement depth (Film::samples, depth):
  // the debug images and the watch page read them. Their totals are in RenderStats either way.
  bool pixel_counts = true;
  // When set, the film keeps the colour only as the 8-bit codes this display transform gives
  // (Film::display8), not as linear RGB: for a picture that is only written as a PNG. Not with
  // aovs, keep_sums or RenderControl::pass_done (which show or keep the linear colour).
  const DisplayTransform* display8 = nullptr;
};

// Renders frame `frame` into `film` (resized to the view's window of the settings.width x
// settings.height image, or all of it), with the pixel sampler's channels. Each pixel is what a
// render of the whole image gives it. Throws std::invalid_argument for an unknown integrator or
// anti-aliasing mode name.
RenderStats render(const Scene& scene, const RenderSettings& settings, Film& film, const RenderControl& control = {},
                   uint32_t frame = 0, const RenderView& view = {});
// The same, keeping only the colour.
RenderStats render(const Scene& scene, const RenderSettings& settings, Image& image, const RenderControl& control = {},
                   uint32_t frame = 0, const RenderView& view = {});

}  // namespace rt
