// Binned SAH build (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007).
// Every node bins primitive centroids on all three axes, sweeps the bins for the cheapest split
// and partitions its slice of the order array in place. Large subtrees are built on separate
// threads into their own node arrays and spliced back in a fixed order, so the tree is identical
// whatever the thread count.
#include <numeric>
#include <thread>

#include "core/accel/bvh.h"

namespace rt {
namespace {

constexpr int kBins = 16;
constexpr float kTraversalCost = 0.5f;   // cost of visiting a node, relative to one primitive test
constexpr uint32_t kMaxLeafSize = 8;     // larger leaves are always split
constexpr int kSahDepthLimit = 32;       // deeper nodes use median splits: depth stays < kMaxDepth
constexpr uint32_t kParallelMinPrims = 4096;

struct Range {
  uint32_t begin = 0, end = 0;
  Aabb bounds, centroid_bounds;
  uint32_t count() const { return end - begin; }
};

struct Bin {
  Aabb bounds, centroid_bounds;
  uint32_t count = 0;
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin) go left
  float cost = kInfinity;
};

class Builder {
 public:
  Builder(const std::vector<Aabb>& boxes, const std::vector<Vec3>& centroids, std::vector<uint32_t>& order)
      : boxes_(boxes), centroids_(centroids), order_(order) {}

  void build(const Range& range, int depth, unsigned threads, std::vector<BvhNode>& out) const {
    const auto index = static_cast<uint32_t>(out.size());
    out.push_back(BvhNode{range.bounds.lo, range.begin, range.bounds.hi, 0, 0, 0});
    const uint32_t n = range.count();
    Split split;
    if (n > 1 && depth < kSahDepthLimit) split = find_split(range);
    const bool sah_prefers_leaf = split.axis < 0 || split.cost >= static_cast<float>(n);
    if (n == 1 || (n <= kMaxLeafSize && sah_prefers_leaf) || depth >= Bvh::kMaxDepth - 1) {
      out[index].count = static_cast<uint16_t>(n);
      return;
    }
    Range left, right;
    if (split.axis >= 0 && depth < kSahDepthLimit) {
      partition(range, split, left, right);
      out[index].axis = static_cast<uint8_t>(split.axis);
    } else {
      median_split(range, left, right);
      out[index].axis = static_cast<uint8_t>(range.centroid_bounds.largest_axis());
    }
    if (threads > 1 && n >= kParallelMinPrims) {
      std::vector<BvhNode> left_nodes, right_nodes;
      {
        std::jthread worker([&] { build(left, depth + 1, threads / 2, left_nodes); });
        build(right, depth + 1, threads - threads / 2, right_nodes);
      }
      splice(out, left_nodes);
      out[index].offset = static_cast<uint32_t>(out.size());
      splice(out, right_nodes);
    } else {
      build(left, depth + 1, threads, out);
      out[index].offset = static_cast<uint32_t>(out.size());
      build(right, depth + 1, threads, out);
    }
  }

 private:
  static int bin_of(float c, float lo, float scale) {
    return std::min(kBins - 1, static_cast<int>((c - lo) * scale));
  }
  static float bin_scale(const Aabb& cb, int axis) { return kBins / (cb.hi[axis] - cb.lo[axis]); }

  Split find_split(const Range& range) const {
    const Aabb& cb = range.centroid_bounds;
    Bin bins[3][kBins];
    float scale[3];
    bool usable[3];
    for (int a = 0; a < 3; ++a) {
      usable[a] = cb.hi[a] > cb.lo[a];
      scale[a] = usable[a] ? bin_scale(cb, a) : 0.0f;
    }
    for (uint32_t i = range.begin; i < range.end; ++i) {
      const uint32_t id = order_[i];
      const Vec3 c = centroids_[id];
      for (int a = 0; a < 3; ++a) {
        Bin& b = bins[a][bin_of(c[a], cb.lo[a], scale[a])];
        b.bounds.extend(boxes_[id]);
        b.centroid_bounds.extend(c);
        ++b.count;
      }
    }
    Split best;
    const float inv_area = 1.0f / std::max(range.bounds.surface_area(), 1e-30f);
    for (int a = 0; a < 3; ++a) {
      if (!usable[a]) continue;
      // Sweep from the right, storing area * count of everything right of each plane.
      float right_cost[kBins];
      Aabb acc;
      uint32_t count = 0;
      for (int k = kBins - 1; k > 0; --k) {
        acc.extend(bins[a][k].bounds);
        count += bins[a][k].count;
        right_cost[k] = count ? acc.surface_area() * static_cast<float>(count) : 0.0f;
      }
      acc = Aabb{};
      count = 0;
      for (int k = 1; k < kBins; ++k) {
        acc.extend(bins[a][k - 1].bounds);
        count += bins[a][k - 1].count;
        if (count == 0 || count == range.count()) continue;
        const float cost = kTraversalCost + (acc.surface_area() * static_cast<float>(count) + right_cost[k]) * inv_area;
        if (cost < best.cost) best = Split{a, k, cost};
      }
    }
    return best;
  }

  void partition(const Range& range, const Split& split, Range& left, Range& right) const {
    const int a = split.axis;
    const float lo = range.centroid_bounds.lo[a];
    const float scale = bin_scale(range.centroid_bounds, a);
    left = Range{range.begin, range.begin, {}, {}};
    right = Range{range.begin, range.end, {}, {}};
    auto mid = std::partition(order_.begin() + range.begin, order_.begin() + range.end,
                              [&](uint32_t id) { return bin_of(centroids_[id][a], lo, scale) < split.bin; });
    left.end = right.begin = static_cast<uint32_t>(mid - order_.begin());
    compute_bounds(left);
    compute_bounds(right);
  }

  // Halves the range along the widest centroid axis; used past the SAH depth limit and when
  // all centroids coincide, so the tree always terminates with small leaves.
  void median_split(const Range& range, Range& left, Range& right) const {
    const int a = range.centroid_bounds.largest_axis();
    const uint32_t mid = range.begin + range.count() / 2;
    std::nth_element(order_.begin() + range.begin, order_.begin() + mid, order_.begin() + range.end,
                     [&](uint32_t x, uint32_t y) {
                       return centroids_[x][a] < centroids_[y][a] || (centroids_[x][a] == centroids_[y][a] && x < y);
                     });
    left = Range{range.begin, mid, {}, {}};
    right = Range{mid, range.end, {}, {}};
    compute_bounds(left);
    compute_bounds(right);
  }

  void compute_bounds(Range& r) const {
    for (uint32_t i = r.begin; i < r.end; ++i) {
      r.bounds.extend(boxes_[order_[i]]);
      r.centroid_bounds.extend(centroids_[order_[i]]);
    }
  }

  // Appends a subtree built into its own array, rebasing its interior links.
  static void splice(std::vector<BvhNode>& out, const std::vector<BvhNode>& sub) {
    const auto base = static_cast<uint32_t>(out.size());
    for (BvhNode node : sub) {
      if (node.count == 0) node.offset += base;
      out.push_back(node);
    }
  }

  const std::vector<Aabb>& boxes_;
  const std::vector<Vec3>& centroids_;
  std::vector<uint32_t>& order_;
};

}  // namespace

Bvh::Bvh(PrimitiveSet prims, const BvhBuildOptions& options) : prims_(std::move(prims)) {
  const uint32_t n = prims_.size();
  if (n == 0) return;
  std::vector<Aabb> boxes(n);
  std::vector<Vec3> centroids(n);
  Range root{0, n, {}, {}};
  for (uint32_t id = 0; id < n; ++id) {
    boxes[id] = prims_.bounds(id);
    centroids[id] = boxes[id].centre();
    root.bounds.extend(boxes[id]);
    root.centroid_bounds.extend(centroids[id]);
  }
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0u);
  nodes_.reserve(2 * static_cast<size_t>(n) / 3 + 1);
  Builder(boxes, centroids, order_).build(root, 0, std::max(1u, options.threads), nodes_);
  nodes_.shrink_to_fit();

  slot_triangles_.resize(n);
  for (uint32_t slot = 0; slot < n; ++slot)
    if (prims_.is_triangle(order_[slot])) slot_triangles_[slot] = prims_.triangles[order_[slot]];
}

Aabb Bvh::bounds() const { return nodes_.empty() ? Aabb{} : Aabb{nodes_[0].lo, nodes_[0].hi}; }

BvhStats Bvh::stats() const {
  BvhStats s;
  s.nodes = nodes_.size();
  if (nodes_.empty()) return s;
  const float root_area = std::max(bounds().surface_area(), 1e-30f);
  struct Item { uint32_t node; int depth; };
  std::vector<Item> stack{{0, 0}};
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    const BvhNode& node = nodes_[it.node];
    const float rel_area = Aabb{node.lo, node.hi}.surface_area() / root_area;
    s.max_depth = std::max(s.max_depth, it.depth);
    if (node.count > 0) {
      ++s.leaves;
      s.sah_cost += rel_area * node.count;
    } else {
      s.sah_cost += rel_area * kTraversalCost;
      stack.push_back({it.node + 1, it.depth + 1});
      stack.push_back({node.offset, it.depth + 1});
    }
  }
  return s;
}

}  // namespace rt
