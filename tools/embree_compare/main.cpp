// embree_compare [MODEL] [--rays FILE] [--repeats N]: rtcli's BVH and Embree 3 on exactly the
// same triangles and the same rays (cli/bench/ray_sets.h, or a file from `rtcli bench
// --save-rays`), timed alternately in one process on 1 thread and on all, each figure the median
// of N runs after a warm-up (cold builds: of N fresh processes each); prints rays per second and rtcli / Embree ratios,
// and checks that the two find the same hits. A ratio above 1 means rtcli is faster (rays per second over Embree's; for
// builds, Embree's time over rtcli's). Built only where Embree is installed (tools/CMakeLists.txt).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "cli/bench/bench_model.h"
#include "cli/bench/ray_benchmark.h"
#include "core/accel/bvh.h"
#include "core/thread_count.h"
#include "tools/embree_compare/embree_scene.h"

namespace {

using namespace rt;

// Times a() and b() in turn, `repeats` times each after one warm-up of each.
template <class A, class B>
std::pair<Timing, Timing> alternate(int repeats, const A& a, const B& b) {
  using Clock = std::chrono::steady_clock;
  a();
  b();
  std::vector<double> ta, tb;
  for (int i = 0; i < repeats; ++i) {
    auto start = Clock::now();
    a();
    ta.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    start = Clock::now();
    b();
    tb.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  return {summarise(ta), summarise(tb)};
}

double mrays(size_t n, const Timing& t) { return static_cast<double>(n) / t.median / 1e6; }

void row(const char* what, double rtcli, double embree, const char* unit, bool higher_is_better) {
  std::printf("  %-34s %10.2f %10.2f %-7s %6.2fx\n", what, rtcli, embree, unit,
              higher_is_better ? rtcli / embree : embree / rtcli);
}

// Rays on which the two disagree: one hits and the other does not, or the distances differ by
// more than 1e-4 relative (a grazed edge may go either way: a handful in millions is expected).
size_t disagreements(const RaySet& set, const Bvh& bvh, const EmbreeScene& embree, unsigned threads) {
  return trace_all(set.rays, threads, [&](const Ray& ray) {
    if (set.occlusion) return bvh.occluded(ray) != embree.occluded(ray);
    Ray r = ray;
    Hit hit;
    const float a = bvh.intersect(r, hit) ? hit.t : kInfinity, b = embree.intersect(ray);
    if (std::isinf(a) || std::isinf(b)) return std::isinf(a) != std::isinf(b);
    return std::fabs(a - b) > 1e-4f * std::max(1.0f, std::fabs(b));
  });
}

}  // namespace

int main(int argc, char** argv) {
  std::string model, rays_file;
  int repeats = 5;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--rays" && i + 1 < argc) rays_file = argv[++i];
    else if (a == "--repeats" && i + 1 < argc) repeats = std::max(1, std::atoi(argv[++i]));
    else if (!a.empty() && a[0] != '-' && model.empty()) model = a;
    else {
      std::fprintf(stderr, "usage: embree_compare [MODEL] [--rays FILE] [--repeats N]\n");
      return 2;
    }
  }
  std::vector<RaySet> sets;
  std::string error;
  if (!rays_file.empty() && !read_ray_sets(rays_file, sets, error)) {
    std::fprintf(stderr, "embree_compare: error: %s\n", error.c_str());
    return 2;
  }
  Diagnostics diags;
  const auto loaded = load_bench_model(model, diags);
  if (!loaded) {
    std::fprintf(stderr, "embree_compare: error: %s does not load (rtcli validate says why)\n", model.c_str());
    return 2;
  }
  const PrimitiveSet& prims = loaded->prims;
  if (!prims.shapes.empty() || !prims.csgs.empty()) {
    std::fprintf(stderr, "embree_compare: error: Embree is compared on triangles only; %s has %zu analytic shapes\n",
                 loaded->name.c_str(), prims.shapes.size() + prims.csgs.size());
    return 2;
  }
  const unsigned all = resolve_thread_count(0);
  std::vector<unsigned> thread_counts{1};
  if (all > 1) thread_counts.push_back(all);
  // Cold builds first, each in a fresh child process, before Embree's thread pool exists here:
  // `repeats` of each, alternately, and the medians (one build is one sample of a noisy
  // machine's page faults). Embree's device (and its thread pool) is made before the clock starts.
  std::vector<std::pair<double, double>> cold;
  for (const unsigned t : thread_counts) {
    std::vector<double> ours, theirs;
    for (int i = 0; i < repeats; ++i) {
      ours.push_back(cold_build_seconds(prims, t, best_isa()));
      theirs.push_back(run_in_fresh_process([&] {
        const EmbreeDevice device(t);
        const auto start = std::chrono::steady_clock::now();
        const EmbreeScene scene(device, prims.triangles);
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }));
    }
    cold.emplace_back(summarise(ours).median, summarise(theirs).median);
  }
  if (sets.empty()) sets = make_ray_sets(prims);

  std::printf("model: %s, %zu triangles; rays: %s;", loaded->name.c_str(), prims.triangles.size(),
              rays_file.empty() ? "generated" : rays_file.c_str());
  for (const RaySet& s : sets) std::printf(" %s %zu", s.name.c_str(), s.rays.size());
  std::printf("\nrtcli and Embree %d.%d.%d alternately; each figure the median of %d runs after a warm-up\n",
              RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH, repeats);
  for (size_t k = 0; k < thread_counts.size(); ++k) {
    const unsigned t = thread_counts[k];
    std::printf("\n%u thread%s %*s %10s %10s %-7s %7s\n", t, t == 1 ? "" : "s", t == 1 ? 26 : 25, "", "rtcli", "Embree",
                "", "ratio");
    row("BVH build, cold", 1e3 * cold[k].first, 1e3 * cold[k].second, "ms", false);
    Bvh bvh;
    const EmbreeDevice device(t);
    std::unique_ptr<EmbreeScene> embree;
    const auto builds = alternate(
        repeats, [&] { bvh = Bvh(prims, BvhBuildOptions{t}); },
        [&] {
          embree.reset();
          embree = std::make_unique<EmbreeScene>(device, prims.triangles);
        });
    row("BVH build, warm", 1e3 * builds.first.median, 1e3 * builds.second.median, "ms", false);
    for (const RaySet& set : sets) {
      const auto times = alternate(
          repeats, [&] { trace_all(set.rays, t, [&](const Ray& ray) { return trace_ray(bvh, ray, set.occlusion); }); },
          [&] {
            trace_all(set.rays, t, [&](const Ray& ray) {
              return set.occlusion ? embree->occluded(ray) : !std::isinf(embree->intersect(ray));
            });
          });
      row((set.name + (set.occlusion ? " (any hit)" : "")).c_str(), mrays(set.rays.size(), times.first),
          mrays(set.rays.size(), times.second), "Mray/s", true);
    }
    // Packets of eight neighbouring camera rays through both (Bvh::intersect_packet, rtcIntersect8).
    const RaySet& primary = sets.front();
    const size_t packet_count = (primary.rays.size() + 7) / 8;
    const auto packets = alternate(
        repeats, [&] { trace_all_packets(primary.rays, t, bvh, false); },
        [&] {
          parallel_for(packet_count, t, 512, [&](unsigned, size_t p) { embree->intersect8(primary.rays, 8 * p); });
        });
    row((primary.name + ", packets of 8").c_str(), mrays(primary.rays.size(), packets.first),
        mrays(primary.rays.size(), packets.second), "Mray/s", true);
    if (k == 0) {
      std::printf("  hits that differ:");
      for (const RaySet& set : sets) std::printf(" %s %zu", set.name.c_str(), disagreements(set, bvh, *embree, all));
      std::printf("\n");
    }
  }
  return 0;
}
