#include "cli/bench/ray_benchmark.h"

#include "core/accel/bvh.h"

namespace rt {

double cold_build_seconds(const PrimitiveSet& prims, unsigned threads, Isa isa) {
  return time_in_fresh_process([&] { const Bvh bvh(prims, BvhBuildOptions{threads, isa}); });
}

RayBenchmarkResult run_ray_benchmark(const PrimitiveSet& prims, const std::vector<RaySet>& sets, unsigned threads,
                                     int repeats, Isa isa) {
  RayBenchmarkResult result;
  result.threads = threads;
  Bvh bvh;
  result.build = time_runs(repeats, [&] { bvh = Bvh(prims, BvhBuildOptions{threads, isa}); });
  const BvhStats stats = bvh.stats();
  result.bvh_nodes = stats.nodes;
  result.sah_cost = stats.sah_cost;
  for (const RaySet& set : sets) {
    SetThroughput t{set.name, set.rays.size(), 0, {}};
    const auto run = [&] {
      t.hits = trace_all(set.rays, threads, [&](const Ray& ray) { return trace_ray(bvh, ray, set.occlusion); });
    };
    t.seconds = time_runs(repeats, run);
    result.sets.push_back(t);
  }
  // The coherent sets again, eight neighbouring rays a packet (Bvh::intersect_packet and
  // occluded_packet), as the renderer traces camera rays and an area light's shadow rays.
  for (const RaySet& set : sets) {
    if (set.name != "primary" && set.name != "occlusion") continue;
    SetThroughput t{set.name + " x8", set.rays.size(), 0, {}};
    const auto run = [&] { t.hits = trace_all_packets(set.rays, threads, bvh, set.occlusion); };
    t.seconds = time_runs(repeats, run);
    result.sets.push_back(t);
  }
  return result;
}

}  // namespace rt
