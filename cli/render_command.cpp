#include "cli/render_command.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/exit_codes.h"
#include "cli/interrupt.h"
#include "cli/progress_bar.h"
#include "cli/report.h"
#include "cli/scene_loading.h"
#include "core/render/integrator.h"
#include "core/render/renderer.h"
#include "io/png_file.h"
#include "io/scene_loader.h"

namespace rt {
namespace {

std::string default_output(const std::string& scene) { return std::filesystem::path(scene).stem().string() + ".png"; }

// Refuses an output we could never write before spending minutes on the render.
bool check_output(const std::string& path, std::string& error) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".png") {
    error = "expected an output file name ending in .png, found \"" + path + "\"";
    return false;
  }
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

}  // namespace

int run_render(const RenderCommand& cmd) {
  const std::string output = cmd.output.empty() ? default_output(cmd.scene) : cmd.output;
  std::string error;
  if (cmd.integrator && !make_integrator(*cmd.integrator)) {
    std::string names;
    for (const std::string& n : integrator_names()) names += (names.empty() ? "" : ", ") + n;
    std::fprintf(stderr, "rtcli: error: --integrator: unknown integrator \"%s\"; expected one of: %s\n",
                 cmd.integrator->c_str(), names.c_str());
    return kExitBadInput;
  }
  if (!check_output(output, error)) {
    std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
    return kExitBadInput;
  }

  const auto load_start = std::chrono::steady_clock::now();
  Diagnostics diags;
  std::optional<LoadedScene> loaded = load_scene(cmd.scene, cli_load_options(cmd.threads.value_or(0)), diags);
  print_diagnostics(stderr, diags);
  if (!loaded) return kExitBadInput;
  if (output_is_an_input(output, loaded->inputs, error)) {
    std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
    return kExitBadInput;
  }
  const double load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();

  RenderSettings settings = loaded->description.render;
  if (cmd.width) settings.width = *cmd.width;
  if (cmd.height) settings.height = *cmd.height;
  if (cmd.seed) settings.seed = *cmd.seed;
  if (cmd.threads) settings.threads = *cmd.threads;
  if (cmd.integrator) settings.integrator = *cmd.integrator;
  if (cmd.glossy_samples) settings.glossy_samples = *cmd.glossy_samples;
  if (cmd.no_glossy) settings.glossy = false;
  if (cmd.shadow_samples) settings.shadow_samples = *cmd.shadow_samples;
  if (cmd.width || cmd.height) {
    if (pixel_count(settings) > kMaxPixels) {
      std::fprintf(stderr,
                   "rtcli: error: %dx%d is %llu pixels, more than the %llu rtcli renders (README, \"Limits\")\n",
                   settings.width, settings.height, static_cast<unsigned long long>(pixel_count(settings)),
                   static_cast<unsigned long long>(kMaxPixels));
      return kExitBadInput;
    }
    if (camera_rays_per_frame(settings) > kCameraRaysWarning)
      std::fprintf(stderr, "rtcli: warning: this render traces %llu camera rays; expect it to take a long time\n",
                   static_cast<unsigned long long>(camera_rays_per_frame(settings)));
  }

  ProgressBar bar(stderr);
  const bool show_progress = !cmd.quiet && ::isatty(::fileno(stderr));
  Image image;
  RenderStats stats;
  {
    const InterruptWatch interrupt;
    RenderControl control;
    if (show_progress) control.progress = [&](const RenderProgress& p) { bar.update(p); };
    control.cancel = &interrupt.flag();
    stats = render(loaded->scene, settings, image, control);
    bar.clear();
    if (stats.cancelled) {
      std::fprintf(stderr, "rtcli: interrupted after %.2f s; nothing written\n", stats.seconds);
      return 128 + interrupt.signal();  // the shell's convention: 130 for Ctrl-C
    }
  }

  {
    const SignalBlock block;  // the temporary file is always renamed or removed
    if (!write_png(output, encode_srgb8(image), error, stats.threads)) {
      std::fprintf(stderr, "rtcli: error: %s\n", error.c_str());
      return kExitFailure;
    }
  }
  if (!cmd.quiet) {
    const double rate = stats.seconds > 0 ? static_cast<double>(stats.rays.total()) / stats.seconds : 0.0;
    std::fprintf(stderr, "rendered %s: %dx%d in %.2f s (load %.2f s), %srays (%s), %.2f Mrays/s, %u thread%s\n",
                 cmd.scene.c_str(), settings.width, settings.height, stats.seconds, load_seconds,
                 format_count(static_cast<double>(stats.rays.total())).c_str(), format_ray_counts(stats.rays).c_str(),
                 rate / 1e6, stats.threads, stats.threads == 1 ? "" : "s");
    std::printf("wrote %s\n", output.c_str());
  }
  return kExitSuccess;
}

}  // namespace rt
