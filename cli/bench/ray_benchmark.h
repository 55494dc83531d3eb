// Ray-tracing throughput of the BVH alone (no shading), as `rtcli bench` reports it.
#pragma once

#include <string>

#include "core/accel/primitives.h"

namespace rt {

struct RayBenchmarkResult {
  unsigned threads = 1;
  double build_seconds = 0.0;
  double primary_mrays = 0.0;  // million rays per second
  double incoherent_mrays = 0.0;
  double shadow_mrays = 0.0;
  double primary_hit_fraction = 0.0;
  double incoherent_hit_fraction = 0.0;
  double shadow_occluded_fraction = 0.0;
  size_t bvh_nodes = 0;
  double sah_cost = 0.0;
};

// Builds a BVH over `prims` with `threads` threads, then traces with as many threads (every
// figure is the best of three runs):
//  primary    - a pinhole camera framing the bounds at 1920x1080, one ray per pixel;
//  incoherent - 2M rays from uniform points in the bounds in uniform random directions;
//  shadow     - from every primary hit towards a point light above the model, any-hit.
RayBenchmarkResult run_ray_benchmark(const PrimitiveSet& prims, unsigned threads);

}  // namespace rt
