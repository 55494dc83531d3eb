#include "core/render/renderer.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/render/pixel_sampler.h"

namespace rt {

RenderStats render(const Scene& scene, const RenderSettings& settings, Image& image, const RenderControl& control,
                   uint32_t frame) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const std::unique_ptr<Integrator> integrator = make_integrator(settings.integrator);
  if (!integrator) throw std::invalid_argument("unknown integrator \"" + settings.integrator + "\"");
  const std::unique_ptr<PixelSampler> sampler = make_pixel_sampler(settings);

  image = Image(settings.width, settings.height);
  const int tile = std::max(1, settings.tile_size);
  const int tiles_x = (settings.width + tile - 1) / tile;
  const int tiles_y = (settings.height + tile - 1) / tile;
  const int tile_count = tiles_x * tiles_y;
  const unsigned threads = std::min<unsigned>(resolve_thread_count(settings.threads), std::max(1, tile_count));

  std::atomic<int> next_tile{0};
  std::atomic<uint64_t> pixels_done{0}, rays_done{0};
  std::atomic<bool> stopped{false};
  const auto cancelled = [&] { return control.cancel && control.cancel->load(std::memory_order_relaxed); };
  std::vector<RayCounters> counters(threads);
  std::mutex mutex;
  std::condition_variable finished;
  unsigned running = threads;

  const auto worker = [&](unsigned index) {
    // Counted on this thread's own stack and stored once at the end: neighbouring entries of
    // `counters` share a cache line, and incrementing them per ray would bounce it between cores.
    RayCounters mine;
    PixelContext ctx{scene, settings, *integrator, mine, frame};
    for (int t = next_tile++; t < tile_count && !stopped; t = next_tile++) {
      const int x0 = (t % tiles_x) * tile, y0 = (t / tiles_x) * tile;
      const int x1 = std::min(x0 + tile, settings.width), y1 = std::min(y0 + tile, settings.height);
      const uint64_t rays_before = mine.total();
      // Checked before every pixel, so that a cancel is seen within one pixel's work.
      for (int y = y0; y < y1 && !stopped; ++y)
        for (int x = x0; x < x1; ++x) {
          if (cancelled()) {
            stopped = true;
            break;
          }
          image.at(x, y) = sampler->pixel(x, y, ctx);
        }
      pixels_done += static_cast<uint64_t>((x1 - x0) * (y1 - y0));
      rays_done += mine.total() - rays_before;
    }
    counters[index] = mine;
    std::lock_guard lock(mutex);
    if (--running == 0) finished.notify_all();
  };

  std::vector<std::jthread> pool;
  pool.reserve(threads);
  for (unsigned i = 0; i < threads; ++i) pool.emplace_back(worker, i);
  const auto report = [&] {
    if (control.progress)
      control.progress(RenderProgress{pixels_done.load(), static_cast<uint64_t>(settings.width) * settings.height,
                                      rays_done.load(), elapsed()});
  };
  {
    std::unique_lock lock(mutex);
    while (!finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return running == 0; })) {
      lock.unlock();
      report();
      lock.lock();
    }
  }
  pool.clear();  // joins
  report();

  RenderStats stats;
  stats.seconds = elapsed();
  stats.threads = threads;
  stats.cancelled = stopped;
  for (const RayCounters& c : counters) stats.rays += c;
  return stats;
}

}  // namespace rt
