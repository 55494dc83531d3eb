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

// Takes the border a neighbour left into `border`, whose buffer goes to the neighbour's entry in
// its place (never read again); or (at the image border, or after a cancel) fills `border` with
// `size` points none of which is known yet.
// The layers are read only where a point is known.
void take_border(std::vector<LatticeBorder>& borders, int tile, size_t size, bool layers, LatticeBorder& border) {
  if (tile >= 0) border.swap(borders[static_cast<size_t>(tile)]);
  if (tile < 0 || border.points.size() != size) border.points.assign(size, LatticeSample{});
  border.layers.resize(layers ? size : 0);
}

Vec3 average(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return (a + b + c + d) * 0.25f; }

// A cell's four samples' layers, each a quarter of the cell's share of the pixel.
void add_layers(Aovs& layers, float share, const Aovs& a, const Aovs& b, const Aovs& c, const Aovs& d) {
  const float quarter = 0.25f * share;
  layers.add(a, quarter);
  layers.add(b, quarter);
  layers.add(c, quarter);
  layers.add(d, quarter);
}

// Lattice points traced a packet of neighbours at a time: add() queues a point, (x, y) in key
// units from the image's top-left corner, and where its sample goes; flush() traces what is
// queued (add() does when the packet is full), its layers going to `layers_to` (null: none
// asked). A point's random numbers are keyed by its place, so when it is traced changes nothing.
class PointBatch {
 public:
  explicit PointBatch(PixelContext& ctx) : ctx_(ctx) {}
  void add(int64_t x, int64_t y, LatticeSample* to, Aovs* layers_to) {
    to_[batch_.count] = to;
    layers_to_[batch_.count] = layers_to;
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
      *to_[i] = LatticeSample{r, {codes.encode(shown.x), codes.encode(shown.y), codes.encode(shown.z)}, true};
      if (layers_to_[i]) *layers_to_[i] = batch_.aovs[i];
    }
    batch_.clear();
  }

 private:
  PixelContext& ctx_;
  CameraBatch batch_;
  LatticeSample* to_[kPacketSize];
  Aovs* layers_to_[kPacketSize];
};

}  // namespace

// The lattice points of one row of a tile's pixels: n + 1 rows of width x n + 1 points, in which
// neighbouring pixels share their edges in place (handing each pixel's edges on by copies cost
// most of the sampler's own time), and the pixel whose cells are being refined.
struct AdaptiveSampler::RowLattice {
  int n = 0;                          // cells per pixel side
  int columns = 0;                    // points per row
  int step = 0;                       // key units between neighbouring points
  std::vector<LatticeSample> points;  // n + 1 rows of `columns`
  std::vector<Aovs> layers;           // the points' layers, when the render asks for them (else empty)
  std::vector<uint8_t> known;         // traced in this row, or taken from a border
  // The current pixel: its top-left corner in key units and its first column, the deepest cell
  // its value averages, and the points its cells used (stamped with the pixel's generation in
  // `counted`, pixel-local, so that starting a pixel clears nothing).
  int x0 = 0, y0 = 0, column = 0;
  int deepest = 0, used = 0;
  uint32_t generation = 0;
  std::vector<uint32_t> counted;

  // For a tile `width` pixels wide, no point known. The points' old values stay (known says
  // which are traced).
  void reset(int cells, int width, bool with_layers) {
    n = cells;
    columns = width * cells + 1;
    step = kKeyCells / cells;
    points.resize(static_cast<size_t>(cells + 1) * static_cast<size_t>(columns));
    layers.resize(with_layers ? points.size() : 0);
    known.assign(points.size(), 0);
    counted.assign(static_cast<size_t>(cells + 1) * static_cast<size_t>(cells + 1), 0);
    generation = 0;
  }
  // Point `c` of row j.
  size_t at(int c, int j) const { return static_cast<size_t>(j) * static_cast<size_t>(columns) + c; }
  // The current pixel's point (i, j), i and j in [0, n].
  size_t index(int i, int j) const { return at(column + i, j); }
  void start_pixel(int x, int y, int first_column) {
    x0 = x * kKeyCells;
    y0 = y * kKeyCells;
    column = first_column;
    deepest = used = 0;
    ++generation;
  }
  // Counts the current pixel's point (i, j) in `used`, once.
  void use(int i, int j) {
    uint32_t& stamp = counted[static_cast<size_t>(j) * static_cast<size_t>(n + 1) + i];
    if (stamp == generation) return;
    stamp = generation;
    ++used;
  }
  Aovs* layers_of(size_t k) { return layers.empty() ? nullptr : &layers[k]; }
  // Point `c` of row j from point k of a border (ignored if the neighbour did not trace it), and
  // back out.
  void take(int c, int j, const LatticeBorder& from, size_t k) {
    if (!from.points[k].known) return;
    points[at(c, j)] = from.points[k];
    if (!layers.empty()) layers[at(c, j)] = from.layers[k];
    known[at(c, j)] = 1;
  }
  void give(int c, int j, LatticeBorder& to, size_t k) const {
    if (!known[at(c, j)]) {
      to.points[k].known = false;
      return;
    }
    to.points[k] = points[at(c, j)];
    if (!layers.empty()) to.layers[k] = layers[at(c, j)];
  }
  // Row n's points are row 0's: the row's bottom is the next row's top.
  void bottom_to_top() {
    const auto bottom = static_cast<std::ptrdiff_t>(at(0, n));
    std::copy_n(points.begin() + bottom, columns, points.begin());
    std::copy_n(known.begin() + bottom, columns, known.begin());
    if (!layers.empty()) std::copy_n(layers.begin() + bottom, columns, layers.begin());
  }
};

// A worker's lattice and tile borders (take_border swaps the borders' buffers with the table's).
struct AdaptiveSampler::CornerBuffers final : SamplerWorkspace {
  RowLattice lattice;
  LatticeBorder above, left, right;
};

AdaptiveSampler::AdaptiveSampler(const AntialiasSettings& settings, const TileGrid& grid)
    : threshold_levels_(settings.threshold * 255.0f),
      max_depth_(std::clamp(settings.max_depth, 0, kMaxAdaptiveDepth)),
      positions_(settings.positions),
      cells_(1 << max_depth_),
      grid_(grid),
      right_borders_(static_cast<size_t>(grid.count())),
      bottom_borders_(static_cast<size_t>(grid.count())) {}

std::unique_ptr<SamplerWorkspace> AdaptiveSampler::make_workspace() const {
  if (positions_ != SamplePositions::kCorners) return nullptr;
  return std::make_unique<CornerBuffers>();
}

bool AdaptiveSampler::render_tile(const Tile& tile, PixelContext& ctx, FilmTile& out) {
  return positions_ == SamplePositions::kCorners ? render_corners(tile, ctx, out) : render_centres(tile, ctx, out);
}

// The contrast measure: the largest difference between the four samples' displayed values in
// any one channel (8-bit sRGB codes), compared with the threshold. The three channels at once, a
// byte each in a vector (channel by channel, with the call, it took 4% of antialias.json).
bool AdaptiveSampler::differ(const LatticeSample& a, const LatticeSample& b, const LatticeSample& c,
                             const LatticeSample& d) const {
  typedef uint8_t Codes __attribute__((vector_size(4)));
  const auto codes = [](const LatticeSample& s) { return Codes{s.display[0], s.display[1], s.display[2], 0}; };
  const auto lower = [](Codes x, Codes y) { return x < y ? x : y; };
  const auto higher = [](Codes x, Codes y) { return x < y ? y : x; };
  const Codes ca = codes(a), cb = codes(b), cc = codes(c), cd = codes(d);
  const Codes range = higher(higher(ca, cb), higher(cc, cd)) - lower(lower(ca, cb), lower(cc, cd));
  const int widest = std::max(std::max(range[0], range[1]), range[2]);
  return static_cast<float>(widest) > threshold_levels_;
}

// The cell with top-left lattice point (i, j) and `size` lattice steps per side, at `depth`.
Vec3 AdaptiveSampler::refine_corners(RowLattice& lattice, int i, int j, int size, int depth, float share, Aovs* layers,
                                     PixelContext& ctx) const {
  // Each point is traced once, by the first cell that needs it (the row's pixel corners and a
  // split's new points are traced ahead, a packet at a time).
  const auto trace_ahead = [&](PointBatch& batch, int ci, int cj) {
    const size_t k = lattice.index(ci, cj);
    if (lattice.known[k]) return;
    batch.add(lattice.x0 + ci * lattice.step, lattice.y0 + cj * lattice.step, &lattice.points[k], lattice.layers_of(k));
    lattice.known[k] = 1;
  };
  const auto corner = [&](int ci, int cj) -> size_t {
    const size_t k = lattice.index(ci, cj);
    if (!lattice.known[k]) {
      PointBatch one(ctx);
      trace_ahead(one, ci, cj);
      one.flush();
    }
    lattice.use(ci, cj);
    return k;
  };
  const size_t ka = corner(i, j), kb = corner(i + size, j), kc = corner(i, j + size), kd = corner(i + size, j + size);
  const LatticeSample &a = lattice.points[ka], &b = lattice.points[kb], &c = lattice.points[kc],
                      &d = lattice.points[kd];
  if (size == 1 || !differ(a, b, c, d)) {
    lattice.deepest = std::max(lattice.deepest, depth);
    if (layers)
      add_layers(*layers, share, lattice.layers[ka], lattice.layers[kb], lattice.layers[kc], lattice.layers[kd]);
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
  // Lattice points along the tile's top border (the bottom of the tile above) and along its left
  // border (the right of the tile to the left); this tile's right border, filled row by row.
  CornerBuffers own;
  auto* const kept = dynamic_cast<CornerBuffers*>(ctx.workspace);
  CornerBuffers& buffers = kept ? *kept : own;
  const auto height_points = static_cast<size_t>(tile.height() * n + 1);
  LatticeBorder& above = buffers.above;
  take_border(bottom_borders_, grid_.above(tile.index), static_cast<size_t>(tile.width() * n + 1), ctx.aovs, above);
  const LatticeBorder& left_border = buffers.left;
  take_border(right_borders_, grid_.left(tile.index), height_points, ctx.aovs, buffers.left);
  LatticeBorder& right_border = buffers.right;  // every point written below
  right_border.points.resize(height_points);
  right_border.layers.resize(ctx.aovs ? height_points : 0);
  RowLattice& lattice = buffers.lattice;
  lattice.reset(n, tile.width(), ctx.aovs);
  const int columns = lattice.columns;
  for (int c = 0; c < columns; ++c) lattice.take(c, 0, above, static_cast<size_t>(c));

  for (int y = tile.y0; y < tile.y1; ++y) {
    const int row = (y - tile.y0) * n;
    // Row 0 holds the bottom of the pixel row above; the rest starts unknown but for the left
    // border's points.
    std::fill(lattice.known.begin() + columns, lattice.known.end(), uint8_t{0});
    for (int j = 0; j <= n; ++j) lattice.take(0, j, left_border, static_cast<size_t>(row + j));
    // The row's pixel corners, which every pixel's first cell needs, traced a packet of
    // neighbours at a time: the upper ones that no tile or row above traced, then the lower ones.
    {
      PointBatch corners(ctx);
      for (int j = 0; j <= n; j += n)
        for (int x = tile.x0; x <= tile.x1; ++x) {
          const size_t k = lattice.at((x - tile.x0) * n, j);
          if (lattice.known[k]) continue;
          corners.add(int64_t{x} * kKeyCells, (int64_t{y} + j / n) * kKeyCells, &lattice.points[k],
                      lattice.layers_of(k));
          lattice.known[k] = 1;
        }
      corners.flush();
    }
    for (int x = tile.x0; x < tile.x1; ++x) {
      if (ctx.cancelled()) return false;
      lattice.start_pixel(x, y, (x - tile.x0) * n);
      FilmPixel& pixel = out.at(x, y);
      pixel.color = refine_corners(lattice, 0, 0, n, 0, 1.0f, ctx.aovs ? &pixel.aovs : nullptr, ctx);
      pixel.depth = static_cast<uint8_t>(lattice.deepest);
      pixel.samples = static_cast<uint16_t>(lattice.used);
    }
    for (int j = 0; j <= n; ++j) lattice.give(columns - 1, j, right_border, static_cast<size_t>(row + j));
    lattice.bottom_to_top();
    ctx.row_done(tile.width());
  }
  if (grid_.below(tile.index) >= 0) {
    for (int c = 0; c < columns; ++c) lattice.give(c, 0, above, static_cast<size_t>(c));
    bottom_borders_[static_cast<size_t>(tile.index)].swap(above);
  }
  if (grid_.right(tile.index) >= 0) {
    right_borders_[static_cast<size_t>(tile.index)].swap(right_border);
    right_border.swap(buffers.left);  // the left border, used, is the next tile's right one
  }
  return true;
}

// The cell with top-left corner (x, y) and `size` key units per side, at `depth`: the average of
// its four quarters' centres, or of its four quarters refined the same way.
Vec3 AdaptiveSampler::refine_centres(int x, int y, int size, int depth, float share, FilmPixel& pixel,
                                     PixelContext& ctx) const {
  const int q = size / 4;
  LatticeSample a, b, c, d;
  Aovs la, lb, lc, ld;
  const bool with_layers = ctx.aovs;
  PointBatch centres(ctx);
  centres.add(x + q, y + q, &a, with_layers ? &la : nullptr);
  centres.add(x + 3 * q, y + q, &b, with_layers ? &lb : nullptr);
  centres.add(x + q, y + 3 * q, &c, with_layers ? &lc : nullptr);
  centres.add(x + 3 * q, y + 3 * q, &d, with_layers ? &ld : nullptr);
  centres.flush();
  pixel.samples = static_cast<uint16_t>(pixel.samples + 4);
  if (depth == max_depth_ || !differ(a, b, c, d)) {
    pixel.depth = static_cast<uint8_t>(std::max<int>(pixel.depth, depth));
    if (with_layers) add_layers(pixel.aovs, share, la, lb, lc, ld);
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
