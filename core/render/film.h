// What a render produces per pixel: the colour, plus the bookkeeping channels a pixel sampler
// writes beside it: how many camera samples the pixel's value averages, and how deep adaptive
// anti-aliasing split it (0 = not refined). Each worker fills a FilmTile; the renderer copies
// the finished tile into the Film, so no two threads ever write the same memory.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"
#include "core/render/tile_grid.h"

namespace rt {

struct FilmPixel {
  Vec3 color{0.0f};
  uint16_t samples = 0;  // camera samples the colour averages (a shared corner counts in each pixel)
  uint8_t depth = 0;     // refinement depth
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

struct Film {
  Image color;                    // linear RGB
  std::vector<uint16_t> samples;  // per pixel, row-major
  std::vector<uint8_t> depth;     // per pixel, row-major

  Film() = default;
  Film(int width, int height)
      : color(width, height),
        samples(static_cast<size_t>(width) * static_cast<size_t>(height), 0),
        depth(samples.size(), 0) {}

  int width() const { return color.width; }
  int height() const { return color.height; }
  size_t index(int x, int y) const {
    return static_cast<size_t>(y) * static_cast<size_t>(color.width) + static_cast<size_t>(x);
  }
  void store(const FilmTile& t) {
    const Tile& r = t.tile();
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) {
        const FilmPixel& p = t.at(x, y);
        color.at(x, y) = p.color;
        samples[index(x, y)] = p.samples;
        depth[index(x, y)] = p.depth;
      }
  }
};

}  // namespace rt
