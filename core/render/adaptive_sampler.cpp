#include "core/render/adaptive_sampler.h"

#include <algorithm>
#include <utility>

#include "core/color.h"

namespace rt {
namespace {

// Sample positions are keyed on a fixed lattice of 64 x 64 cells per pixel, fine enough for
// every position either mode uses up to kMaxAdaptiveDepth (centres at depth 4: 1/64 of a
// pixel). A point keeps its random numbers whatever max_depth is.
constexpr int kKeyCells = 64;
static_assert(kKeyCells >= 4 << kMaxAdaptiveDepth);

// Takes the border a neighbour left, or (at the image border, or after a cancel) a border of
// `size` points none of which is known yet.
std::vector<LatticeSample> take_border(std::vector<std::vector<LatticeSample>>& borders, int tile, size_t size) {
  std::vector<LatticeSample> border;
  if (tile >= 0) border = std::move(borders[static_cast<size_t>(tile)]);
  if (border.size() != size) border.assign(size, LatticeSample{});
  return border;
}

Vec3 average(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return (a + b + c + d) * 0.25f; }

}  // namespace

// The (cells + 1)^2 lattice points of one pixel, and which of them its cells used.
struct AdaptiveSampler::PixelLattice {
  int x0 = 0, y0 = 0;  // the pixel's top-left corner in key units
  int side = 0;        // points per side: cells + 1
  int step = 0;        // key units between neighbouring points
  int deepest = 0;     // the deepest cell the pixel's value averages
  std::vector<LatticeSample> points;
  std::vector<uint8_t> used;

  PixelLattice(int cells) : side(cells + 1), step(kKeyCells / cells) {
    points.resize(static_cast<size_t>(side) * static_cast<size_t>(side));
    used.resize(points.size());
  }
  LatticeSample& at(int i, int j) { return points[static_cast<size_t>(j) * static_cast<size_t>(side) + i]; }
  void start_pixel(int x, int y) {
    x0 = x * kKeyCells;
    y0 = y * kKeyCells;
    std::fill(points.begin(), points.end(), LatticeSample{});
    std::fill(used.begin(), used.end(), uint8_t{0});
    deepest = 0;
  }
};

AdaptiveSampler::AdaptiveSampler(const AntialiasSettings& settings, const TileGrid& grid)
    : threshold_(settings.threshold),
      max_depth_(std::clamp(settings.max_depth, 0, kMaxAdaptiveDepth)),
      positions_(settings.positions),
      cells_(1 << max_depth_),
      grid_(grid),
      right_borders_(static_cast<size_t>(grid.count())),
      bottom_borders_(static_cast<size_t>(grid.count())) {}

bool AdaptiveSampler::render_tile(const Tile& tile, PixelContext& ctx, FilmTile& out) {
  return positions_ == SamplePositions::kCorners ? render_corners(tile, ctx, out) : render_centres(tile, ctx, out);
}

// One camera ray through lattice point (x, y), in key units from the image's top-left corner.
LatticeSample AdaptiveSampler::trace(int64_t x, int64_t y, PixelContext& ctx) const {
  const RenderSettings& s = ctx.settings;
  const auto point = static_cast<uint64_t>(y) << 32 | static_cast<uint64_t>(x);
  const SampleStream samples(s.seed, ctx.frame, point, 0);
  const Vec3 radiance =
      trace_camera_sample(static_cast<float>(x) / kKeyCells, static_cast<float>(y) / kKeyCells, samples, ctx);
  return LatticeSample{radiance, srgb_encode(radiance), true};
}

// The contrast measure: the largest difference between the four samples' displayed values in
// any one channel (sRGB-encoded, clamped to [0, 1]), compared with the threshold.
bool AdaptiveSampler::differ(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) const {
  const Vec3 lo = glm::min(glm::min(a, b), glm::min(c, d));
  const Vec3 hi = glm::max(glm::max(a, b), glm::max(c, d));
  const Vec3 range = hi - lo;
  return std::max(range.x, std::max(range.y, range.z)) > threshold_;
}

// The cell with top-left lattice point (i, j) and `size` lattice steps per side, at `depth`.
Vec3 AdaptiveSampler::refine_corners(PixelLattice& lattice, int i, int j, int size, int depth,
                                     PixelContext& ctx) const {
  const auto corner = [&](int ci, int cj) -> const LatticeSample& {
    LatticeSample& p = lattice.at(ci, cj);
    if (!p.known) p = trace(lattice.x0 + ci * lattice.step, lattice.y0 + cj * lattice.step, ctx);
    lattice.used[static_cast<size_t>(cj) * static_cast<size_t>(lattice.side) + ci] = 1;
    return p;
  };
  const LatticeSample& a = corner(i, j);
  const LatticeSample& b = corner(i + size, j);
  const LatticeSample& c = corner(i, j + size);
  const LatticeSample& d = corner(i + size, j + size);
  if (size == 1 || !differ(a.display, b.display, c.display, d.display)) {
    lattice.deepest = std::max(lattice.deepest, depth);
    return average(a.radiance, b.radiance, c.radiance, d.radiance);
  }
  const int h = size / 2;
  return average(refine_corners(lattice, i, j, h, depth + 1, ctx), refine_corners(lattice, i + h, j, h, depth + 1, ctx),
                 refine_corners(lattice, i, j + h, h, depth + 1, ctx),
                 refine_corners(lattice, i + h, j + h, h, depth + 1, ctx));
}

bool AdaptiveSampler::render_corners(const Tile& tile, PixelContext& ctx, FilmTile& out) {
  const int n = cells_;
  // Lattice points along the bottom edge of the pixel row above (at first the tile's top border),
  // and along the right edge of the pixel to the left (at first the tile's left border).
  std::vector<LatticeSample> above =
      take_border(bottom_borders_, grid_.above(tile.index), static_cast<size_t>(tile.width() * n + 1));
  const std::vector<LatticeSample> left_border =
      take_border(right_borders_, grid_.left(tile.index), static_cast<size_t>(tile.height() * n + 1));
  std::vector<LatticeSample> right_border(static_cast<size_t>(tile.height() * n + 1));
  std::vector<LatticeSample> left(static_cast<size_t>(n + 1));
  PixelLattice lattice(n);

  for (int y = tile.y0; y < tile.y1; ++y) {
    const int row = (y - tile.y0) * n;
    std::copy_n(left_border.begin() + row, n + 1, left.begin());
    for (int x = tile.x0; x < tile.x1; ++x) {
      if (ctx.cancelled()) return false;
      const int column = (x - tile.x0) * n;
      lattice.start_pixel(x, y);
      // The corner they share is known to the left neighbour, the row above, both or neither.
      for (int k = 0; k <= n; ++k) {
        lattice.at(k, 0) = above[static_cast<size_t>(column + k)];
        if (left[static_cast<size_t>(k)].known) lattice.at(0, k) = left[static_cast<size_t>(k)];
      }
      FilmPixel& pixel = out.at(x, y);
      pixel.color = refine_corners(lattice, 0, 0, n, 0, ctx);
      pixel.depth = static_cast<uint8_t>(lattice.deepest);
      pixel.samples = static_cast<uint16_t>(std::count(lattice.used.begin(), lattice.used.end(), uint8_t{1}));
      for (int k = 0; k <= n; ++k) {
        above[static_cast<size_t>(column + k)] = lattice.at(k, n);
        left[static_cast<size_t>(k)] = lattice.at(n, k);
      }
    }
    std::copy_n(left.begin(), n + 1, right_border.begin() + row);
  }
  if (grid_.below(tile.index) >= 0) bottom_borders_[static_cast<size_t>(tile.index)] = std::move(above);
  if (grid_.right(tile.index) >= 0) right_borders_[static_cast<size_t>(tile.index)] = std::move(right_border);
  return true;
}

// The cell with top-left corner (x, y) and `size` key units per side, at `depth`: the average of
// its four quarters' centres, or of its four quarters refined the same way.
Vec3 AdaptiveSampler::refine_centres(int x, int y, int size, int depth, FilmPixel& pixel, PixelContext& ctx) const {
  const int q = size / 4;
  const LatticeSample a = trace(x + q, y + q, ctx);
  const LatticeSample b = trace(x + 3 * q, y + q, ctx);
  const LatticeSample c = trace(x + q, y + 3 * q, ctx);
  const LatticeSample d = trace(x + 3 * q, y + 3 * q, ctx);
  pixel.samples = static_cast<uint16_t>(pixel.samples + 4);
  if (depth == max_depth_ || !differ(a.display, b.display, c.display, d.display)) {
    pixel.depth = static_cast<uint8_t>(std::max<int>(pixel.depth, depth));
    return average(a.radiance, b.radiance, c.radiance, d.radiance);
  }
  const int h = size / 2;
  return average(refine_centres(x, y, h, depth + 1, pixel, ctx), refine_centres(x + h, y, h, depth + 1, pixel, ctx),
                 refine_centres(x, y + h, h, depth + 1, pixel, ctx),
                 refine_centres(x + h, y + h, h, depth + 1, pixel, ctx));
}

bool AdaptiveSampler::render_centres(const Tile& tile, PixelContext& ctx, FilmTile& out) {
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      if (ctx.cancelled()) return false;
      FilmPixel pixel;
      pixel.color = refine_centres(x * kKeyCells, y * kKeyCells, kKeyCells, 0, pixel, ctx);
      out.at(x, y) = pixel;
    }
  return true;
}

}  // namespace rt
