#include "cli/bench/ray_benchmark.h"

#include <chrono>
#include <vector>

#include "core/accel/bvh.h"
#include "core/camera.h"
#include "core/parallel_for.h"
#include "core/rng.h"

namespace rt {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kWidth = 1920, kHeight = 1080;
constexpr size_t kIncoherentRays = 2'000'000;
constexpr size_t kChunk = 4096;  // rays per work item: big enough to amortise the atomic
constexpr int kRepeats = 3;      // every figure is the best of this many runs: VM timings are noisy

// Runs trace(i) for i in [0, n) on `threads` threads, in chunks taken from a shared counter so
// fast and slow regions balance out. Returns seconds and the number of trace() == true.
template <class Trace>
std::pair<double, size_t> parallel_trace(size_t n, unsigned threads, const Trace& trace) {
  double best = kInfinity;
  size_t hit_count = 0;
  for (int repeat = 0; repeat < kRepeats; ++repeat) {
    // Per worker, a cache line apart: counting into neighbours would bounce one line between cores.
    struct alignas(64) Count {
      size_t hits = 0;
    };
    std::vector<Count> hits(std::max(1u, threads));
    const auto start = Clock::now();
    parallel_for(n, threads, kChunk, [&](unsigned worker, size_t i) { hits[worker].hits += trace(i) ? 1 : 0; });
    best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
    hit_count = 0;
    for (const Count& c : hits) hit_count += c.hits;
  }
  return {best, hit_count};
}

Vec3 random_direction(Rng& rng) {
  const float z = 1.0f - 2.0f * rng.next_float();
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * rng.next_float();
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

}  // namespace

RayBenchmarkResult run_ray_benchmark(const PrimitiveSet& prims, unsigned threads) {
  RayBenchmarkResult result;
  result.threads = threads;
  Bvh bvh;
  result.build_seconds = kInfinity;
  for (int repeat = 0; repeat < kRepeats; ++repeat) {
    const auto build_start = Clock::now();
    bvh = Bvh(prims, BvhBuildOptions{threads});
    result.build_seconds =
        std::min(result.build_seconds, std::chrono::duration<double>(Clock::now() - build_start).count());
  }
  const BvhStats stats = bvh.stats();
  result.bvh_nodes = stats.nodes;
  result.sah_cost = stats.sah_cost;

  const Aabb bounds = bvh.bounds();
  const Camera camera = Camera::framing(bounds, 40.0f, static_cast<float>(kWidth) / kHeight);
  const size_t pixels = static_cast<size_t>(kWidth) * kHeight;

  // Primary rays; their hit points are kept (outside the timed loop's allocations) for shadows.
  std::vector<Vec3> hit_points(pixels, Vec3(kInfinity));
  std::vector<Vec3> hit_normals(pixels);
  auto [primary_s, primary_hits] = parallel_trace(pixels, threads, [&](size_t i) {
    Ray ray = camera.generate_ray(static_cast<float>(i % kWidth) + 0.5f, static_cast<float>(i / kWidth) + 0.5f, kWidth,
                                  kHeight);
    Hit hit;
    if (!bvh.intersect(ray, hit)) return false;
    hit_points[i] = ray.at(hit.t);
    hit_normals[i] = prims.is_triangle(hit.prim)
                         ? glm::normalize(glm::cross(prims.triangles[hit.prim].e1, prims.triangles[hit.prim].e2))
                         : -ray.direction;
    return true;
  });
  result.primary_mrays = static_cast<double>(pixels) / primary_s / 1e6;
  result.primary_hit_fraction = static_cast<double>(primary_hits) / static_cast<double>(pixels);

  const Vec3 extent = bounds.extent();
  auto [incoherent_s, incoherent_hits] = parallel_trace(kIncoherentRays, threads, [&](size_t i) {
    Rng rng(mix64(i));
    Ray ray;
    ray.origin = bounds.lo + extent * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
    ray.direction = random_direction(rng);
    Hit hit;
    return bvh.intersect(ray, hit);
  });
  result.incoherent_mrays = static_cast<double>(kIncoherentRays) / incoherent_s / 1e6;
  result.incoherent_hit_fraction = static_cast<double>(incoherent_hits) / kIncoherentRays;

  std::vector<uint32_t> shadow_pixels;
  shadow_pixels.reserve(primary_hits);
  for (size_t i = 0; i < pixels; ++i)
    if (hit_points[i].x != kInfinity) shadow_pixels.push_back(static_cast<uint32_t>(i));
  const Vec3 light = bounds.centre() + glm::length(extent) * Vec3(0.4f, 1.0f, 0.6f);
  auto [shadow_s, occluded] = parallel_trace(shadow_pixels.size(), threads, [&](size_t k) {
    const uint32_t i = shadow_pixels[k];
    const Vec3 to_light = light - hit_points[i];
    Ray ray;
    ray.direction = glm::normalize(to_light);
    ray.origin = offset_ray_origin(hit_points[i], hit_normals[i], ray.direction);
    ray.tmax = glm::length(to_light);
    return bvh.occluded(ray);
  });
  result.shadow_mrays = shadow_pixels.empty() ? 0.0 : static_cast<double>(shadow_pixels.size()) / shadow_s / 1e6;
  result.shadow_occluded_fraction =
      shadow_pixels.empty() ? 0.0 : static_cast<double>(occluded) / static_cast<double>(shadow_pixels.size());
  return result;
}

}  // namespace rt
