#include "cli/render/render_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/common/exit_codes.h"
#include "cli/common/interrupt.h"
#include "cli/common/isa_choice.h"
#include "cli/common/number_checks.h"
#include "cli/common/progress_bar.h"
#include "cli/common/report.h"
#include "cli/common/scene_loading.h"
#include "cli/common/suggestions.h"
#include "cli/frames/frame_output.h"
#include "cli/frames/output_checks.h"
#include "cli/render/frame_renderer.h"
#include "cli/render/render_job.h"
#include "cli/render/render_plan.h"
#include "cli/render/render_stats.h"
#include "cli/render/render_summary.h"
#include "cli/render/settings_overrides.h"
#include "core/render/integrator.h"
#include "core/render/pixel_sampler.h"
#include "core/render/refinement_images.h"
#include "core/render/renderer.h"
#include "core/render/stereo_images.h"
#include "core/thread_count.h"
#include "io/image/gif_file.h"
#include "io/image/png_file.h"
#include "io/scene_loader.h"

namespace rt {
namespace {

// What a render writes, every name checked once the scene's own files are known.
struct RenderOutputs {
  std::vector<std::string> paths;  // each frame's file (or the one PNG or GIF), then --aa-debug's two
  std::string aa_refined, aa_depth;
  std::string samples_map;  // --samples-debug's
};

// Without --frame or --frames: an animated GIF or a PNG sequence shows the scene's whole
// animation (its timeline), a PNG the timeline's first frame.
FrameList frames_to_render(const RenderJob& job, const LoadedScene& loaded) {
  if (job.frames_given) return job.frames;
  const Timeline& t = loaded.graph.timeline;
  if (!is_single_image(job.kind) && loaded.graph.animated) {
    // A looping GIF whose last frame shows the first again (Blender's 0-120 turntable) ends one
    // frame before it: the loop's start is shown once.
    if (job.kind == OutputKind::kGif && loaded.graph.ends_where_it_starts())
      return FrameList::range(t.first_frame, t.last_frame - 1);
    return FrameList::range(t.first_frame, t.last_frame);
  }
  return FrameList::range(loaded.frame, loaded.frame);
}

// "view.png" -> "view-left.png", "out/f_####.png" -> "out/f_####-left.png": stereo mode pair's files.
std::string eye_path(const std::string& output, const char* eye) {
  std::filesystem::path p(output);
  const std::string ext = p.extension().string();
  p.replace_extension();
  return p.string() + "-" + eye + ext;
}

// The outputs' patterns: the one asked for, or its two eyes' for stereo mode pair.
std::vector<std::string> output_patterns(const RenderJob& job, const StereoSettings& stereo) {
  if (stereo.mode != StereoMode::kPair) return {job.output};
  return {eye_path(job.output, "left"), eye_path(job.output, "right")};
}

std::optional<RenderOutputs> check_outputs(const RenderJob& job, const FrameList& frames, const StereoSettings& stereo,
                                           const std::vector<std::string>& inputs) {
  RenderOutputs out;
  for (const std::string& pattern : output_patterns(job, stereo)) {
    if (is_sequence(job.kind))
      for (const int f : frames.frames) out.paths.push_back(sequence_path(pattern, f));
    else out.paths.push_back(pattern);
  }
  if (!job.stats.empty()) out.paths.push_back(job.stats);
  if (job.aa_debug) {
    out.aa_refined = beside(job.output, ".aa-refined");
    out.aa_depth = beside(job.output, ".aa-depth");
    out.paths.push_back(out.aa_refined);
    out.paths.push_back(out.aa_depth);
  }
  if (job.samples_debug) {
    out.samples_map = beside(job.output, ".samples");
    out.paths.push_back(out.samples_map);
  }
  std::string error;
  for (const std::string& path : out.paths) {
    if (!check_new_output(path, inputs, error)) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return std::nullopt;
    }
  }
  return out;
}

// The size limit on what the command line asks for, and a word about renders that will be slow
// or show one picture many times.
bool check_settings(const RenderCommand& cmd, const RenderSettings& settings, const FrameList& frames,
                    const SceneGraph& graph, OutputKind kind) {  // the overrides are the command's own
  if (kind == OutputKind::kGif && !(graph.timeline.fps >= kMinGifFps)) {
    std::fprintf(stderr,
                 "rtcli: error: %s: %g frames per second: a GIF frame lasts at most 655.35 s, so a GIF takes at least "
                 "%g fps (numbered frames, -o NAME_####.png, take any rate)\n",
                 cmd.scene.c_str(), static_cast<double>(graph.timeline.fps), kMinGifFps);
    return false;
  }
  if (cmd.width || cmd.height || cmd.aa_mode || cmd.aa_samples || cmd.aa_depth || cmd.aa_positions) {
    if (pixel_count(settings) > kMaxPixels) {
      std::fprintf(stderr,
                   "rtcli: error: %dx%d is %llu pixels, more than the %llu rtcli renders "
                   "(docs/errors-and-limits.md, \"Limits\")\n",
                   settings.width, settings.height, static_cast<unsigned long long>(pixel_count(settings)),
                   static_cast<unsigned long long>(kMaxPixels));
      return false;
    }
    if (max_camera_rays_per_frame(settings) > kCameraRaysWarning)
      std::fprintf(stderr,
                   "rtcli: warning: this render can trace up to %llu camera rays; expect it to take a long time\n",
                   static_cast<unsigned long long>(max_camera_rays_per_frame(settings)));
  }
  if (cmd.time && !integrator_samples_pixels(settings.integrator)) {
    std::fprintf(stderr,
                 "rtcli: error: --time stops the path tracer between passes of samples; %s renders each pixel "
                 "once (use --integrator path, or --preview for a quick draft)\n",
                 settings.integrator.c_str());
    return false;
  }
  // Whitted's ambient stands in for indirect light, which the path tracer computes: a scene made for
  // Whitted keeps its direct light (one light unit), and loses the flat term.
  if (settings.integrator == "path" && max_component(graph.ambient) > 0.0f)
    std::fprintf(stderr,
                 "rtcli: warning: %s: \"ambient\" is Whitted's stand-in for indirect light; the path tracer "
                 "computes that light instead and ignores it (docs/rendering.md, \"Lights and units\")\n",
                 cmd.scene.c_str());
  const Timeline& t = graph.timeline;
  if (frames.count() > 1 && !graph.animated)
    std::fprintf(stderr, "rtcli: warning: %s has no animation: all %d frames will show the same picture\n",
                 cmd.scene.c_str(), frames.count());
  else if (graph.animated && (frames.first() < t.first_frame || frames.last() > t.last_frame))
    std::fprintf(stderr, "rtcli: warning: --frames %s goes beyond the scene's animation, frames %d-%d (at %g fps)\n",
                 frames.text().c_str(), t.first_frame, t.last_frame, static_cast<double>(t.fps));
  return true;
}

// Finishes the output (the GIF is written at the end) and --aa-debug's images.
bool finish_outputs(const RenderOutputs& outputs, std::vector<FrameSink>& sinks, const Film& film, unsigned threads,
                    int most_samples) {
  const SignalBlock block;
  std::string error;
  const auto write = [&](const std::string& path, const Image& image) {
    if (write_png(path, encode_srgb8(image), error, threads)) return true;
    std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
    return false;
  };
  for (FrameSink& sink : sinks) {
    if (!sink.finish(error)) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return false;
    }
  }
  if (!outputs.samples_map.empty() && !write(outputs.samples_map, sample_count_heat_map(film, most_samples)))
    return false;
  return outputs.aa_refined.empty() ||
         (write(outputs.aa_refined, refined_pixels_marked(film)) && write(outputs.aa_depth, refinement_heat_map(film)));
}

// The camera's stereo settings, --stereo's mode replacing the scene's; nothing (after saying why)
// for a camera that cannot see in stereo.
std::optional<StereoSettings> stereo_settings(const RenderJob& job, const Camera& camera) {
  StereoSettings s = camera.stereo;
  if (job.choices.stereo) s.mode = *job.choices.stereo;
  if (s.enabled() && camera.projection == CameraProjection::kOrthographic) {
    std::fprintf(stderr,
                 "rtcli: error: --stereo needs a perspective, fisheye or equirectangular camera; %s's is orthographic "
                 "(parallel rays see no depth)\n",
                 job.scene.c_str());
    return std::nullopt;
  }
  if (s.enabled() && job.aa_debug) {
    std::fprintf(stderr,
                 "rtcli: error: --aa-debug shows one image's refinement; it does not go with a stereo camera\n");
    return std::nullopt;
  }
  return s;
}

}  // namespace

int run_render(const RenderCommand& cmd) {
  // Check the arguments: from here on the job says what is asked, beside the settings' overrides.
  const std::optional<RenderJob> job = make_render_job(cmd, process_environment());
  if (!job) return kExitBadInput;

  // Load: the first frame asked for is the one built with the scene.
  const auto load_start = std::chrono::steady_clock::now();
  const std::optional<Isa> isa = choose_isa(cmd.isa, "rtcli");
  if (!isa) return kExitBadInput;
  std::optional<LoadOptions> asked = scene_load_options(cmd, *isa);
  if (!asked) return kExitBadInput;
  LoadOptions& options = *asked;
  if (job->frames_given) options.frame = job->frames.first();
  Diagnostics diags;
  const std::optional<LoadedScene> loaded = load_scene(job->scene, options, diags);
  print_diagnostics(stderr, diags);
  if (!loaded) return kExitBadInput;
  const FrameList frames = frames_to_render(*job, *loaded);
  const std::optional<StereoSettings> stereo = stereo_settings(*job, loaded->scene.camera);
  if (!stereo) return kExitBadInput;
  const std::optional<RenderOutputs> outputs = check_outputs(*job, frames, *stereo, loaded->inputs);
  if (!outputs) return kExitBadInput;
  const double load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();
  const RenderSettings settings = with_overrides(loaded->settings, cmd);
  if (!check_settings(cmd, settings, frames, loaded->graph, job->kind)) return kExitBadInput;
  const std::optional<RenderPlan> plan =
      plan_render(*job, output_patterns(*job, *stereo), frames, settings, *stereo, *loaded);
  if (!plan) return kExitBadInput;
  if (!plan->skipped.empty() && !job->quiet) std::fprintf(stderr, "rtcli: %s\n", plan->skipped.c_str());
  if (plan->frames.frames.empty()) return kExitSuccess;

  // Render the frames.
  std::vector<FrameSink> sinks;
  for (const std::string& pattern : output_patterns(*job, *stereo))
    sinks.emplace_back(job->kind, pattern, stereo_image_width(stereo->mode, settings.width),
                       stereo_image_height(stereo->mode, settings.height), loaded->graph.timeline.fps,
                       plan->frames.count(), job->dither, resolve_thread_count(settings.threads));
  RenderTotals totals;
  Film film;
  if (const std::optional<int> stop =
          render_frames(*job, *loaded, settings, *stereo, plan->frames, plan->content, sinks, film, totals))
    return *stop;

  // Write and summarise.
  const int most_samples =
      integrator_samples_pixels(settings.integrator)
          ? settings.path.samples_per_pixel
          : static_cast<int>(std::min<uint64_t>(
                max_camera_rays_per_frame(settings) / std::max<uint64_t>(1, pixel_count(settings)), 65535));
  if (!finish_outputs(*outputs, sinks, film, totals.last.threads, most_samples)) return kExitFailure;
  std::vector<std::string> written;
  for (const FrameSink& sink : sinks) written.insert(written.end(), sink.written().begin(), sink.written().end());
  if (!job->stats.empty()) {
    std::string error;
    const SignalBlock block;
    if (!write_render_stats(job->stats,
                            RenderStatsInput{job->scene, written, settings, *stereo, plan->frames, totals, load_seconds,
                                             loaded->scene.bvh.isa(), job->time_limit},
                            error)) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return kExitFailure;
    }
  }
  if (!job->quiet) {
    print_summary(*job, settings, plan->frames, totals, load_seconds, written, loaded->scene.bvh.isa());
    if (!job->stats.empty()) std::printf("wrote %s (the render's figures)\n", job->stats.c_str());
    if (job->samples_debug)
      std::printf("wrote %s (samples per pixel: black 0, blue, green, orange, white %d)\n",
                  outputs->samples_map.c_str(), most_samples);
    if (job->aa_debug) {
      std::printf("wrote %s (the image, refined pixels in green)\n", outputs->aa_refined.c_str());
      std::printf("wrote %s (refinement depth: black 0, blue 1, green 2, orange 3, white 4)\n",
                  outputs->aa_depth.c_str());
    }
  }
  return kExitSuccess;
}

}  // namespace rt
