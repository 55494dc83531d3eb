#include "cli/render/frame_renderer.h"

#include <unistd.h>

#include <cstdio>
#include <string>

#include "cli/common/exit_codes.h"
#include "cli/common/interrupt.h"
#include "cli/common/progress_bar.h"
#include "cli/render/aov_layers.h"
#include "cli/render/sample_state.h"
#include "core/denoise/denoiser.h"
#include "core/frame_scenes.h"
#include "core/render/integrator.h"
#include "core/render/stereo_images.h"
#include "core/thread_count.h"

namespace rt {

std::optional<int> render_frames(const RenderJob& job, const LoadedScene& loaded, const RenderSettings& settings,
                                 const StereoSettings& stereo, const FrameList& frames, const FrameContent& content,
                                 std::vector<FrameSink>& sinks, Film& film, RenderTotals& totals) {
  const ProgressStyle style = job.progress != ProgressStyle::kAuto       ? job.progress
                              : !job.quiet && ::isatty(::fileno(stderr)) ? ProgressStyle::kBar
                                                                         : ProgressStyle::kNone;
  ProgressBar bar(stderr, style);
  const bool show_progress = style != ProgressStyle::kNone;
  FrameScenes scenes(loaded.graph, loaded.frame, loaded.scene,
                     BvhBuildOptions{resolve_thread_count(settings.threads), loaded.scene.bvh.isa()});
  totals.passes = stereo.enabled() ? 2 : 1;
  const int all_passes = frames.count() * totals.passes;
  std::string error;
  Image left;
  const std::unique_ptr<Denoiser> denoiser = content.denoiser.empty() ? nullptr : make_denoiser(content.denoiser);
  if (denoiser && !integrator_samples_pixels(settings.integrator))
    std::fprintf(stderr,
                 "rtcli: warning: --denoise weighs each pixel's noise by its variance, which only the path tracer "
                 "estimates; under %s the image is left as rendered\n",
                 settings.integrator.c_str());
  // An 8-bit picture (PNG, JPEG, GIF) that is all the render writes from the film: the film keeps
  // the display codes (RenderView::display8), not 33 MB of linear colour at 1920 x 1440.
  const bool codes_only = !is_exr(sinks[0].kind()) && !stereo.enabled() && !denoiser && !content.view &&
                          content.aovs.empty() && !content.keep_sums && !job.aa_debug && !job.samples_debug;
  for (int index = 0; index < frames.count(); ++index) {
    const int frame = frames.frames[static_cast<size_t>(index)];
    const Scene& scene = scenes.at(frame);
    totals.place_seconds = scenes.placing_seconds();
    Camera camera = scene.camera;
    camera.stereo = stereo;
    const Camera eyes[2] = {camera.eye_camera(-1), camera.eye_camera(1)};
    for (int pass = 0; pass < totals.passes; ++pass) {
      const InterruptWatch interrupt;
      RenderControl control;
      const int done = index * totals.passes + pass;
      if (show_progress) {
        std::string label =
            frames.count() > 1 ? "frame " + std::to_string(index + 1) + "/" + std::to_string(frames.count()) : "";
        if (totals.passes == 2) label += std::string(label.empty() ? "" : " ") + (pass == 0 ? "left eye" : "right eye");
        bar.set_label(label);
        control.progress = [&, done](const RenderProgress& p) {
          RenderProgress all = p;  // the bar counts passes: done passes, plus this one's share
          all.pixels_done += static_cast<uint64_t>(done) * p.pixels_total;
          all.pixels_total *= static_cast<uint64_t>(all_passes);
          all.seconds += totals.seconds + totals.place_seconds;
          bar.update(all);
        };
      }
      control.cancel = &interrupt.flag();
      control.time_limit = job.time_limit;
      // EXR layers come from the same pass as the colour (no stereo with EXR: checked before).
      RenderView view = stereo.enabled()
                            ? RenderView{&eyes[pass], static_cast<uint32_t>(pass), {}, false}
                            : RenderView{nullptr, 0, content.window, !content.aovs.empty() || denoiser != nullptr};
      if (content.resume) view.resume_from = &*content.resume;
      view.pixel_counts = job.aa_debug || job.samples_debug;
      view.keep_sums = content.keep_sums;
      if (codes_only) view.display8 = &settings.display;
      totals.last = render(scene, settings, film, control, static_cast<uint32_t>(frame), view);
      bar.clear();
      if (totals.last.cancelled) {
        const double seconds = totals.seconds + totals.last.seconds;
        bool written = false;
        for (const FrameSink& sink : sinks) written = written || !sink.written().empty();
        if (frames.count() == 1) std::fprintf(stderr, "rtcli: interrupted after %.2f s; nothing written\n", seconds);
        else
          std::fprintf(stderr, "rtcli: interrupted in frame %d after %.2f s; %s\n", frame, seconds,
                       written ? "the frames before it were written" : "nothing written");
        return 128 + interrupt.signal();  // the shell's convention: 130 for Ctrl-C
      }
      totals.seconds += totals.last.seconds;
      totals.rays += totals.last.rays;
      totals.pixels_per_pass = static_cast<uint64_t>(film.width()) * static_cast<uint64_t>(film.height());
      totals.refined += totals.last.pixels.refined;
      totals.samples += totals.last.pixels.samples;
      if (content.resume)
        for (const SampleSums& p : *content.resume) totals.resumed_samples += static_cast<uint64_t>(p.n);
      totals.time_passes = totals.last.passes;
      totals.time_limited = totals.time_limited || totals.last.time_limited;
      if (pass == 0 && totals.passes == 2) left = film.color;
    }

    // The denoised image, shown in the raw one's place (no stereo: checked before).
    const Image shown =
        denoiser ? denoiser->denoise(denoise_input(film), resolve_thread_count(settings.threads)) : Image{};
    const Image& picture = denoiser ? shown : film.color;
    if (is_exr(sinks[0].kind())) {  // linear, with its layers and metadata (no stereo: checked before)
      ExrImage exr;
      exr.width = settings.width;
      exr.height = settings.height;
      exr.window = film.window();
      exr.layers.push_back(color_layer(picture, ""));
      if (denoiser) exr.layers.push_back(color_layer(film.color, "raw"));
      for (const std::string& aov : content.aovs)
        exr.layers.push_back(aov_layer(film, *find_aov(aov)));  // checked by render_plan
      if (!film.sums.empty())
        for (ExrLayer& l : sample_state_layers(film.sums, film.has_aovs())) exr.layers.push_back(std::move(l));
      exr.attributes = render_attributes(content.identity, frame, exr.window);
      const SignalBlock block;
      if (!sinks[0].add_exr(exr, frame, content.exr_float, error)) {
        std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
        return kExitFailure;
      }
      continue;
    }
    const SignalBlock block;  // each temporary file is always renamed or removed
    bool ok = true;
    const DisplayTransform& display = settings.display;
    const ViewTransform* display_view = content.view.get();
    if (codes_only) {
      ok = sinks[0].add(Rgb8Image{film.width(), film.height(), std::move(film.display8)}, frame, error);
    } else if (!stereo.enabled()) {
      ok = sinks[0].add(picture, display, display_view, frame, error);
    } else if (stereo.mode == StereoMode::kPair) {
      ok = sinks[0].add(left, display, display_view, frame, error) &&
           sinks[1].add(film.color, display, display_view, frame, error);
    } else {
      ok = sinks[0].add(compose_stereo(left, film.color, stereo), display, display_view, frame, error);
    }
    if (!ok) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return kExitFailure;
    }
  }
  return std::nullopt;
}

}  // namespace rt
