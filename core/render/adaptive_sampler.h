// Adaptive anti-aliasing, the proposal's Whitted/Mitchell scheme. A pixel is first sampled at
// its four corners; a cell whose samples differ by more than the threshold is split into four
// and each quarter is treated the same way, down to max_depth; the pixel is the area-weighted
// average of its cells. docs/rendering.md ("Anti-aliasing") describes the contrast measure and the keying.
//
// positions = corners: samples lie on a lattice of 2^max_depth x 2^max_depth cells per pixel,
// and a lattice point is traced once however many cells, pixels and tiles it touches. Within a
// tile, a row of pixels shares one lattice (neighbours' edges in place), and a row's bottom is the
// next row's top; between tiles, a finished tile hands its bottom and right borders to the tiles
// below and right of it, which the renderer starts only once their left and upper neighbours
// are done (shares_tile_borders). Each point's random numbers (its lens sample, say) are keyed
// by its global lattice position, so the image does not depend on threads or tile size.
//
// positions = centres: each cell is estimated from the centres of its four quarters instead,
// which no neighbour shares (the proposal's comparison): four rays a pixel at the least.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/render/pixel_sampler.h"

namespace rt {

// A traced lattice point: its radiance, and what a display shows of it, as 8-bit sRGB codes
// (the contrast measure compares displayed values). known = false: not traced yet. Its layers
// (Aovs), when the render asks for them, are kept beside it (LatticeBorder, the row lattice):
// 16 bytes a point, not 56, made antialias.json 0.97x the time.
struct LatticeSample {
  Vec3 radiance{0.0f};
  std::array<uint8_t, 3> display{};
  bool known = false;
};
static_assert(sizeof(LatticeSample) == 16);

// Lattice points along a tile's border, and their layers (empty unless the render asks for them).
struct LatticeBorder {
  std::vector<LatticeSample> points;
  std::vector<Aovs> layers;
  void swap(LatticeBorder& other) noexcept {
    points.swap(other.points);
    layers.swap(other.layers);
  }
};

class AdaptiveSampler final : public PixelSampler {
 public:
  AdaptiveSampler(const AntialiasSettings& settings, const TileGrid& grid);

  bool shares_tile_borders() const override { return positions_ == SamplePositions::kCorners; }
  std::unique_ptr<SamplerWorkspace> make_workspace() const override;
  bool render_tile(const Tile& tile, PixelContext& ctx, FilmTile& out) override;

 private:
  struct RowLattice;
  struct CornerBuffers;
  bool render_corners(const Tile& tile, PixelContext& ctx, FilmTile& out);
  bool render_centres(const Tile& tile, PixelContext& ctx, FilmTile& out);
  // Each returns the cell's radiance; `share` is its area as a fraction of the pixel's, with
  // which its samples' layers go into `layers` (null: none asked).
  Vec3 refine_corners(RowLattice& lattice, int i, int j, int size, int depth, float share, Aovs* layers,
                      PixelContext& ctx) const;
  Vec3 refine_centres(int x, int y, int size, int depth, float share, FilmPixel& pixel, PixelContext& ctx) const;
  bool differ(const LatticeSample& a, const LatticeSample& b, const LatticeSample& c, const LatticeSample& d) const;

  float threshold_levels_;  // the threshold in levels of 255
  int max_depth_;
  SamplePositions positions_;
  int cells_;  // lattice cells per pixel side: 2^max_depth
  TileGrid grid_;
  // Lattice points along a finished tile's right and bottom borders, kept until the tile right
  // of it or below it takes them. Written and read by different threads: the renderer's
  // wavefront orders every write before its read. Each entry is written once and read once, its
  // buffer swapped with the reader's (CornerBuffers), so that buffers go round, not new ones.
  std::vector<LatticeBorder> right_borders_, bottom_borders_;
};

}  // namespace rt
