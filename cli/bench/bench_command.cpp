#include "cli/bench/bench_command.h"

#include <cstdio>
#include <filesystem>

#include "cli/bench/generated_mesh.h"
#include "cli/bench/ray_benchmark.h"
#include "cli/bench/render_benchmark.h"
#include "cli/exit_codes.h"
#include "cli/progress_bar.h"
#include "cli/report.h"
#include "cli/scene_loading.h"
#include "core/thread_count.h"
#include "io/scene_loader.h"

namespace rt {
namespace {

constexpr size_t kGeneratedTriangles = 300'000;

}  // namespace

int run_bench(const BenchCommand& cmd) {
  PrimitiveSet prims;
  std::string what;
  if (cmd.model.empty()) {
    prims = make_primitive_set({make_benchmark_mesh(kGeneratedTriangles)}, {});
    what = "generated displaced sphere";
  } else {
    Diagnostics diags;
    const auto loaded = load_scene(cmd.model, cli_load_options(), diags);
    print_diagnostics(stderr, diags);
    if (!loaded) return kExitBadInput;
    prims = make_primitive_set(loaded->scene.world_meshes(), loaded->scene.bvh.shapes());
    what = cmd.model;
  }
  const unsigned all = resolve_thread_count(0);
  std::printf("model: %s, %zu triangles, %zu analytic shapes; %u hardware threads\n", what.c_str(),
              prims.triangles.size(), prims.shapes.size(), all);
  std::fflush(stdout);

  std::vector<unsigned> thread_counts{1};
  if (all > 1) thread_counts.push_back(all);
  std::vector<RayBenchmarkResult> results;
  for (const unsigned t : thread_counts) results.push_back(run_ray_benchmark(prims, t));

  std::printf("\n%-34s", "");
  for (const auto& r : results) std::printf("%10u thread%s", r.threads, r.threads == 1 ? " " : "s");
  if (results.size() > 1) std::printf("   scaling");
  std::printf("\n");
  const auto row = [&](const char* label, double RayBenchmarkResult::*field, const char* unit, bool higher_is_better) {
    std::printf("%-34s", label);
    for (const auto& r : results) std::printf("%10.3f %-7s", r.*field, unit);
    if (results.size() > 1) {
      const double a = results.front().*field, b = results.back().*field;
      std::printf("%8.2fx", higher_is_better ? b / a : a / b);
    }
    std::printf("\n");
  };
  row("BVH build", &RayBenchmarkResult::build_seconds, "s", false);
  row("primary rays (1920x1080)", &RayBenchmarkResult::primary_mrays, "Mray/s", true);
  row("incoherent rays (2M)", &RayBenchmarkResult::incoherent_mrays, "Mray/s", true);
  row("shadow rays (any hit)", &RayBenchmarkResult::shadow_mrays, "Mray/s", true);
  const RayBenchmarkResult& r0 = results.front();
  std::printf("BVH: %zu nodes, SAH cost %.1f; hit fractions: primary %.2f, incoherent %.2f, shadow occluded %.2f\n",
              r0.bvh_nodes, r0.sah_cost, r0.primary_hit_fraction, r0.incoherent_hit_fraction,
              r0.shadow_occluded_fraction);

  if (cmd.scene.empty()) return kExitSuccess;
  Diagnostics diags;
  const auto scene = load_scene(cmd.scene, cli_load_options(), diags);
  if (!scene) {
    print_diagnostics(stderr, diags);
    std::fprintf(stderr, "rtcli bench: skipped the scene render: %s did not load\n", cmd.scene.c_str());
    return kExitBadInput;
  }
  std::printf("\nrender %s (%dx%d):", std::filesystem::path(cmd.scene).filename().c_str(), scene->settings.width,
              scene->settings.height);
  std::vector<RenderStats> renders;
  for (const unsigned t : thread_counts) {
    renders.push_back(best_render(scene->scene, scene->settings, t));
    const RenderStats& r = renders.back();
    std::printf("  %u thread%s %.3f s (%.2f Mrays/s)", t, t == 1 ? "" : "s", r.seconds,
                static_cast<double>(r.rays.total()) / r.seconds / 1e6);
  }
  if (renders.size() > 1) std::printf("  (%.2fx)", renders.front().seconds / renders.back().seconds);
  std::printf("\nrays: %s\n", format_ray_counts(renders.front().rays).c_str());
  return kExitSuccess;
}

}  // namespace rt
