#include "cli/render_command.h"

#include <unistd.h>
#include <climits>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/exit_codes.h"
#include "cli/frame_output.h"
#include "cli/interrupt.h"
#include "cli/progress_bar.h"
#include "cli/report.h"
#include "cli/scene_loading.h"
#include "core/render/integrator.h"
#include "core/render/pixel_sampler.h"
#include "core/render/refinement_images.h"
#include "core/render/renderer.h"
#include "core/thread_count.h"
#include "io/image/png_file.h"
#include "io/scene_loader.h"

namespace rt {
namespace {

std::string default_output(const std::string& scene, bool animation) {
  return std::filesystem::path(scene).stem().string() + (animation ? ".gif" : ".png");
}

// Refuses an output we could never write before spending minutes on the render: a missing or
// read-only folder, a folder in its place, a name too long for the file system.
bool check_output(const std::string& path, std::string& error) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    error = "cannot write \"" + path + "\": the folder \"" + folder.string() + "\" does not exist";
    return false;
  }
  if (::access(folder.c_str(), W_OK) != 0) {
    error = "cannot write \"" + path + "\": the folder \"" + folder.string() + "\" is not writable";
    return false;
  }
  if (fs::is_directory(p, ec)) {
    error = "cannot write \"" + path + "\": it is a folder";
    return false;
  }
  const long name_max = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  const std::string name = p.filename().string();
  if (name_max > 0 && name.size() > static_cast<size_t>(name_max)) {
    error = "cannot write \"" + path + "\": its name is " + std::to_string(name.size()) + " bytes, more than the " +
            std::to_string(name_max) + " the file system allows";
    return false;
  }
  if (path.size() >= PATH_MAX) {
    error = "cannot write \"" + path.substr(0, 60) + "...\": its path is " + std::to_string(path.size()) +
            " bytes, more than the " + std::to_string(PATH_MAX - 1) + " the system allows";
    return false;
  }
  return true;
}

// The image must not replace a file the scene was read from (the same file, links resolved).
bool output_is_an_input(const std::string& output, const std::vector<std::string>& inputs, std::string& error) {
  std::error_code ec;
  if (!std::filesystem::exists(output, ec)) return false;
  for (const std::string& input : inputs) {
    if (std::filesystem::equivalent(output, input, ec)) {
      error = "refusing to write the image to \"" + output + "\": it is the input file \"" + input +
              "\" (choose another name with -o)";
      return true;
    }
  }
  return false;
}

// A name the render pipeline must know (an integrator, an anti-aliasing mode), or an error
// listing the names it knows.
bool check_name(const char* option, const char* what, const std::string& name, const std::vector<std::string>& names) {
  if (std::find(names.begin(), names.end(), name) != names.end()) return true;
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  std::fprintf(stderr, "rtcli: error: %s: unknown %s \"%s\"; expected one of: %s\n", option, what, name.c_str(),
               list.c_str());
  return false;
}

// "out.png" -> "out.aa-refined.png" for --aa-debug's images.
std::string beside(const std::string& output, const std::string& suffix) {
  std::filesystem::path p(output);
  p.replace_extension(suffix + ".png");
  return p.string();
}

// The scene's render settings with the command line's overrides applied.
RenderSettings with_overrides(RenderSettings s, const RenderCommand& cmd) {
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
  if (cmd.aa_mode) s.antialias.mode = *cmd.aa_mode;
  if (cmd.aa_samples) s.antialias.samples = *cmd.aa_samples;
  if (cmd.aa_threshold) s.antialias.threshold = *cmd.aa_threshold;
  if (cmd.aa_depth) s.antialias.max_depth = *cmd.aa_depth;
  if (cmd.aa_positions)
    s.antialias.positions = *cmd.aa_positions == "centres" ? SamplePositions::kCentres : SamplePositions::kCorners;
  return s;
}

// The frames the command asks for; without --frame or --frames, the scene's first frame.
std::optional<FrameRange> requested_frames(const RenderCommand& cmd) {
  if (!cmd.frames) return FrameRange{};
  const auto range = parse_frame_range(*cmd.frames);
  if (!range)
    std::fprintf(stderr,
                 "rtcli: error: --frames: expected a frame N or a range A-B with A <= B (whole numbers within "
                 "+-1000000), found \"%s\"\n",
                 cmd.frames->c_str());
  return range;
}

struct RenderTotals {
  RenderStats last;  // the last frame's
  RayCounters rays;
  double seconds = 0.0;        // rendering, all frames
  double place_seconds = 0.0;  // placing animated frames (top-level BVH builds)
  size_t refined = 0;          // pixels refined by adaptive anti-aliasing, all frames
};

void print_summary(const RenderCommand& cmd, const RenderSettings& settings, const FrameRange& frames,
                   const RenderTotals& t, double load_seconds, const std::vector<std::string>& written) {
  const double rate = t.seconds > 0 ? static_cast<double>(t.rays.total()) / t.seconds : 0.0;
  const unsigned threads = t.last.threads;
  if (frames.count() == 1) {
    std::fprintf(stderr, "rendered %s: %dx%d in %.2f s (load %.2f s), %srays (%s), %.2f Mrays/s, %u thread%s\n",
                 cmd.scene.c_str(), settings.width, settings.height, t.seconds, load_seconds,
                 format_count(static_cast<double>(t.rays.total())).c_str(), format_ray_counts(t.rays).c_str(),
                 rate / 1e6, threads, threads == 1 ? "" : "s");
  } else {
    std::fprintf(stderr,
                 "rendered %s: frames %d-%d (%d), %dx%d, %.2f s per frame (placing %.1f ms), %.2f s in all "
                 "(load %.2f s), %srays, %.2f Mrays/s, %u thread%s\n",
                 cmd.scene.c_str(), frames.first, frames.last, frames.count(), settings.width, settings.height,
                 t.seconds / frames.count(), 1e3 * t.place_seconds / frames.count(), t.seconds + t.place_seconds,
                 load_seconds, format_count(static_cast<double>(t.rays.total())).c_str(), rate / 1e6, threads,
                 threads == 1 ? "" : "s");
  }
  const double pixels = static_cast<double>(pixel_count(settings)) * frames.count();
  std::fprintf(stderr, "  %.2f rays per pixel (%.2f camera rays), %.1f%% of pixels refined (anti-aliasing %s)\n",
               static_cast<double>(t.rays.total()) / pixels, static_cast<double>(t.rays[RayKind::kCamera]) / pixels,
               100.0 * static_cast<double>(t.refined) / pixels, settings.antialias.mode.c_str());
  if (written.size() <= 3) {
    for (const std::string& w : written) std::printf("wrote %s\n", w.c_str());
  } else {
    std::printf("wrote %s ... %s (%zu files)\n", written.front().c_str(), written.back().c_str(), written.size());
  }
}

}  // namespace

int run_render(const RenderCommand& cmd) {
  std::string error;
  if (cmd.integrator && !check_name("--integrator", "integrator", *cmd.integrator, integrator_names()))
    return kExitBadInput;
  if (cmd.aa_mode && !check_name("--aa", "anti-aliasing mode", *cmd.aa_mode, pixel_sampler_names()))
    return kExitBadInput;
  if (cmd.texture_filter &&
      !check_name("--texture-filter", "texture filter", *cmd.texture_filter, texture_filter_names()))
    return kExitBadInput;
  const std::optional<FrameRange> asked = requested_frames(cmd);
  if (!asked) return kExitBadInput;
  const std::string output = cmd.output.empty() ? default_output(cmd.scene, asked->count() > 1) : cmd.output;
  const std::optional<OutputKind> kind = output_kind(output, error);
  if (!kind || !check_output(output, error)) {
    std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
    return kExitBadInput;
  }
  if (asked->count() > 1 && *kind == OutputKind::kPng) {
    std::fprintf(stderr,
                 "rtcli: error: %d frames need an animated GIF (-o NAME.gif) or numbered PNGs (-o NAME_####.png), "
                 "found \"%s\"\n",
                 asked->count(), output.c_str());
    return kExitBadInput;
  }
  if (cmd.aa_debug && *kind != OutputKind::kPng) {
    std::fprintf(stderr, "rtcli: error: --aa-debug writes images beside one PNG; it does not go with \"%s\"\n",
                 output.c_str());
    return kExitBadInput;
  }

  const auto load_start = std::chrono::steady_clock::now();
  Diagnostics diags;
  std::optional<LoadedScene> loaded =
      load_scene(cmd.scene, cli_load_options(cmd.threads.value_or(0), cmd.camera, cmd.allow_outside_files), diags);
  print_diagnostics(stderr, diags);
  if (!loaded) return kExitBadInput;
  const Timeline& timeline = loaded->graph.timeline;
  const FrameRange frames = cmd.frames ? *asked : FrameRange{timeline.first_frame, timeline.first_frame};
  std::vector<std::string> outputs;
  if (*kind == OutputKind::kPngSequence)
    for (int f = frames.first; f <= frames.last; ++f) outputs.push_back(sequence_path(output, f));
  else outputs.push_back(output);
  if (cmd.aa_debug) {
    outputs.push_back(beside(output, ".aa-refined"));
    outputs.push_back(beside(output, ".aa-depth"));
  }
  for (const std::string& out : outputs) {
    if (!check_output(out, error) || output_is_an_input(out, loaded->inputs, error)) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return kExitBadInput;
    }
  }
  const double load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();

  const RenderSettings settings = with_overrides(loaded->description.render, cmd);
  if (cmd.width || cmd.height || cmd.aa_mode || cmd.aa_samples || cmd.aa_depth || cmd.aa_positions) {
    if (pixel_count(settings) > kMaxPixels) {
      std::fprintf(stderr,
                   "rtcli: error: %dx%d is %llu pixels, more than the %llu rtcli renders (docs/errors-and-limits.md, \"Limits\")\n",
                   settings.width, settings.height, static_cast<unsigned long long>(pixel_count(settings)),
                   static_cast<unsigned long long>(kMaxPixels));
      return kExitBadInput;
    }
    if (max_camera_rays_per_frame(settings) > kCameraRaysWarning)
      std::fprintf(stderr,
                   "rtcli: warning: this render can trace up to %llu camera rays; expect it to take a long time\n",
                   static_cast<unsigned long long>(max_camera_rays_per_frame(settings)));
  }
  if (frames.count() > 1 && !loaded->graph.animated)
    std::fprintf(stderr, "rtcli: warning: %s has no animation: all %d frames will show the same picture\n",
                 cmd.scene.c_str(), frames.count());

  ProgressBar bar(stderr);
  const bool show_progress = !cmd.quiet && ::isatty(::fileno(stderr));
  const BvhBuildOptions bvh_options{resolve_thread_count(settings.threads)};
  FrameSink sink(*kind, output, settings.width, settings.height, timeline.fps, frames.count(), cmd.dither,
                 resolve_thread_count(settings.threads));
  RenderTotals totals;
  Film film;
  for (int frame = frames.first; frame <= frames.last; ++frame) {
    const int index = frame - frames.first;
    // The loaded scene is the first frame of the timeline; any other frame is placed anew (its
    // top-level BVH only: meshes and their BVHs are shared).
    std::optional<Scene> placed;
    if (frame != timeline.first_frame) {
      const auto start = std::chrono::steady_clock::now();
      placed = loaded->graph.at(timeline.seconds(frame), bvh_options);
      totals.place_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    const Scene& scene = placed ? *placed : loaded->scene;
    const InterruptWatch interrupt;
    RenderControl control;
    if (show_progress) {
      if (frames.count() > 1)
        bar.set_label("frame " + std::to_string(index + 1) + "/" + std::to_string(frames.count()));
      control.progress = [&](const RenderProgress& p) {
        RenderProgress all = p;  // the bar counts frames: done frames, plus this one's share
        all.pixels_done += static_cast<uint64_t>(index) * p.pixels_total;
        all.pixels_total *= static_cast<uint64_t>(frames.count());
        all.seconds += totals.seconds + totals.place_seconds;
        bar.update(all);
      };
    }
    control.cancel = &interrupt.flag();
    totals.last = render(scene, settings, film, control, static_cast<uint32_t>(frame));
    bar.clear();
    if (totals.last.cancelled) {
      const double seconds = totals.seconds + totals.last.seconds;
      if (frames.count() == 1) std::fprintf(stderr, "rtcli: interrupted after %.2f s; nothing written\n", seconds);
      else
        std::fprintf(stderr, "rtcli: interrupted in frame %d after %.2f s; %s\n", frame, seconds,
                     sink.written().empty() ? "nothing written" : "the frames before it were written");
      return 128 + interrupt.signal();  // the shell's convention: 130 for Ctrl-C
    }
    totals.seconds += totals.last.seconds;
    for (size_t k = 0; k < kRayKindCount; ++k) totals.rays.count[k] += totals.last.rays.count[k];
    for (const uint8_t d : film.depth) totals.refined += d > 0;

    const SignalBlock block;  // each temporary file is always renamed or removed
    if (!sink.add(encode_srgb8(film.color), frame, error)) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return kExitFailure;
    }
  }
  {
    const SignalBlock block;
    const auto write = [&](const std::string& path, const Image& image) {
      if (write_png(path, encode_srgb8(image), error, totals.last.threads)) return true;
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return false;
    };
    if (!sink.finish(error)) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return kExitFailure;
    }
    if (cmd.aa_debug &&
        (!write(outputs[1], refined_pixels_in_red(film)) || !write(outputs[2], refinement_heat_map(film))))
      return kExitFailure;
  }
  if (!cmd.quiet) {
    print_summary(cmd, settings, frames, totals, load_seconds, sink.written());
    if (cmd.aa_debug) {
      std::printf("wrote %s (the image, refined pixels in red)\n", outputs[1].c_str());
      std::printf("wrote %s (refinement depth: black 0, blue 1, green 2, orange 3, white 4)\n", outputs[2].c_str());
    }
  }
  return kExitSuccess;
}

}  // namespace rt
