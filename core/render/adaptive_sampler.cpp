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

// A cell's four samples' layers, each a quarter of the cell's share of the pixel.
void add_layers(Aovs& layers, float share, const LatticeSample& a, const LatticeSample& b, const LatticeSample& c,
                const LatticeSample& d) {
  const float quarter = 0.25f * share;
  layers.add(a.aovs, quarter);
  layers.add(b.aovs, quarter);
  layers.add(c.aovs, quarter);
  layers.add(d.aovs, quarter);
}

// Lattice points traced a packet of neighbours at a time: add() queues a point, (x, y) in key
// units from the image's top-left corner, and where its sample goes; flush() traces what is
// queued (add() does when the packet is full). A point's random numbers are keyed by its place,
// so when it is traced changes nothing.
class PointBatch {
 public:
  explicit PointBatch(PixelContext& ctx) : ctx_(ctx) {}
  void add(int64_t x, int64_t y, LatticeSample* to) {
    to_[batch_.count] = to;
    CameraSample& c = batch_.add(ctx_, static_cast<uint64_t>(y) << 32 | static_cast<uint64_t>(x), 0, 0);
    c.px = static_cast<float>(x) / kKeyCells;
    c.py = static_cast<float>(y) / kKeyCells;
    if (batch_.full()) flush();
  }
  void flush() {
    if (batch_.count == 0) return;
    batch_.trace(ctx_);
    const Srgb8Table& codes = srgb8_table();
    for (int i = 0; i < batch_.count; ++i) {
      const Vec3& r = batch_.radiance[i];
      const Vec3 shown = ctx_.settings.display.apply(r);  // what the picture shows of it
      *to_[i] =
          LatticeSample{r, {codes.encode(shown.x), codes.encode(shown.y), codes.encode(shown.z)}, true, batch_.aovs[i]};
    }
    batch_.clear();
  }

 private:
  PixelContext& ctx_;
  CameraBatch batch_;
  LatticeSample* to_[kPacketSize];
};

}  // namespace

// The (cells + 1)^2 lattice points of one pixel, and which of them its cells used. A point
// belongs to the current pixel when its stamp is the pixel's generation, so starting a pixel
// clears nothing.
struct AdaptiveSampler::PixelLattice {
  int x0 = 0, y0 = 0;  // the pixel's top-left corner in key units
  int side = 0;        // points per side: cells + 1
  int step = 0;        // key units between neighbouring points
  int deepest = 0;     // the deepest cell the pixel's value averages
  int used = 0;        // points its cells used
  uint32_t generation = 0;
  std::vector<LatticeSample> points;
  std::vector<uint32_t> known, counted;  // stamps: traced or handed in; counted in `used`

  explicit PixelLattice(int cells) : side(cells + 1), step(kKeyCells / cells) {
    const size_t n = static_cast<size_t>(side) * static_cast<size_t>(side);
    points.resize(n);
    known.resize(n, 0);
    counted.resize(n, 0);
  }
  size_t index(int i, int j) const { return static_cast<size_t>(j) * static_cast<size_t>(side) + i; }
  void start_pixel(int x, int y) {
    x0 = x * kKeyCells;
    y0 = y * kKeyCells;
    deepest = used = 0;
    ++generation;
  }
  // A point a neighbour traced (ignored if it did not).
  void hand_in(int i, int j, const LatticeSample& s) {
    if (!s.known) return;
    points[index(i, j)] = s;
    known[index(i, j)] = generation;
  }
  // The point for a neighbour: unknown unless this pixel traced it or was handed it. Written in
  // place: building a temporary LatticeSample stalls on store forwarding (measured: half the
  // sampler's own time).
  void hand_out(int i, int j, LatticeSample& to) const {
    if (known[index(i, j)] == generation) to = points[index(i, j)];
    else to.known = false;
  }
};

AdaptiveSampler::AdaptiveSampler(const AntialiasSettings& settings, const TileGrid& grid)
    : threshold_levels_(settings.threshold * 255.0f),
      max_depth_(std::clamp(settings.max_depth, 0, kMaxAdaptiveDepth)),
      positions_(settings.positions),
      cells_(1 << max_depth_),
      grid_(grid),
      right_borders_(static_cast<size_t>(grid.count())),
      bottom_borders_(static_cast<size_t>(grid.count())) {}

bool AdaptiveSampler::render_tile(const Tile& tile, PixelContext& ctx, FilmTile& out) {
  return positions_ == SamplePositions::kCorners ? render_corners(tile, ctx, out) : render_centres(tile, ctx, out);
}

// The contrast measure: the largest difference between the four samples' displayed values in
// any one channel (8-bit sRGB codes), compared with the threshold.
bool AdaptiveSampler::differ(const LatticeSample& a, const LatticeSample& b, const LatticeSample& c,
                             const LatticeSample& d) const {
  int range = 0;
  for (size_t k = 0; k < 3; ++k) {
    const int lo = std::min(std::min(a.display[k], b.display[k]), std::min(c.display[k], d.display[k]));
    const int hi = std::max(std::max(a.display[k], b.display[k]), std::max(c.display[k], d.display[k]));
    range = std::max(range, hi - lo);
  }
  return static_cast<float>(range) > threshold_levels_;
}

// The cell with top-left lattice point (i, j) and `size` lattice steps per side, at `depth`.
Vec3 AdaptiveSampler::refine_corners(PixelLattice& lattice, int i, int j, int size, int depth, float share,
                                     Aovs* layers, PixelContext& ctx) const {
  // Each point is traced once, by the first cell that needs it (the row's pixel corners and a
  // split's new points are traced ahead, a packet at a time).
  const auto trace_ahead = [&](PointBatch& batch, int ci, int cj) {
    const size_t k = lattice.index(ci, cj);
    if (lattice.known[k] == lattice.generation) return;
    batch.add(lattice.x0 + ci * lattice.step, lattice.y0 + cj * lattice.step, &lattice.points[k]);
    lattice.known[k] = lattice.generation;
  };
  const auto corner = [&](int ci, int cj) -> const LatticeSample& {
    const size_t k = lattice.index(ci, cj);
    if (lattice.known[k] != lattice.generation) {
      PointBatch one(ctx);
      trace_ahead(one, ci, cj);
      one.flush();
    }
    if (lattice.counted[k] != lattice.generation) {
      lattice.counted[k] = lattice.generation;
      ++lattice.used;
    }
    return lattice.points[k];
  };
  const LatticeSample& a = corner(i, j);
  const LatticeSample& b = corner(i + size, j);
  const LatticeSample& c = corner(i, j + size);
  const LatticeSample& d = corner(i + size, j + size);
  if (size == 1 || !differ(a, b, c, d)) {
    lattice.deepest = std::max(lattice.deepest, depth);
    if (layers) add_layers(*layers, share, a, b, c, d);
    return average(a.radiance, b.radiance, c.radiance, d.radiance);
  }
  const int h = size / 2;
  // The five points the quarters add, traced together before the quarters ask for them.
  PointBatch split(ctx);
  trace_ahead(split, i + h, j);
  trace_ahead(split, i, j + h);
  trace_ahead(split, i + h, j + h);
  trace_ahead(split, i + size, j + h);
  trace_ahead(split, i + h, j + size);
  split.flush();
  const float quarter = 0.25f * share;
  return average(refine_corners(lattice, i, j, h, depth + 1, quarter, layers, ctx),
                 refine_corners(lattice, i + h, j, h, depth + 1, quarter, layers, ctx),
                 refine_corners(lattice, i, j + h, h, depth + 1, quarter, layers, ctx),
                 refine_corners(lattice, i + h, j + h, h, depth + 1, quarter, layers, ctx));
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
  std::vector<LatticeSample> bottom(static_cast<size_t>(tile.width() + 1));  // the pixel row's lower corners
  PixelLattice lattice(n);

  for (int y = tile.y0; y < tile.y1; ++y) {
    const int row = (y - tile.y0) * n;
    std::copy_n(left_border.begin() + row, n + 1, left.begin());
    // The row's pixel corners, which every pixel's first cell needs, traced a packet of
    // neighbours at a time: the upper ones that no tile or row above traced (the first may be
    // the left tile's), and the lower ones (the first, again, may be the left tile's).
    {
      PointBatch corners(ctx);
      if (!above[0].known) above[0] = left[0];
      for (int x = tile.x0; x <= tile.x1; ++x) {
        LatticeSample& upper = above[static_cast<size_t>((x - tile.x0) * n)];
        if (!upper.known) corners.add(int64_t{x} * kKeyCells, int64_t{y} * kKeyCells, &upper);
      }
      bottom[0] = left[static_cast<size_t>(n)];
      for (int x = tile.x0; x <= tile.x1; ++x) {
        LatticeSample& lower = bottom[static_cast<size_t>(x - tile.x0)];
        if (x == tile.x0 && lower.known) continue;
        corners.add(int64_t{x} * kKeyCells, int64_t{y + 1} * kKeyCells, &lower);
      }
      corners.flush();
    }
    for (int x = tile.x0; x < tile.x1; ++x) {
      if (ctx.cancelled()) return false;
      const int column = (x - tile.x0) * n;
      lattice.start_pixel(x, y);
      // The corner they share is known to the left neighbour, the row above, both or neither.
      for (int k = 0; k <= n; ++k) {
        lattice.hand_in(k, 0, above[static_cast<size_t>(column + k)]);
        lattice.hand_in(0, k, left[static_cast<size_t>(k)]);
      }
      lattice.hand_in(0, n, bottom[static_cast<size_t>(x - tile.x0)]);
      lattice.hand_in(n, n, bottom[static_cast<size_t>(x - tile.x0 + 1)]);
      FilmPixel& pixel = out.at(x, y);
      pixel.color = refine_corners(lattice, 0, 0, n, 0, 1.0f, ctx.aovs ? &pixel.aovs : nullptr, ctx);
      pixel.depth = static_cast<uint8_t>(lattice.deepest);
      pixel.samples = static_cast<uint16_t>(lattice.used);
      for (int k = 0; k <= n; ++k) {
        lattice.hand_out(k, n, above[static_cast<size_t>(column + k)]);
        lattice.hand_out(n, k, left[static_cast<size_t>(k)]);
      }
    }
    std::copy_n(left.begin(), n + 1, right_border.begin() + row);
    ctx.row_done(tile.width());
  }
  if (grid_.below(tile.index) >= 0) bottom_borders_[static_cast<size_t>(tile.index)] = std::move(above);
  if (grid_.right(tile.index) >= 0) right_borders_[static_cast<size_t>(tile.index)] = std::move(right_border);
  return true;
}

// The cell with top-left corner (x, y) and `size` key units per side, at `depth`: the average of
// its four quarters' centres, or of its four quarters refined the same way.
Vec3 AdaptiveSampler::refine_centres(int x, int y, int size, int depth, float share, FilmPixel& pixel,
                                     PixelContext& ctx) const {
  const int q = size / 4;
  LatticeSample a, b, c, d;
  PointBatch centres(ctx);
  centres.add(x + q, y + q, &a);
  centres.add(x + 3 * q, y + q, &b);
  centres.add(x + q, y + 3 * q, &c);
  centres.add(x + 3 * q, y + 3 * q, &d);
  centres.flush();
  pixel.samples = static_cast<uint16_t>(pixel.samples + 4);
  if (depth == max_depth_ || !differ(a, b, c, d)) {
    pixel.depth = static_cast<uint8_t>(std::max<int>(pixel.depth, depth));
    if (ctx.aovs) add_layers(pixel.aovs, share, a, b, c, d);
    return average(a.radiance, b.radiance, c.radiance, d.radiance);
  }
  const int h = size / 2;
  const float quarter = 0.25f * share;
  return average(refine_centres(x, y, h, depth + 1, quarter, pixel, ctx),
                 refine_centres(x + h, y, h, depth + 1, quarter, pixel, ctx),
                 refine_centres(x, y + h, h, depth + 1, quarter, pixel, ctx),
                 refine_centres(x + h, y + h, h, depth + 1, quarter, pixel, ctx));
}

bool AdaptiveSampler::render_centres(const Tile& tile, PixelContext& ctx, FilmTile& out) {
  return render_pixels(tile, ctx, out, [&](int x, int y) {
    FilmPixel pixel;
    pixel.color = refine_centres(x * kKeyCells, y * kKeyCells, kKeyCells, 0, 1.0f, pixel, ctx);
    return pixel;
  });
}

}  // namespace rt
