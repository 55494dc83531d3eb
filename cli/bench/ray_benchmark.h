// Ray-tracing throughput of the BVH alone (no shading), as `rtcli bench` reports it, on ray sets
// made before the clock starts (cli/bench/ray_sets.h).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "cli/bench/ray_sets.h"
#include "cli/bench/timing.h"
#include "core/accel/bvh.h"
#include "core/accel/primitives.h"
#include "core/parallel_for.h"

namespace rt {

struct SetThroughput {
  std::string name;
  size_t rays = 0;
  size_t hits = 0;  // rays that hit (closest hit) or were blocked (occlusion)
  Timing seconds;
  double mrays() const { return seconds.median > 0 ? static_cast<double>(rays) / seconds.median / 1e6 : 0.0; }
  double mrays_slowest() const { return seconds.max > 0 ? static_cast<double>(rays) / seconds.max / 1e6 : 0.0; }
  double mrays_fastest() const { return seconds.min > 0 ? static_cast<double>(rays) / seconds.min / 1e6 : 0.0; }
};

struct RayBenchmarkResult {
  unsigned threads = 1;
  Timing build;  // warm: the builds after the first
  std::vector<SetThroughput> sets;
  size_t bvh_nodes = 0;
  double sah_cost = 0.0;
};

// Builds a BVH over `prims` with `threads` threads, then traces each set with as many threads,
// `repeats` timed runs after a warm-up each.
// The BVH traces with `isa`'s kernels.
RayBenchmarkResult run_ray_benchmark(const PrimitiveSet& prims, const std::vector<RaySet>& sets, unsigned threads,
                                     int repeats, Isa isa);

// The first build of a BVH over `prims` in a fresh process (time_in_fresh_process).
double cold_build_seconds(const PrimitiveSet& prims, unsigned threads, Isa isa);

// One ray of a set through rtcli's BVH: any hit for an occlusion set, else the closest.
inline bool trace_ray(const Bvh& bvh, const Ray& ray, bool occlusion) {
  if (occlusion) return bvh.occluded(ray);
  Ray r = ray;
  Hit hit;
  return bvh.intersect(r, hit);
}

// Runs trace(ray) for every ray of `rays` on `threads` threads in chunks of 4096 from a shared
// counter (so fast and slow regions balance out); returns how many returned true.
// Each worker counts into its own cache line: counting into neighbours would bounce one line
// between cores.
template <class Trace>
size_t trace_all(const std::vector<Ray>& rays, unsigned threads, const Trace& trace) {
  struct alignas(64) Count {
    size_t n = 0;
  };
  std::vector<Count> counts(std::max(1u, threads));
  parallel_for(rays.size(), threads, 4096,
               [&](unsigned worker, size_t i) { counts[worker].n += trace(rays[i]) ? 1 : 0; });
  size_t total = 0;
  for (const Count& c : counts) total += c.n;
  return total;
}

// trace_all for packets: rays 8i..8i+7 traced together as packet i, in chunks of 512 packets.
inline size_t trace_all_packets(const std::vector<Ray>& rays, unsigned threads, const Bvh& bvh, bool occlusion) {
  struct alignas(64) Count {
    size_t n = 0;
  };
  std::vector<Count> counts(std::max(1u, threads));
  const size_t packets = (rays.size() + kPacketSize - 1) / kPacketSize;
  parallel_for(packets, threads, 512, [&](unsigned worker, size_t p) {
    const size_t first = p * kPacketSize;
    const int count = static_cast<int>(std::min<size_t>(kPacketSize, rays.size() - first));
    unsigned mask;
    if (occlusion) {
      mask = bvh.occluded_packet(rays.data() + first, count);
    } else {
      Ray packet[kPacketSize];
      Hit hits[kPacketSize];
      std::copy_n(rays.data() + first, count, packet);
      mask = bvh.intersect_packet(packet, hits, count);
    }
    counts[worker].n += static_cast<size_t>(__builtin_popcount(mask));
  });
  size_t total = 0;
  for (const Count& c : counts) total += c.n;
  return total;
}

}  // namespace rt
