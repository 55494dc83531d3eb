#include "cli/render/render_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/common/exit_codes.h"
#include "cli/frames/frame_output.h"
#include "cli/render/frame_renderer.h"
#include "cli/common/interrupt.h"
#include "cli/common/isa_choice.h"
#include "cli/common/number_checks.h"
#include "cli/frames/output_checks.h"
#include "cli/common/progress_bar.h"
#include "cli/render/render_plan.h"
#include "cli/render/render_stats.h"
#include "cli/render/render_summary.h"
#include "cli/common/report.h"
#include "cli/common/scene_loading.h"
#include "cli/common/suggestions.h"
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

std::string default_output(const std::string& scene, bool animation) {
  return std::filesystem::path(scene).stem().string() + (animation ? ".gif" : ".png");
}

// A name the render pipeline must know (an integrator, an anti-aliasing mode), or an error
// listing the names it knows.
bool check_name(const char* option, const char* what, const std::string& name, const std::vector<std::string>& names) {
  if (std::find(names.begin(), names.end(), name) != names.end()) return true;
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  std::fprintf(stderr, "rtcli: error: %s: unknown %s \"%s\"%s; expected one of: %s\n", option, what, name.c_str(),
               did_you_mean(name, names).c_str(), list.c_str());
  return false;
}

// The scene's render settings with the command line's overrides applied.
RenderSettings with_overrides(RenderSettings s, const RenderCommand& cmd) {
  if (cmd.preview) s = preview_settings(s);  // first: an option given beside it still wins
  if (cmd.width) s.width = *cmd.width;
  if (cmd.height) s.height = *cmd.height;
  if (cmd.seed) s.seed = *cmd.seed;
  if (cmd.threads) s.threads = *cmd.threads;
  if (cmd.integrator) s.integrator = *cmd.integrator;
  if (cmd.glossy_samples) s.glossy_samples = *cmd.glossy_samples;
  if (cmd.no_glossy) s.glossy = false;
  if (cmd.no_textures) s.detail.textures = false;
  if (cmd.no_bumps) s.detail.bumps = false;
  if (cmd.texture_filter) {
    const std::vector<std::string> names = texture_filter_names();
    s.detail.override_filter = true;
    s.detail.filter =
        static_cast<TextureFilter>(std::find(names.begin(), names.end(), *cmd.texture_filter) - names.begin());
  }
  if (cmd.shadow_samples) s.shadow_samples = *cmd.shadow_samples;
  if (cmd.secondary_shadows) s.scale_secondary_shadows = *cmd.secondary_shadows == "scaled";
  if (cmd.exposure) s.display.exposure = *cmd.exposure;
  if (cmd.tone_map) s.display.curve = *cmd.tone_map == "filmic" ? ToneMap::kFilmic : ToneMap::kClamp;
  if (cmd.spp) s.path.samples_per_pixel = *cmd.spp;
  if (cmd.noise_threshold) s.path.noise_threshold = *cmd.noise_threshold;
  if (cmd.clamp) s.path.clamp = *cmd.clamp;
  if (cmd.aa_mode) s.antialias.mode = *cmd.aa_mode;
  if (cmd.aa_samples) s.antialias.samples = *cmd.aa_samples;
  if (cmd.aa_threshold) s.antialias.threshold = *cmd.aa_threshold;
  if (cmd.aa_depth) s.antialias.max_depth = *cmd.aa_depth;
  if (cmd.aa_positions)
    s.antialias.positions = *cmd.aa_positions == "centres" ? SamplePositions::kCentres : SamplePositions::kCorners;
  // A debug view's values are data (a normal, a depth): shown as they are, never tone mapped.
  if (!integrator_shows_radiance(s.integrator)) s.display = DisplayTransform{};
  return s;
}

// The frames the command asks for; without --frame or --frames, the scene's first frame.
std::optional<FrameList> requested_frames(const RenderCommand& cmd) {
  if (!cmd.frames) return FrameList::range(0, 0);
  std::string error;
  const auto list = parse_frame_list(*cmd.frames, error);
  if (!list)
    std::fprintf(stderr,
                 "rtcli: error: --frames: %s; expected a frame N, a range A-B, every S-th frame A-BxS, or a list "
                 "of those (1,5,9-12), whole numbers within +-%d\n",
                 error.c_str(), kMaxFrameNumber);
  return list;
}

// What the command line asks for, checked before anything is loaded.
struct RenderRequest {
  FrameList frames;  // as asked; without --frame or --frames, the scene's first frame (known once loaded)
  bool frames_given = false;
  std::string output;
  OutputKind kind = OutputKind::kPng;
};

// What a render writes, every name checked once the scene's own files are known.
struct RenderOutputs {
  std::vector<std::string> paths;  // each frame's file (or the one PNG or GIF), then --aa-debug's two
  std::string aa_refined, aa_depth;
  std::string samples_map;  // --samples-debug's
};

std::optional<RenderRequest> check_arguments(const RenderCommand& cmd) {
  if (cmd.integrator && !check_name("--integrator", "integrator", *cmd.integrator, integrator_names()))
    return std::nullopt;
  if (cmd.aa_mode && !check_name("--aa", "anti-aliasing mode", *cmd.aa_mode, pixel_sampler_names()))
    return std::nullopt;
  if (cmd.texture_filter &&
      !check_name("--texture-filter", "texture filter", *cmd.texture_filter, texture_filter_names()))
    return std::nullopt;
  if (cmd.secondary_shadows &&
      !check_name("--secondary-shadows", "secondary shadow rule", *cmd.secondary_shadows, secondary_shadow_names()))
    return std::nullopt;
  if (cmd.tone_map && !check_name("--tone-map", "tone curve", *cmd.tone_map, tone_map_names())) return std::nullopt;
  if ((cmd.fps || cmd.animation) && !is_gltf_path(cmd.scene)) {
    std::fprintf(stderr, "rtcli: error: %s applies to a glTF file rendered on its own; a scene file sets %s\n",
                 cmd.fps ? "--fps" : "--animation",
                 cmd.fps ? "\"animation\": {\"fps\": ...}" : "\"animation\" on its glTF reference (\"mesh\")");
    return std::nullopt;
  }
  const std::optional<FrameList> asked = requested_frames(cmd);
  if (!asked) return std::nullopt;
  RenderRequest r{*asked, cmd.frames.has_value(), "", OutputKind::kPng};
  r.output = cmd.output.empty() ? default_output(cmd.scene, asked->count() > 1) : cmd.output;
  std::string error;
  const std::optional<OutputKind> kind = output_kind(r.output, error);
  if (!kind || !check_output(r.output, error)) {
    std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
    return std::nullopt;
  }
  r.kind = *kind;
  if (asked->count() > 1 && is_single_image(r.kind)) {
    std::fprintf(stderr,
                 "rtcli: error: %d frames need an animated GIF (-o NAME.gif) or numbered files (-o NAME_####.png or "
                 "NAME_####.exr), found \"%s\"\n",
                 asked->count(), r.output.c_str());
    return std::nullopt;
  }
  if (cmd.aa_debug && cmd.stereo && *cmd.stereo != "none") {
    std::fprintf(stderr, "rtcli: error: --aa-debug shows one image's refinement; it does not go with --stereo\n");
    return std::nullopt;
  }
  if (cmd.samples_debug && ((cmd.stereo && *cmd.stereo != "none") || r.kind != OutputKind::kPng)) {
    std::fprintf(stderr, "rtcli: error: --samples-debug writes one image beside one PNG (no --stereo, no \"%s\")\n",
                 r.output.c_str());
    return std::nullopt;
  }
  if (cmd.aa_debug && r.kind != OutputKind::kPng) {
    std::fprintf(stderr, "rtcli: error: --aa-debug writes images beside one PNG; it does not go with \"%s\"\n",
                 r.output.c_str());
    return std::nullopt;
  }
  return r;
}

// Without --frame or --frames: an animated GIF or a PNG sequence shows the scene's whole
// animation (its timeline), a PNG the timeline's first frame.
FrameList frames_to_render(const RenderRequest& request, const LoadedScene& loaded) {
  if (request.frames_given) return request.frames;
  const Timeline& t = loaded.graph.timeline;
  if (!is_single_image(request.kind) && loaded.graph.animated) return FrameList::range(t.first_frame, t.last_frame);
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
std::vector<std::string> output_patterns(const RenderRequest& request, const StereoSettings& stereo) {
  if (stereo.mode != StereoMode::kPair) return {request.output};
  return {eye_path(request.output, "left"), eye_path(request.output, "right")};
}

std::optional<RenderOutputs> check_outputs(const RenderCommand& cmd, const RenderRequest& request,
                                           const FrameList& frames, const StereoSettings& stereo,
                                           const std::vector<std::string>& inputs) {
  RenderOutputs out;
  for (const std::string& pattern : output_patterns(request, stereo)) {
    if (is_sequence(request.kind))
      for (const int f : frames.frames) out.paths.push_back(sequence_path(pattern, f));
    else out.paths.push_back(pattern);
  }
  if (!cmd.stats.empty()) out.paths.push_back(cmd.stats);
  if (cmd.aa_debug) {
    out.aa_refined = beside(request.output, ".aa-refined");
    out.aa_depth = beside(request.output, ".aa-depth");
    out.paths.push_back(out.aa_refined);
    out.paths.push_back(out.aa_depth);
  }
  if (cmd.samples_debug) {
    out.samples_map = beside(request.output, ".samples");
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
                    const SceneGraph& graph, OutputKind kind) {
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
         (write(outputs.aa_refined, refined_pixels_in_red(film)) && write(outputs.aa_depth, refinement_heat_map(film)));
}

// The camera's stereo settings, --stereo's mode replacing the scene's; nothing (after saying why)
// for a camera that cannot see in stereo.
std::optional<StereoSettings> stereo_settings(const RenderCommand& cmd, const Camera& camera) {
  StereoSettings s = camera.stereo;
  if (cmd.stereo) {
    const auto& names = kStereoModeNames;
    s.mode = static_cast<StereoMode>(std::find(names.begin(), names.end(), *cmd.stereo) - names.begin());
  }
  if (s.enabled() && camera.projection == CameraProjection::kOrthographic) {
    std::fprintf(stderr,
                 "rtcli: error: --stereo needs a perspective, fisheye or equirectangular camera; %s's is orthographic "
                 "(parallel rays see no depth)\n",
                 cmd.scene.c_str());
    return std::nullopt;
  }
  if (s.enabled() && cmd.aa_debug) {
    std::fprintf(stderr,
                 "rtcli: error: --aa-debug shows one image's refinement; it does not go with a stereo camera\n");
    return std::nullopt;
  }
  return s;
}

}  // namespace

int run_render(const RenderCommand& cmd) {
  // Check the arguments.
  const std::optional<RenderRequest> request = check_arguments(cmd);
  if (!request) return kExitBadInput;

  // Load: the first frame asked for is the one built with the scene.
  const auto load_start = std::chrono::steady_clock::now();
  const std::optional<Isa> isa = choose_isa(cmd.isa, "rtcli");
  if (!isa) return kExitBadInput;
  LoadOptions options = cli_load_options(cmd.threads.value_or(0), cmd.camera, cmd.allow_outside_files, *isa);
  if (request->frames_given) options.frame = request->frames.first();
  options.animation = cmd.animation;
  options.fps = cmd.fps;
  options.integrator = cmd.integrator;
  if (cmd.background) options.background = parse_color(*cmd.background);
  if (cmd.ambient) options.ambient = parse_color(*cmd.ambient);
  Diagnostics diags;
  const std::optional<LoadedScene> loaded = load_scene(cmd.scene, options, diags);
  print_diagnostics(stderr, diags);
  if (!loaded) return kExitBadInput;
  const FrameList frames = frames_to_render(*request, *loaded);
  const std::optional<StereoSettings> stereo = stereo_settings(cmd, loaded->scene.camera);
  if (!stereo) return kExitBadInput;
  const std::optional<RenderOutputs> outputs = check_outputs(cmd, *request, frames, *stereo, loaded->inputs);
  if (!outputs) return kExitBadInput;
  const double load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();
  const RenderSettings settings = with_overrides(loaded->settings, cmd);
  if (!check_settings(cmd, settings, frames, loaded->graph, request->kind)) return kExitBadInput;
  const std::optional<RenderPlan> plan =
      plan_render(cmd, request->kind, output_patterns(*request, *stereo), frames, settings, *stereo, *loaded);
  if (!plan) return kExitBadInput;
  if (!plan->skipped.empty() && !cmd.quiet) std::fprintf(stderr, "rtcli: %s\n", plan->skipped.c_str());
  if (plan->frames.frames.empty()) return kExitSuccess;

  // Render the frames.
  std::vector<FrameSink> sinks;
  for (const std::string& pattern : output_patterns(*request, *stereo))
    sinks.emplace_back(request->kind, pattern, stereo_image_width(stereo->mode, settings.width),
                       stereo_image_height(stereo->mode, settings.height), loaded->graph.timeline.fps, plan->frames.count(),
                       cmd.dither, resolve_thread_count(settings.threads));
  RenderTotals totals;
  Film film;
  if (const std::optional<int> stop =
          render_frames(cmd, *loaded, settings, *stereo, plan->frames, plan->content, sinks, film, totals))
    return *stop;

  // Write and summarise.
  const int most_samples = integrator_samples_pixels(settings.integrator)
                               ? settings.path.samples_per_pixel
                               : static_cast<int>(std::min<uint64_t>(max_camera_rays_per_frame(settings) /
                                                                         std::max<uint64_t>(1, pixel_count(settings)),
                                                                     65535));
  if (!finish_outputs(*outputs, sinks, film, totals.last.threads, most_samples)) return kExitFailure;
  std::vector<std::string> written;
  for (const FrameSink& sink : sinks) written.insert(written.end(), sink.written().begin(), sink.written().end());
  if (!cmd.stats.empty()) {
    std::string error;
    const SignalBlock block;
    if (!write_render_stats(
            cmd.stats, RenderStatsInput{cmd.scene, written, settings, *stereo, plan->frames, totals, load_seconds, loaded->scene.bvh.isa()}, error)) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return kExitFailure;
    }
  }
  if (!cmd.quiet) {
    print_summary(cmd, settings, plan->frames, totals, load_seconds, written, loaded->scene.bvh.isa());
    if (!cmd.stats.empty()) std::printf("wrote %s (the render's figures)\n", cmd.stats.c_str());
    if (cmd.samples_debug)
      std::printf("wrote %s (samples per pixel: black 0, blue, green, orange, white %d)\n",
                  outputs->samples_map.c_str(), most_samples);
    if (cmd.aa_debug) {
      std::printf("wrote %s (the image, refined pixels in red)\n", outputs->aa_refined.c_str());
      std::printf("wrote %s (refinement depth: black 0, blue 1, green 2, orange 3, white 4)\n",
                  outputs->aa_depth.c_str());
    }
  }
  return kExitSuccess;
}

}  // namespace rt
