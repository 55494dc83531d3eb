// What a render produces per pixel: the colour, plus the bookkeeping channels a pixel sampler
// writes beside it: how many camera samples the pixel's value averages, and how deep adaptive
// anti-aliasing split it (0 = not refined), kept in the Film when asked; and when asked, the first
// hit's layers (aovs.h). Each worker fills a FilmTile; the renderer copies the finished tile into
// the Film, so no two threads ever write the same memory.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/display_codes.h"
#include "core/image.h"
#include "core/render/aovs.h"
#include "core/render/sample_sums.h"
#include "core/render/tile_grid.h"

namespace rt {

// Over some pixels: how many adaptive anti-aliasing refined, and the camera samples their values
// average (a render's statistics line).
struct PixelTotals {
  uint64_t refined = 0;
  uint64_t samples = 0;

  PixelTotals& operator+=(const PixelTotals& o) {
    refined += o.refined;
    samples += o.samples;
    return *this;
  }
};

struct FilmPixel {
  Vec3 color{0.0f};
  uint16_t samples = 0;  // camera samples the colour averages (a shared corner counts in each pixel)
  uint8_t depth = 0;     // refinement depth
  Aovs aovs;             // when the render asks for them
  // The variance of the colour's mean luminance, from its samples (the path tracer's pixels; 0
  // where a pixel sampler does not estimate it): what a denoiser weighs noise by.
  float variance = 0.0f;
};

class FilmTile {
 public:
  void reset(const Tile& tile) {
    tile_ = tile;
    pixels_.assign(static_cast<size_t>(tile.width()) * static_cast<size_t>(tile.height()), FilmPixel{});
  }
  const Tile& tile() const { return tile_; }
  // (x, y) in image coordinates, inside the tile.
  FilmPixel& at(int x, int y) { return pixels_[index(x, y)]; }
  const FilmPixel& at(int x, int y) const { return pixels_[index(x, y)]; }

 private:
  size_t index(int x, int y) const {
    return static_cast<size_t>(y - tile_.y0) * static_cast<size_t>(tile_.width()) + static_cast<size_t>(x - tile_.x0);
  }
  Tile tile_;
  std::vector<FilmPixel> pixels_;
};

// What a film keeps besides the colour (Film::allocate).
struct FilmChannels {
  bool aovs = false;                           // the first hit's layers
  bool counts = true;                          // samples and depth
  const DisplayTransform* display8 = nullptr;  // the colour as these display codes only
};

// The pixels of a window of the image (all of it unless a render asked for part): (0, 0) of
// `color` and of the channels is the window's corner (x0, y0) of the image.
struct Film {
  // Linear RGB; its pixels empty (its size set) when the film keeps display codes instead.
  Image color;
  // The colour as the 8-bit codes a PNG holds, 3 bytes a pixel, row-major, when the render asked
  // for them (RenderView::display8: a picture that is only written): each tile encoded as it is
  // stored (core/display_codes.h), and no linear colour kept. Else empty. At 1920 x 1440 the linear
  // colour is 33 MB whose every page is a first touch the kernel zeroes: 5% of antialias.json's
  // CPU time; these codes are 8 MB.
  ZeroedVector<uint8_t> display8;
  // FilmPixel's samples and depth per pixel, row-major, when the render asked for them
  // (RenderView::pixel_counts); else empty. Only debug images and the watch page read them; at
  // 1920 x 1440 their 8 MB of first touches and stores, and the walk that summed them, were 3-6%
  // of antialias.json's wall (docs/benchmark.md, "Round two, a twelfth session"). The totals are
  // RenderStats'.
  ZeroedVector<uint16_t> samples;
  ZeroedVector<uint8_t> depth;
  // The first hit's layers (aovs.h), when the render asked for them (RenderView::aovs); else empty.
  Image albedo, normal, emission;
  std::vector<float> distance;
  std::vector<float> variance;  // FilmPixel::variance, beside the layers
  // The path tracer's sums per pixel, when the render kept them (RenderView::keep_sums); else empty.
  SampleState sums;
  int x0 = 0, y0 = 0;  // where the film's first pixel is in the image

  Film() = default;
  Film(int width, int height) { allocate(width, height, nullptr); }

  // Sized for width x height pixels, all zero, grown a slice at a time with `cancel` checked in
  // between. The colour, sample and depth channels are ZeroedVectors: a fresh film's are not
  // written here at all (their pages are first touched by the render threads), and a reused
  // film's storage is given back and taken afresh. The sample and depth channels only with
  // `counts`. With `aovs`, the first hit's layers too: their distance and variance are written, at
  // 8192 x 8192 a quarter of a gigabyte each, and Ctrl-C must not wait for them. False (the film
  // left partly grown) once `cancel` is set.
  bool allocate(int width, int height, const std::atomic<bool>* cancel, FilmChannels channels = {}) {
    const bool aovs = channels.aovs, counts = channels.counts;
    const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
    color.width = albedo.width = normal.width = emission.width = width;
    color.height = albedo.height = normal.height = emission.height = height;
    // Released, not cleared: a ZeroedVector grows from zero only into fresh storage.
    release(color.pixels);
    release(display8);
    display_ = channels.display8 ? std::optional<DisplayTransform>(*channels.display8) : std::nullopt;
    release(samples);
    release(depth);
    release(albedo.pixels);
    release(normal.pixels);
    release(emission.pixels);
    distance.clear();
    variance.clear();
    sums.clear();
    if (display_) display8.reserve(3 * n);
    else color.pixels.reserve(n);
    if (counts) {
      samples.reserve(n);
      depth.reserve(n);
    }
    if (aovs) {
      albedo.pixels.reserve(n);
      normal.pixels.reserve(n);
      emission.pixels.reserve(n);
      distance.reserve(n);
      variance.reserve(n);
    }
    constexpr size_t kSlice = size_t{1} << 20;
    for (size_t done = 0; done < n;) {
      if (cancel && cancel->load(std::memory_order_relaxed)) return false;
      const size_t next = std::min(n, done + kSlice);
      done = next;
      if (display_) display8.resize(3 * next);  // zero, not written (ZeroedVector)
      else color.pixels.resize(next);
      if (counts) {
        samples.resize(next);
        depth.resize(next);
      }
      if (aovs) {
        albedo.pixels.resize(next);
        normal.pixels.resize(next);
        emission.pixels.resize(next);
        distance.resize(next, Aovs::kFarAway);
        variance.resize(next, 0.0f);
      }
    }
    return true;
  }
  bool has_aovs() const { return !distance.empty(); }
  bool has_counts() const { return !samples.empty(); }

  int width() const { return color.width; }
  int height() const { return color.height; }
  PixelWindow window() const { return PixelWindow{x0, y0, x0 + width(), y0 + height()}; }
  // (x, y) in the film's own coordinates.
  size_t index(int x, int y) const {
    return static_cast<size_t>(y) * static_cast<size_t>(color.width) + static_cast<size_t>(x);
  }
  // Copies the tile in; returns its pixels' totals, counted in the same pass.
  PixelTotals store(const FilmTile& t) {
    const Tile& r = t.tile();
    const bool counts = has_counts();
    PixelTotals totals;
    // Display codes: each run of a row's colours gathered, then encoded together.
    constexpr int kRun = 64;
    Vec3 run[kRun];
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) {
        const FilmPixel& p = t.at(x, y);
        const size_t i = index(x - x0, y - y0);
        if (display_) {
          const int k = (x - r.x0) % kRun;
          run[k] = p.color;
          if (k + 1 == kRun || x + 1 == r.x1)
            display_codes(run, static_cast<size_t>(k + 1), *display_, &display8[3 * (i - static_cast<size_t>(k))]);
        } else {
          color.pixels[i] = p.color;
        }
        totals.refined += p.depth > 0;
        totals.samples += p.samples;
        if (counts) {
          samples[i] = p.samples;
          depth[i] = p.depth;
        }
        if (has_aovs()) {
          albedo.pixels[i] = p.aovs.albedo;
          normal.pixels[i] = p.aovs.normal;
          emission.pixels[i] = p.aovs.emission;
          distance[i] = p.aovs.distance;
          variance[i] = p.variance;
        }
      }
    return totals;
  }

 private:
  std::optional<DisplayTransform> display_;  // set: the colour is kept as display8's codes
};

}  // namespace rt
