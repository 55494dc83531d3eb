// Pixel samplers choose where in a pixel camera rays go and how their radiance is combined.
// An open, coarse set chosen by name from render.antialias.mode, like integrators: one call
// per tile, never per ray. A sampler writes colour and its bookkeeping channels into the
// worker's FilmTile.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/pixel_window.h"
#include "core/render/film.h"
#include "core/render/integrator.h"
#include "core/render/sample_sums.h"
#include "core/render/tile_grid.h"

namespace rt {

// A worker's own buffers for a sampler's render_tile, made once per worker (make_workspace) and
// kept from tile to tile: the adaptive sampler's, made and written empty for every tile, cost
// antialias.json 6% of its wall.
class SamplerWorkspace {
 public:
  virtual ~SamplerWorkspace() = default;
};

// What a worker thread hands a sampler: the scene, settings, its own counters, the flag that
// stops the render (checked before every pixel), and the count of finished pixels the progress
// bar shows (added to after every row of a tile, so that it moves even when a tile is slow).
struct PixelContext {
  const Scene& scene;
  const RenderSettings& settings;
  const Integrator& integrator;
  RayCounters& counters;
  uint32_t frame = 0;
  const std::atomic<bool>* cancel = nullptr;
  std::atomic<uint64_t>* pixels_done = nullptr;
  // The camera the rays come from (null: the scene's), and which eye of a stereo pair: the right
  // eye's (1) random numbers are keyed apart; the left eye's (0) are a mono render's.
  const Camera* camera = nullptr;
  uint32_t eye = 0;
  bool aovs = false;  // fill each pixel's first-hit layers (FilmPixel::aovs) beside its colour
  // This worker's buffers from the sampler's make_workspace (null: none kept; the sampler then
  // makes its buffers for the tile).
  SamplerWorkspace* workspace = nullptr;

  const Camera& view() const { return camera ? *camera : scene.camera; }
  // A sample point's key (a pixel's index, a lattice point) with the eye in its top bits.
  uint64_t point_key(uint64_t point) const { return point | (static_cast<uint64_t>(eye) << 62); }
  // Pixel (x, y)'s index in the image, the point its camera samples are keyed by: the same
  // numbers whichever thread or tile traces it.
  uint64_t pixel_point(int x, int y) const {
    return static_cast<uint64_t>(y) * static_cast<uint64_t>(settings.width) + static_cast<uint64_t>(x);
  }

  bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
  // Finished pixels are added to the shared count a few thousand at a time: a tile's row is 32
  // pixels, and two threads adding each row bounced the counter's cache line between the cores
  // (antialias.json 0.98x without it, measured). The worker publishes the rest after each tile.
  void row_done(int pixels) const {
    unpublished_pixels += static_cast<uint64_t>(pixels);
    if (unpublished_pixels >= kPublishPixels) publish_progress();
  }
  void publish_progress() const {
    if (pixels_done && unpublished_pixels > 0) pixels_done->fetch_add(unpublished_pixels, std::memory_order_relaxed);
    unpublished_pixels = 0;
  }
  static constexpr uint64_t kPublishPixels = 4096;
  mutable uint64_t unpublished_pixels = 0;
};

class PixelSampler {
 public:
  virtual ~PixelSampler() = default;
  // True when a tile reuses rays that the tiles left of and above it traced along their shared
  // borders: the renderer then starts a tile only once those two are done (a wavefront).
  virtual bool shares_tile_borders() const { return false; }
  // Buffers a worker keeps for render_tile (PixelContext::workspace); null for a sampler that
  // needs none.
  virtual std::unique_ptr<SamplerWorkspace> make_workspace() const { return nullptr; }
  // Renders `tile` into `out` (already reset to the tile). Called from several threads at once,
  // each on its own tile. Returns false when it stopped early because the render was cancelled.
  virtual bool render_tile(const Tile& tile, PixelContext& ctx, FilmTile& out) = 0;
  // Progressive rendering (RenderControl::time_limit): whether the sampler can add samples in
  // passes, and the next pass: render_tile then adds samples up to `samples_end` to the pixels of
  // `window`. False when no pixel would take another sample.
  virtual bool renders_passes() const { return false; }
  virtual bool begin_pass(int /*samples_end*/, const PixelWindow& /*window*/) { return false; }
  // Continuing an earlier render (RenderView::resume_from): its pixels' sums, one per pixel of
  // `window`, from which the passes go on; false if the sampler cannot (or the sizes differ).
  virtual bool resume(SampleState /*state*/, const PixelWindow& /*window*/) { return false; }
  // The fewest samples a pixel of a resumed render has that will take more (0 when none was given).
  virtual int resumed_samples() const { return 0; }
  // The pixels' sums after the passes so far; null for a sampler that keeps none.
  virtual const SampleState* sums() const { return nullptr; }
};

// The sampler registered under settings.antialias.mode, for an image cut into `grid` (the path
// sampler, whatever the mode, for an integrator that samples pixels itself);
// nullptr if no sampler has that name.
std::unique_ptr<PixelSampler> make_pixel_sampler(const RenderSettings& settings, const TileGrid& grid);

// What a sampler's name stands for in the name table: render.antialias.mode and --aa.
struct PixelSamplerKind {
  std::unique_ptr<PixelSampler> (*make)(const AntialiasSettings&, const TileGrid&);
};
const NameTable<PixelSamplerKind>& pixel_samplers();

// Fills a tile pixel by pixel with pixel(x, y) -> FilmPixel, for samplers whose pixels are
// independent; stops (returning false) once the render is cancelled.
template <class PixelFn>
bool render_pixels(const Tile& tile, const PixelContext& ctx, FilmTile& out, PixelFn&& pixel) {
  for (int y = tile.y0; y < tile.y1; ++y) {
    for (int x = tile.x0; x < tile.x1; ++x) {
      if (ctx.cancelled()) return false;
      out.at(x, y) = pixel(x, y);
    }
    ctx.row_done(tile.width());
  }
  return true;
}

// One camera sample: the continuous pixel position (px, py) its ray goes through, the keyed
// numbers of the sample (its lens position among them), and `spacing`: the distance in pixels to
// the neighbouring camera samples (1 / n for n x n per pixel), which narrows the ray cone that
// picks texture mip levels.
struct CameraSample {
  float px = 0.0f, py = 0.0f;
  SampleStream samples;
  float spacing = 1.0f;
};

// Camera samples queued and traced kPacketSize at a time: their rays meet the scene as one packet
// (Scene::intersect_packet), then each is shaded alone, with the radiance it would have alone.
// A sampler adds samples with a tag of its own (which pixel), and once full() calls trace(), reads
// radiance[i], aovs[i] (when the render asks for them) and tag[i] for i < count in the order
// added, and clear()s.
struct CameraBatch {
  CameraSample sample[kPacketSize];
  uint32_t tag[kPacketSize];
  Vec3 radiance[kPacketSize];
  Aovs aovs[kPacketSize];
  int count = 0;
  // The render's seed and frame hashed, once for the batch (key()), and what it was made of.
  SampleStream::FrameKey frame;
  uint64_t frame_seed = 0;
  uint32_t frame_number = 0;
  bool frame_known = false;

  bool full() const { return count == kPacketSize; }
  // Queues sample `index` of image point `point` (the render's seed and frame, the context's eye)
  // and returns its slot, where the caller sets px, py and (if not 1) spacing. The numbers are
  // built in the slot: a sample built on the stack and copied in was read back by wide loads of
  // its narrow stores, which stalled (twice measured: see the commits).
  CameraSample& add(const PixelContext& ctx, uint64_t point, uint32_t index, uint32_t t) {
    return add(ctx, key(ctx, point), index, t);
  }
  // The same, for a point's key from key(): a pixel's samples hash the point once.
  CameraSample& add(const PixelContext& ctx, SampleStream::PointKey point, uint32_t index, uint32_t t) {
    CameraSample& slot = sample[count];
    std::construct_at(&slot.samples, point, index, ctx.settings.sampler);
    slot.spacing = 1.0f;
    tag[count++] = t;
    return slot;
  }
  // Fills radiance[0, count) (and aovs, if PixelContext::aovs); counts the camera rays.
  void trace(PixelContext& ctx);
  void clear() { count = 0; }
  // Image point `point`'s key (the render's seed and frame, the context's eye).
  SampleStream::PointKey key(const PixelContext& ctx, uint64_t point) {
    if (!frame_known || frame_seed != ctx.settings.seed || frame_number != ctx.frame) {
      frame = SampleStream::frame_key(ctx.settings.seed, ctx.frame);
      frame_seed = ctx.settings.seed;
      frame_number = ctx.frame;
      frame_known = true;
    }
    return SampleStream::point_key(frame, ctx.point_key(point));
  }
};

}  // namespace rt
