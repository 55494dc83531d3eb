#include "cli/bench/bench_command.h"

#include <cstdio>
#include <filesystem>

#include "cli/bench/bench_model.h"
#include "cli/bench/ray_benchmark.h"
#include "cli/bench/render_benchmark.h"
#include "cli/common/child_process.h"
#include "cli/common/exit_codes.h"
#include "cli/common/isa_choice.h"
#include "cli/common/progress_bar.h"
#include "cli/common/report.h"
#include "cli/common/scene_loading.h"
#include "core/thread_count.h"
#include "io/scene_loader.h"

namespace rt {
namespace {

// "12.345 [12.001-12.500]": a median with its range.
std::string with_range(double median, double lo, double hi, const char* format) {
  char text[96];
  const std::string f = std::string(format) + " [" + format + "-" + format + "]";
  std::snprintf(text, sizeof text, f.c_str(), median, lo, hi);
  return text;
}

void print_ray_table(const std::vector<RayBenchmarkResult>& results, const std::vector<double>& cold) {
  std::printf("\n%-28s", "");
  for (const auto& r : results)
    std::printf("  %-30s", (std::to_string(r.threads) + (r.threads == 1 ? " thread" : " threads")).c_str());
  if (results.size() > 1) std::printf("scaling");
  std::printf("\n%-28s", "BVH build, cold (ms)");
  for (const double c : cold) {
    char text[32] = "n/a (no child process)";
    if (c >= 0) std::snprintf(text, sizeof text, "%.1f", 1e3 * c);
    std::printf("  %-30s", text);
  }
  if (results.size() > 1 && cold.front() > 0 && cold.back() > 0) std::printf("%.2fx", cold.front() / cold.back());
  std::printf("\n%-28s", "BVH build, warm (ms)");
  for (const auto& r : results)
    std::printf("  %-30s", with_range(1e3 * r.build.median, 1e3 * r.build.min, 1e3 * r.build.max, "%.1f").c_str());
  if (results.size() > 1) std::printf("%.2fx", results.front().build.median / results.back().build.median);
  std::printf("\n");
  for (size_t s = 0; s < results.front().sets.size(); ++s) {
    const SetThroughput& first = results.front().sets[s];
    std::printf("%-28s", (first.name + " (Mray/s)").c_str());
    for (const auto& r : results) {
      const SetThroughput& t = r.sets[s];
      std::printf("  %-30s", with_range(t.mrays(), t.mrays_slowest(), t.mrays_fastest(), "%.2f").c_str());
    }
    if (results.size() > 1) std::printf("%.2fx", results.back().sets[s].mrays() / first.mrays());
    std::printf("\n");
  }
}

// The render time of a scene on each thread count; `path`: path traced, small (at most 160
// pixels a side, 16 samples per pixel), with samples per second. False if it did not load.
bool bench_render(const std::string& path, bool path_traced, Isa isa, const std::vector<unsigned>& thread_counts,
                  int repeats) {
  Diagnostics diags;
  const auto scene = load_scene(path, cli_load_options(0, std::nullopt, false, isa), diags);
  if (!scene) {
    print_diagnostics(stderr, diags);
    std::fprintf(stderr, "rtcli bench: skipped the scene render: %s did not load\n", path.c_str());
    return false;
  }
  RenderSettings settings = scene->settings;
  if (path_traced) {
    settings.integrator = "path";
    const int side = std::max(settings.width, settings.height);
    if (side > 160) {
      settings.width = std::max(1, settings.width * 160 / side);
      settings.height = std::max(1, settings.height * 160 / side);
    }
    settings.path.samples_per_pixel = 16;
    settings.path.noise_threshold = 0.0f;
  }
  std::printf("\n%s %s (%dx%d%s), s:", path_traced ? "path trace" : "render",
              std::filesystem::path(path).filename().c_str(), settings.width, settings.height,
              path_traced ? ", 16 spp" : "");
  std::vector<RenderBenchmark> renders;
  for (const unsigned t : thread_counts) {
    renders.push_back(time_render(scene->scene, settings, t, repeats));
    const RenderBenchmark& r = renders.back();
    std::printf("  %u thread%s %s (%.2f Mrays/s", t, t == 1 ? "" : "s",
                with_range(r.seconds.median, r.seconds.min, r.seconds.max, "%.3f").c_str(),
                static_cast<double>(r.rays.total()) / r.seconds.median / 1e6);
    if (path_traced)
      std::printf(", %.3f Msamples/s", static_cast<double>(r.rays[RayKind::kCamera]) / r.seconds.median / 1e6);
    std::printf(")");
  }
  if (renders.size() > 1) std::printf("  (%.2fx)", renders.front().seconds.median / renders.back().seconds.median);
  std::printf("\nrays: %s\n", format_ray_counts(renders.front().rays).c_str());
  return true;
}

// The script behind a comparison --against names.
std::string comparison_script(const std::string& against, const BenchCommand& cmd) {
  return cmd.tools_dir + (against == "povray" ? "/povray/compare.py" : "/cycles/speed.py");
}

// Whether a comparison --against names can run: its scene given, its script there. Checked
// before anything slow; false with the reason printed.
bool comparison_ready(const std::string& against, const BenchCommand& cmd) {
  const bool pov = against == "povray";
  const std::string& scene = pov ? cmd.scene : cmd.path_scene;
  const std::string script = comparison_script(against, cmd);
  if (scene.empty()) {
    std::fprintf(stderr, "rtcli bench: error: --against %s compares %s, which is '' (skipped)\n", against.c_str(),
                 pov ? "--scene" : "--path-scene");
    return false;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(script, ec)) {
    std::fprintf(stderr, "rtcli bench: error: --against %s runs %s from rtcli's source tree, which is not there\n",
                 against.c_str(), script.c_str());
    return false;
  }
  return true;
}

// One of the comparisons --against names, run as a user would run it by hand (the command is
// printed first, to rerun), with this rtcli and the bench's threads and repeats (at most 3: each
// run renders a full-size image with both renderers). False when it failed.
bool run_comparison(const std::string& against, const BenchCommand& cmd, unsigned threads) {
  const bool pov = against == "povray";
  std::error_code ec;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
  const std::vector<std::string> args{"python3",
                                      comparison_script(against, cmd),
                                      "--threads",
                                      std::to_string(threads),
                                      "--runs",
                                      std::to_string(std::min(cmd.repeats, 3)),
                                      "--rtcli",
                                      self.empty() ? "rtcli" : self,
                                      "--",  // a scene path that starts with '-' is still a path
                                      pov ? cmd.scene : cmd.path_scene};
  std::printf("\nagainst %s:", pov ? "POV-Ray" : "Cycles");
  for (const std::string& a : args) std::printf(" %s", a.c_str());
  std::printf("\n");
  std::fflush(stdout);
  std::string error;
  const int status = run_program_attached(args, error);
  if (status == 0) return true;
  if (status < 0) std::fprintf(stderr, "rtcli bench: error: %s\n", error.c_str());
  else std::fprintf(stderr, "rtcli bench: error: the comparison with %s failed (exit %d)\n", against.c_str(), status);
  return false;
}

}  // namespace

int run_bench(const BenchCommand& cmd) {
  const std::optional<Isa> isa = choose_isa(cmd.isa, "rtcli bench");
  if (!isa) return kExitBadInput;
  for (const std::string& against : cmd.against)
    if (!comparison_ready(against, cmd)) return kExitBadInput;
  // A ray file is read first: a bad one is reported before anything slow.
  std::vector<RaySet> sets;
  std::string error;
  if (!cmd.rays.empty() && !read_ray_sets(cmd.rays, sets, error)) {
    std::fprintf(stderr, "rtcli bench: error: %s\n", error.c_str());
    return kExitBadInput;
  }
  Diagnostics model_diags;
  const auto model = load_bench_model(cmd.model, model_diags);
  print_diagnostics(stderr, model_diags);
  if (!model) return kExitBadInput;
  const PrimitiveSet& prims = model->prims;
  const unsigned all = resolve_thread_count(0);
  std::vector<unsigned> thread_counts{1};
  if (all > 1) thread_counts.push_back(all);
  // Cold builds first, each in a fresh process: nothing built here yet has warmed the memory.
  std::vector<double> cold;
  for (const unsigned t : thread_counts) cold.push_back(cold_build_seconds(prims, t, *isa));

  if (cmd.rays.empty()) sets = make_ray_sets(prims);
  if (!cmd.save_rays.empty() && !write_ray_sets(cmd.save_rays, sets, error)) {
    std::fprintf(stderr, "rtcli bench: error: %s\n", error.c_str());
    return kExitFailure;
  }
  std::printf("model: %s, %zu triangles, %zu analytic shapes; %u usable CPUs; BVH kernels: %s (of %s)\n",
              model->name.c_str(), prims.triangles.size(), prims.shapes.size(), all, isa_name(*isa),
              supported_isa_names().c_str());
  std::printf("rays: %s:", cmd.rays.empty() ? "generated" : cmd.rays.c_str());
  for (const RaySet& s : sets) std::printf(" %s %zu%s", s.name.c_str(), s.rays.size(), s.occlusion ? " (any hit)" : "");
  std::printf("\neach figure: the median of %d runs after a warm-up [slowest-fastest]\n", cmd.repeats);
  std::fflush(stdout);

  std::vector<RayBenchmarkResult> results;
  for (const unsigned t : thread_counts) results.push_back(run_ray_benchmark(prims, sets, t, cmd.repeats, *isa));
  print_ray_table(results, cold);
  const RayBenchmarkResult& r0 = results.front();
  std::printf("BVH: %zu nodes, SAH cost %.1f; hit fractions:", r0.bvh_nodes, r0.sah_cost);
  for (const SetThroughput& t : r0.sets)
    std::printf(" %s %.2f", t.name.c_str(), t.rays ? static_cast<double>(t.hits) / static_cast<double>(t.rays) : 0.0);
  std::printf("\n");

  if (!cmd.scene.empty() && !bench_render(cmd.scene, false, *isa, thread_counts, cmd.repeats)) return kExitBadInput;
  if (!cmd.path_scene.empty() && !bench_render(cmd.path_scene, true, *isa, thread_counts, cmd.repeats))
    return kExitBadInput;
  for (const std::string& against : cmd.against)
    if (!run_comparison(against, cmd, all)) return kExitFailure;
  return kExitSuccess;
}

}  // namespace rt
