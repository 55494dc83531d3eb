#include "core/render/renderer.h"

#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/parallel_for.h"
#include "core/render/pixel_sampler.h"

namespace rt {

RenderStats render(const Scene& scene, const RenderSettings& settings, Film& film, const RenderControl& control,
                   uint32_t frame, const RenderView& view) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const std::unique_ptr<Integrator> integrator = make_integrator(settings.integrator);
  if (!integrator) throw std::invalid_argument("unknown integrator \"" + settings.integrator + "\"");
  const PixelWindow window = view.window.empty() ? PixelWindow::whole(settings.width, settings.height) : view.window;
  if (!window.inside(settings.width, settings.height)) throw std::invalid_argument("render window outside the image");
  const TileGrid grid(window, settings.tile_size);
  const std::unique_ptr<PixelSampler> sampler = make_pixel_sampler(settings, grid);
  if (!sampler) throw std::invalid_argument("unknown anti-aliasing mode \"" + settings.antialias.mode + "\"");

  film.x0 = window.x0;
  film.y0 = window.y0;
  if (!film.allocate(window.width(), window.height(), control.cancel,
                     FilmChannels{view.aovs, view.pixel_counts, view.display8})) {
    RenderStats stats;
    stats.seconds = elapsed();
    stats.cancelled = true;
    return stats;
  }
  // A sampler that shares tile borders needs each tile's left and upper neighbours finished
  // first: tiles then go out in wavefront order, and a worker waits (rarely) for a neighbour.
  const bool wavefront = sampler->shares_tile_borders();
  const std::vector<int> order = grid.order(wavefront);
  const auto done = std::make_unique<std::atomic<bool>[]>(static_cast<size_t>(grid.count()));
  const auto wait_for = [&](int tile) {
    if (tile >= 0) done[static_cast<size_t>(tile)].wait(false, std::memory_order_acquire);
  };
  const unsigned threads = std::min<unsigned>(resolve_thread_count(settings.threads), std::max(1, grid.count()));

  std::atomic<int> next{0};
  std::atomic<uint64_t> pixels_done{0}, rays_done{0};
  std::atomic<bool> stopped{false};
  std::vector<RayCounters> counters(threads);
  // Each tile's totals as last stored: a pass of a progressive render stores the tile again.
  std::vector<PixelTotals> tile_totals(static_cast<size_t>(grid.count()));

  const auto worker = [&](unsigned index) {
    // Counted on this thread's own stack and stored once at the end: neighbouring entries of
    // `counters` share a cache line, and incrementing them per ray would bounce it between cores.
    RayCounters mine;
    PixelContext ctx{scene,          settings,     *integrator, mine,     frame,
                     control.cancel, &pixels_done, view.camera, view.eye, view.aovs};
    const std::unique_ptr<SamplerWorkspace> workspace = sampler->make_workspace();
    ctx.workspace = workspace.get();
    FilmTile tile_film;
    // Every tile is marked done, even one skipped after a cancel, so that no worker waits forever.
    for (int k = next++; k < grid.count(); k = next++) {
      const Tile tile = grid.tile(order[static_cast<size_t>(k)]);
      if (!stopped) {
        if (wavefront) {
          wait_for(grid.left(tile.index));
          wait_for(grid.above(tile.index));
        }
        const uint64_t rays_before = mine.total();
        tile_film.reset(tile);
        if (sampler->render_tile(tile, ctx, tile_film)) {
          tile_totals[static_cast<size_t>(tile.index)] = film.store(tile_film);
        } else {
          stopped = true;
        }
        ctx.publish_progress();
        rays_done += mine.total() - rays_before;
      }
      done[static_cast<size_t>(tile.index)].store(true, std::memory_order_release);
      done[static_cast<size_t>(tile.index)].notify_all();
    }
    counters[index] += mine;
  };
  // The calling thread reports progress while the workers render.
  const auto run_pass = [&] {
    next = 0;
    pixels_done = 0;
    for (int t = 0; t < grid.count(); ++t) done[static_cast<size_t>(t)].store(false);
    run_workers(threads, worker, [&] {
      if (control.progress)
        control.progress(RenderProgress{pixels_done.load(), window.pixels(), rays_done.load(), elapsed()});
    });
  };
  RenderStats stats;
  const bool resumed = view.resume_from != nullptr;
  if (view.display8 && (view.aovs || view.keep_sums || control.pass_done))
    throw std::invalid_argument("a film of display codes keeps no layers, sums or passes to show");
  if ((resumed || view.keep_sums) && !sampler->renders_passes())
    throw std::invalid_argument("this integrator keeps no sample sums to resume from");
  if (resumed && !sampler->resume(*view.resume_from, window))
    throw std::invalid_argument("the sample sums to resume from are not the window's");
  if ((control.time_limit > 0.0 || control.pass_done) && sampler->renders_passes()) {
    // Passes of kPassSamples samples a pixel, each finished whole and stored: the film always
    // holds the image so far. Another pass starts only if one as long as the last still ends in
    // time, so the render stops near the limit with whole passes.
    int end = sampler->resumed_samples() / kPassSamples * kPassSamples;
    // A resumed render's first pass runs even when no pixel takes a sample: it writes the film.
    for (bool first = true; !stopped; first = false) {
      end += kPassSamples;
      if (!sampler->begin_pass(end, window) && !(first && resumed)) break;
      const double before = elapsed();
      run_pass();
      if (stopped) break;
      ++stats.passes;
      if (control.pass_done) control.pass_done(film, end);
      const double took = elapsed() - before;
      if (control.time_limit > 0.0 && elapsed() + took > control.time_limit) break;
    }
    stats.time_limited = !stopped && sampler->begin_pass(end + kPassSamples, window);
  } else if (resumed || view.keep_sums) {
    // One pass to every sample, the sampler keeping each pixel's sums (a pixel that has all
    // its samples already is written from its sums).
    sampler->begin_pass(settings.path.samples_per_pixel, window);
    run_pass();
  } else {
    run_pass();
  }
  if (view.keep_sums && !stopped && sampler->sums()) film.sums = *sampler->sums();

  stats.seconds = elapsed();
  stats.threads = threads;
  stats.cancelled = stopped;
  for (const RayCounters& c : counters) stats.rays += c;
  for (const PixelTotals& t : tile_totals) stats.pixels += t;
  return stats;
}

RenderStats render(const Scene& scene, const RenderSettings& settings, Image& image, const RenderControl& control,
                   uint32_t frame, const RenderView& view) {
  Film film;
  RenderView colour_only = view;
  colour_only.pixel_counts = false;
  const RenderStats stats = render(scene, settings, film, control, frame, colour_only);
  image = std::move(film.color);
  return stats;
}

}  // namespace rt
