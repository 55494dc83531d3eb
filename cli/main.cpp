// rtcli: command-line parsing and dispatch only; each subcommand lives in its own file.
#include <cstdio>
#include <exception>
#include <new>

#include <CLI/CLI.hpp>

#include "cli/bench/bench_command.h"
#include "cli/common/exit_codes.h"
#include "cli/common/number_checks.h"
#include "cli/common/suggestions.h"
#include "cli/common/validate_command.h"
#include "cli/farm/farm_command.h"
#include "cli/frames/encode_command.h"
#include "cli/frames/merge_command.h"
#include "cli/render/render_command.h"
#include "cli/render/render_options.h"
#include "cli/watch/watch_command.h"
#include "core/accel/isa.h"
#include "core/denoise/denoiser.h"
#include "core/render/integrator.h"
#include "core/render/pixel_sampler.h"
#include "core/render_settings.h"
#include "core/stereo.h"
#include "io/image/gif_file.h"

int main(int argc, char** argv) {
  using namespace rt;
  CLI::App app{"rtcli - a data-driven ray tracer: JSON scenes and glTF models in; PNG, JPEG, EXR and GIF out."};
  app.set_version_flag("--version", std::string("rtcli ") + RTCLI_VERSION);
  app.require_subcommand(1);

  RenderCommand render;
  CLI::App* render_cmd = app.add_subcommand(
      "render", "Render a scene (.json) or a glTF model (.gltf/.glb) to a PNG image or an animation");
  add_render_options(*render_cmd, render);

  WatchCommand watch;
  CLI::App* watch_cmd = app.add_subcommand(
      "watch", "Show a scene rendering in the browser, refining; every saved change to it or its files shows at once");
  watch_cmd->add_option("scene", watch.render.scene, "Scene file (.json) or glTF model (.gltf/.glb)")->required();
  watch_cmd->add_option("--port", watch.port, "Port of the page (0: any free one; default 8765)")
      ->check(whole_number(0, 65535));
  watch_cmd->add_option("--bind", watch.bind,
                        "Address to serve on (default 127.0.0.1: this machine only; 0.0.0.0 shows it to the network)");
  watch_cmd->add_option("--frame", watch.frame, "Frame of the scene's animation to show first (the page changes it)");
  add_scene_options(*watch_cmd, watch.render);

  ValidateCommand validate;
  CLI::App* validate_cmd = app.add_subcommand(
      "validate", "Check scene files (.json) and glTF models (.gltf/.glb) without rendering: every problem, located");
  validate_cmd->add_option("files", validate.files, "Files to check")->required();
  validate_cmd->add_flag("--allow-outside-files", validate.allow_outside_files, kOutsideFilesHelp);
  validate_cmd->add_flag("--json", validate.json,
                         "Print the problems as a JSON array (file, line, column, pointer, severity, message)");

  BenchCommand bench;
  bench.scene = std::string(RTCLI_SOURCE_DIR) + "/scenes/primitives.json";
  bench.path_scene = std::string(RTCLI_SOURCE_DIR) + "/scenes/cornell_box.json";
  CLI::App* bench_cmd = app.add_subcommand("bench", "Measure BVH build time, ray throughput and render time");
  bench_cmd->add_option("model", bench.model,
                        "Mesh to trace (.glb/.gltf/.json; default: a generated 300k-triangle mesh)");
  bench_cmd->add_option("--scene", bench.scene, "Scene whose render time is measured last ('' to skip)")
      ->capture_default_str();
  bench_cmd
      ->add_option("--path-scene", bench.path_scene,
                   "Scene path traced last, at most 160 pixels a side and 16 samples per pixel ('' to skip)")
      ->capture_default_str();
  bench_cmd->add_option("--repeats", bench.repeats, "Timed runs of each figure, after a warm-up; the median is shown")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  bench_cmd->add_option("--rays", bench.rays,
                        "Replay the ray sets in FILE (from --save-rays) instead of generating them");
  bench_cmd->add_option("--save-rays", bench.save_rays,
                        "Write the ray sets traced to FILE, for another build or tools/embree_compare to replay");
  bench_cmd->add_option("--isa", bench.isa, isa_help());
  bench.tools_dir = std::string(RTCLI_SOURCE_DIR) + "/tools";
  bench_cmd
      ->add_option("--against", bench.against,
                   "Then compare with povray (tools/povray/compare.py on --scene's twin: wall and render time) or "
                   "cycles (tools/cycles/speed.py on --path-scene's: path-traced samples per second); repeatable")
      ->check(CLI::IsMember({"povray", "cycles"}));

  MergeCommand merge;
  CLI::App* merge_cmd = app.add_subcommand(
      "merge", "Put the EXR tiles of a render (render --tile or --crop) together into one PNG or EXR image");
  merge_cmd->add_option("tiles", merge.tiles, "The tiles (.exr), each once")->required();
  merge_cmd->add_option("-o,--output", merge.output, "The image: .png or .exr")->required();
  merge_cmd->add_flag("-q,--quiet", merge.quiet, "Print nothing but errors");
  bool merge_denoise = false;
  std::optional<std::string> merge_denoiser;
  merge_cmd->add_flag("--denoise", merge_denoise,
                      "Denoise the merged image (tiles rendered with --denoise hold the layers it reads); an EXR "
                      "keeps the raw image as layer \"raw\"");
  merge_cmd->add_option("--denoiser", merge_denoiser, "Which denoiser --denoise uses: " + denoisers().help())
      ->check([](const std::string& name) {
        return denoisers().find(name) ? std::string()
                                      : "unknown denoiser \"" + name + "\"; expected one of: " + denoisers().list();
      });

  EncodeCommand encode;
  CLI::App* encode_cmd =
      app.add_subcommand("encode", "Make an animated GIF from rendered frames (.png or .exr), in the order given");
  encode_cmd->add_option("frames", encode.frames, "The frames (.png or .exr), or with --frames one NAME_####.png/.exr")
      ->required();
  encode_cmd->add_option("--frames", encode.frame_list,
                         "The frame numbers (A-B, A-BxS, lists) that fill the one pattern's '#'s, encoded in ascending "
                         "order (rtcli farm's frames, negative numbers included)");
  encode_cmd->add_option("-o,--output", encode.output, "The animation: .gif")->required();
  encode_cmd->add_option("--fps", encode.fps, "Frames per second (default: the first EXR's, else 24)")
      ->check(real_number(kMinGifFps, 1000.0));
  encode_cmd->add_flag("--dither", encode.dither, "Floyd-Steinberg dithering (less banding, some noise)");
  encode_cmd->add_flag("-q,--quiet", encode.quiet, "Print nothing but errors");

  CLI::App* farm_cmd = app.add_subcommand("farm", "Render on a cluster: write and submit Slurm jobs, follow them");
  farm_cmd->require_subcommand(1);
  FarmSlurmCommand farm_slurm;
  CLI::App* slurm_cmd = farm_cmd->add_subcommand(
      "slurm",
      "Write, print and submit (sbatch) a Slurm job array rendering SCENE in N tasks, then the merge or "
      "encode; options not listed here are passed to every task's rtcli render");
  slurm_cmd->add_option("scene", farm_slurm.scene, "Scene file (.json) or glTF model")->required();
  slurm_cmd
      ->add_option("-o,--output", farm_slurm.output,
                   "The result: .png/.exr (tiles), .gif or NAME_####.png/.exr (frames)")
      ->required();
  slurm_cmd
      ->add_option("--tasks", farm_slurm.tasks, "Array tasks: bands of rows for a still, frame chunks for an animation")
      ->required()
      ->check(whole_number(1, 10000));
  slurm_cmd->add_option("--cpus", farm_slurm.cpus, "CPUs per task (--cpus-per-task; rtcli --threads)")
      ->check(whole_number(1, 1024))
      ->capture_default_str();
  slurm_cmd->add_option("--partition", farm_slurm.partition, "Slurm partition");
  slurm_cmd->add_option("--time", farm_slurm.time, "Time limit per task, Slurm's format (e.g. 1:00:00)");
  slurm_cmd->add_option("--farm-dir", farm_slurm.farm_dir,
                        "Folder for the job scripts, tiles or frames, and logs, on the shared file system (default: "
                        "OUT's name + -farm)");
  slurm_cmd->add_flag("--dry-run", farm_slurm.dry_run, "Write and print the scripts; submit nothing");
  slurm_cmd->add_flag("-q,--quiet", farm_slurm.quiet, "Do not print the scripts");
  slurm_cmd->allow_extras();
  FarmStatusCommand farm_status;
  CLI::App* status_cmd =
      farm_cmd->add_subcommand("status", "Show a submitted farm render's jobs, parts done and task times");
  status_cmd->add_option("farm_dir", farm_status.farm_dir, "The farm folder (rtcli farm slurm --farm-dir)")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // A misspelt command or option gets the nearest real one, as a scene file's keys do.
    if (e.get_exit_code() != 0) {
      if (const auto message = unknown_argument_message(app, std::vector<std::string>(argv + 1, argv + argc))) {
        std::fprintf(stderr, "rtcli: error: %s\nRun with --help for more information.\n", message->c_str());
        return kExitBadInput;
      }
    }
    const int code = app.exit(e);  // prints help, version or the parse error
    return code == 0 ? kExitSuccess : kExitBadInput;
  }
  // Loading never throws (bad input is a diagnostic); what escapes is a runtime failure.
  try {
    if (render_cmd->parsed()) return run_render(render);
    if (watch_cmd->parsed()) return run_watch(watch);
    if (validate_cmd->parsed()) return run_validate(validate);
    if (bench_cmd->parsed()) return run_bench(bench);
    if (merge_cmd->parsed()) {
      if (merge_denoise || merge_denoiser)
        merge.denoiser = merge_denoiser.value_or(std::string(denoisers().entries()[0].name));
      return run_merge(merge);
    }
    if (encode_cmd->parsed()) return run_encode(encode);
    if (slurm_cmd->parsed()) {
      farm_slurm.render_options = slurm_cmd->remaining();
      return run_farm_slurm(farm_slurm);
    }
    if (status_cmd->parsed()) return run_farm_status(farm_status);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "rtcli: error: out of memory\n");
    return kExitFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rtcli: error: %s\n", e.what());
    return kExitFailure;
  }
  return kExitBadInput;
}
