// BVH construction in two steps.
// 1. A binary tree by binned SAH (Wald, "On fast construction of SAH-based bounding volume
//    hierarchies", 2007): each node bins primitive centroids on all three axes, sweeps the bins
//    for the cheapest split and partitions its slice of the build records in place. Large
//    subtrees are built on spare threads into their own arrays and spliced back in a fixed order,
//    and the largest nodes bin on all spare threads, so the tree is identical whatever the thread
//    count.
// 2. A collapse to kBvhWidth-wide nodes (core/accel/bvh_collapse.cpp).
#include <algorithm>
#include <atomic>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <thread>

#include "core/accel/bvh.h"
#include "core/accel/bvh_binary_tree.h"
#include "core/accel/bvh_bins.h"
#include "core/parallel_for.h"
#include "core/simd.h"

namespace rt {
namespace {

// Larger leaves are always split (<= BvhRef::kMaxLeafCount). A mesh's leaves hold up to three
// quads, which lie side by side in memory: on the stone, incoherent rays ran 1.09x and shadow rays
// 1.03x what they did with at most two (docs/benchmark.md, "Round two, a twentieth session"). A
// top level's objects, each tested alone, stay at eight.
constexpr uint32_t kMaxQuadLeafSize = 12;
constexpr uint32_t kMaxObjectLeafSize = 8;
constexpr int kSahDepthLimit = 32;            // deeper nodes use median splits, so depth < Bvh::kMaxDepth
constexpr uint32_t kParallelMinPrims = 4096;  // smaller subtrees are not worth starting a thread
// Nodes this large bin their primitives on every spare thread: the root's binning (4 ms of a
// 300k-triangle build) otherwise leaves the other threads waiting.
constexpr uint32_t kParallelBinPrims = 65536;
static_assert(kMaxQuadLeafSize <= BvhRef::kMaxLeafCount && kMaxObjectLeafSize <= BvhRef::kMaxLeafCount);

// One primitive during the build: its box as two 4-lane vectors, the id riding in the unused
// fourth lane of `lo`. The id's bits are offset into the range of normal floats (2.0 and up): raw
// small integers would be denormals, which the centroid sum would then compute with, very slowly
// on some CPUs. Records are partitioned in place, so every pass reads memory in order.
struct alignas(32) BuildPrim {
  static constexpr uint32_t kIdBias = 0x40000000u;  // the bits of 2.0f
  Float4 lo;                                        // x, y, z, (biased id bits)
  Float4 hi;                                        // x, y, z, 0

  static BuildPrim make(const Aabb& box, uint32_t id) {
    BuildPrim p{Float4{box.lo.x, box.lo.y, box.lo.z, 0.0f}, Float4{box.hi.x, box.hi.y, box.hi.z, 0.0f}};
    const uint32_t bits = id + kIdBias;
    std::memcpy(reinterpret_cast<char*>(&p.lo) + 12, &bits, 4);
    return p;
  }
  uint32_t id() const {
    uint32_t bits;
    std::memcpy(&bits, reinterpret_cast<const char*>(&lo) + 12, 4);
    return bits - kIdBias;
  }
  // Half of each corner, added: lo + hi would overflow to infinity for boxes near the float limit.
  Float4 centroid() const { return splat4(0.5f) * lo + splat4(0.5f) * hi; }
};

struct Range {
  uint32_t begin = 0, end = 0;
  Box4 bounds = Box4::empty(), centroids = Box4::empty();
  uint32_t count() const { return end - begin; }
};

class BinaryBuilder {
 public:
  // `spare_threads`: how many more threads may run at once. A large node hands its right subtree
  // to a new thread while one is spare, and the thread is spare again when that subtree is done,
  // so work moves to wherever it remains. Every handed-off subtree is built into its own array
  // and spliced back in place, which gives exactly the array a single thread would write.
  // `block`: primitives a leaf tests at once (4: triangles, as quads). The SAH counts a leaf's cost
  // in blocks, as Embree's builders do, so that leaves fill their quads.
  BinaryBuilder(BuildPrim* prims, unsigned spare_threads, uint32_t block)
      : prims_(prims), spare_threads_(spare_threads), block_(block) {}

  void build(const Range& range, int depth, std::vector<BinaryNode>& out) {
    const auto index = static_cast<uint32_t>(out.size());
    out.push_back(BinaryNode{range.bounds.aabb(), range.begin, 0});
    const uint32_t n = range.count();
    Split split;
    if (n > 1 && depth < kSahDepthLimit) split = find_split(range);
    const bool sah_prefers_leaf = split.axis < 0 || split.cost >= leaf_tests(n, block_);
    const uint32_t max_leaf = block_ == 1 ? kMaxObjectLeafSize : kMaxQuadLeafSize;
    if (n == 1 || (n <= max_leaf && sah_prefers_leaf) || depth >= Bvh::kMaxDepth - 1) {
      out[index].count = n;
      return;
    }
    Range left, right;
    if (split.axis >= 0) partition(range, split, left, right);
    else median_split(range, left, right);
    if (n >= kParallelMinPrims && take_spare_thread()) {
      // The right subtree on the new thread, into an array of its own with room for the most
      // nodes it can have (2m - 1 for m primitives: never regrown), appended once the left one
      // is in place; the left subtree goes straight into `out`, so only half is ever copied.
      std::vector<BinaryNode> right_nodes;
      right_nodes.reserve(2 * static_cast<size_t>(right.count()));
      {
        std::jthread worker([&] {
          build(right, depth + 1, right_nodes);
          ++spare_threads_;
        });
        build(left, depth + 1, out);
      }
      out[index].offset = static_cast<uint32_t>(out.size());
      splice(out, right_nodes);
    } else {
      build(left, depth + 1, out);
      out[index].offset = static_cast<uint32_t>(out.size());
      build(right, depth + 1, out);
    }
  }

 private:
  // The primitives of [begin, end) added to `bins`.
  void bin(uint32_t begin, uint32_t end, const Binner& binner, Bins& bins) const {
    for (uint32_t i = begin; i < end; ++i) {
      const BuildPrim& p = prims_[i];
      const Int4 k = binner.bins(p.centroid());
      for (int a = 0; a < 3; ++a) {
        Bin& b = bins[a][k[a]];
        b.bounds.extend(p.lo, p.hi);
        ++b.count;
      }
    }
  }

  static void clear(Bins& bins, int nb) {
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < nb; ++k) bins[a][k] = Bin{Box4::empty(), 0};
  }

  // A large node's binning in runs of primitives on the spare threads, each into its own bins,
  // then merged: boxes by min and max and counts by sums, so the bins (and the split) are exactly
  // those of one thread.
  void bin_all(const Range& range, const Binner& binner, Bins& bins) {
    const int nb = binner.count;
    clear(bins, nb);
    unsigned helpers = 0;
    if (range.count() >= kParallelBinPrims)
      while (helpers < kMaxBinWorkers - 1 && take_spare_thread()) ++helpers;
    if (helpers == 0) {
      bin(range.begin, range.end, binner, bins);
      return;
    }
    constexpr uint32_t kRun = 16384;
    Bins worker_bins[kMaxBinWorkers];
    for (unsigned w = 0; w <= helpers; ++w) clear(worker_bins[w], nb);
    parallel_for((range.count() + kRun - 1) / kRun, helpers + 1, 1, [&](unsigned w, size_t run) {
      const uint32_t begin = range.begin + static_cast<uint32_t>(run) * kRun;
      bin(begin, std::min(range.end, begin + kRun), binner, worker_bins[w]);
    });
    spare_threads_ += helpers;
    for (unsigned w = 0; w <= helpers; ++w)
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < nb; ++k) {
          bins[a][k].bounds.extend(worker_bins[w][a][k].bounds);
          bins[a][k].count += worker_bins[w][a][k].count;
        }
  }

  Split find_split(const Range& range) {
    const Binner binner(range.centroids, range.count());
    Bins bins;
    bin_all(range, binner, bins);
    return sah_sweep(bins, binner.count, range.bounds, block_);
  }

  // Hoare-style partition by bin; gathers each side's centroid bounds on the way.
  void partition(const Range& range, const Split& split, Range& left, Range& right) const {
    const Binner binner(range.centroids, range.count());
    const auto goes_left = [&](const BuildPrim& p) { return binner.bins(p.centroid())[split.axis] < split.bin; };
    Box4 left_centroids = Box4::empty(), right_centroids = Box4::empty();
    uint32_t i = range.begin, j = range.end;
    while (true) {
      for (; i < j && goes_left(prims_[i]); ++i) left_centroids.extend(prims_[i].centroid(), prims_[i].centroid());
      for (; i < j && !goes_left(prims_[j - 1]); --j)
        right_centroids.extend(prims_[j - 1].centroid(), prims_[j - 1].centroid());
      if (i >= j) break;
      std::swap(prims_[i], prims_[j - 1]);
    }
    left = Range{range.begin, i, split.left_bounds, left_centroids};
    right = Range{i, range.end, split.right_bounds, right_centroids};
  }

  // Halves the range along the widest centroid axis: used past the SAH depth limit and when no
  // bin boundary separates the centroids, so the tree always ends in small leaves.
  void median_split(const Range& range, Range& left, Range& right) const {
    const Float4 extent = range.centroids.hi - range.centroids.lo;
    const int a = (extent[0] >= extent[1] && extent[0] >= extent[2]) ? 0 : (extent[1] >= extent[2] ? 1 : 2);
    const uint32_t mid = range.begin + range.count() / 2;
    std::nth_element(prims_ + range.begin, prims_ + mid, prims_ + range.end,
                     [&](const BuildPrim& x, const BuildPrim& y) {
                       const float cx = x.centroid()[a], cy = y.centroid()[a];
                       return cx < cy || (cx == cy && x.id() < y.id());
                     });
    // Box4 has no default member initialisers: `{}` would be a zero box, which extend() would
    // stretch to include the origin.
    left = Range{range.begin, mid, Box4::empty(), Box4::empty()};
    right = Range{mid, range.end, Box4::empty(), Box4::empty()};
    for (Range* r : {&left, &right})
      for (uint32_t k = r->begin; k < r->end; ++k) {
        r->bounds.extend(prims_[k].lo, prims_[k].hi);
        r->centroids.extend(prims_[k].centroid(), prims_[k].centroid());
      }
  }

  // Appends a subtree built into its own array, rebasing its interior links.
  static void splice(std::vector<BinaryNode>& out, const std::vector<BinaryNode>& sub) {
    const auto base = static_cast<uint32_t>(out.size());
    for (BinaryNode node : sub) {
      if (node.count == 0) node.offset += base;
      out.push_back(node);
    }
  }

  bool take_spare_thread() {
    unsigned spare = spare_threads_.load();
    while (spare > 0)
      if (spare_threads_.compare_exchange_weak(spare, spare - 1)) return true;
    return false;
  }

  static constexpr unsigned kMaxBinWorkers = 8;
  BuildPrim* prims_;
  std::atomic<unsigned> spare_threads_;
  uint32_t block_;
};

double binary_sah_cost(const std::vector<BinaryNode>& nodes, uint32_t block) {
  const double root_area = std::max(half_area(nodes[0].bounds), 1e-300);
  double cost = 0.0;
  for (const BinaryNode& n : nodes)
    cost += half_area(n.bounds) / root_area * (n.count ? leaf_tests(n.count, block) : double{kTraversalCost});
  return cost / kTraversalCost;  // in node visits (BvhStats)
}

}  // namespace

Bvh::Bvh(const PrimitiveSet& prims, const BvhBuildOptions& options)
    : kernels_(&bvh_kernels(options.isa)),
      ranges_(prims.ranges()),
      shapes_(prims.shapes),
      instances_(prims.instances),
      csgs_(prims.csgs),
      owners_(prims.owners) {
  const uint32_t total = prims.size();
  if (total > BvhRef::kMaxFirst) throw std::length_error("more primitives than the BVH can address (2^26)");
  // The ids the tree holds: all of them, but for flattened instances, whose triangles are there
  // in their place. Empty: every id, in order (a mesh's BVH, or a top level with none flattened).
  std::vector<uint32_t> held;
  if (std::any_of(instances_.begin(), instances_.end(), [](const MeshInstance& i) { return i.flattened; }))
    for (uint32_t id = 0; id < total; ++id)
      if (prims.kind(id) != PrimitiveKind::kInstance || !prims.instance(id).flattened) held.push_back(id);
  const uint32_t n = held.empty() ? total : static_cast<uint32_t>(held.size());
  if (n == 0) return;
  // The build records are written on all threads, each worker a contiguous share, so that their
  // pages are first touched in parallel; the root's boxes are merged from the workers' own (min
  // and max: the same whatever the split).
  // A small build is done on the calling thread: starting threads costs more than it saves (the
  // 120 shapes of antialias.json: four threads started, 1-2 ms of a 25 ms run). The tree is the
  // same either way.
  constexpr uint32_t kThreadedBuildMin = 4096;
  const unsigned threads = n < kThreadedBuildMin ? 1u : std::max(1u, options.threads);
  std::unique_ptr<BuildPrim[]> records(new BuildPrim[n]);  // not value-initialised: written once below
  std::vector<Range> shares(threads);
  std::atomic<uint32_t> bad{total};
  run_workers(threads, [&](unsigned w) {
    Range share;  // on this thread's stack: written to `shares` once, as neighbours there share cache lines
    const uint32_t begin = static_cast<uint32_t>(uint64_t{n} * w / threads);
    const uint32_t end = static_cast<uint32_t>(uint64_t{n} * (w + 1) / threads);
    for (uint32_t i = begin; i < end; ++i) {
      const uint32_t id = held.empty() ? i : held[i];
      const Aabb box = prims.bounds(id);
      // Callers check their input (io reports a located error); this is the last line of defence.
      const bool finite_triangle = prims.kind(id) != PrimitiveKind::kTriangle || prims.triangles[id].is_finite();
      if (!finite_triangle || !is_finite(box.lo) || !is_finite(box.hi) || box.empty()) {
        uint32_t first = bad.load();
        while (id < first && !bad.compare_exchange_weak(first, id)) {
        }
        return;
      }
      const BuildPrim& p = records[i] = BuildPrim::make(box, id);
      share.bounds.extend(p.lo, p.hi);
      share.centroids.extend(p.centroid(), p.centroid());
    }
    shares[w] = share;
  });
  if (bad.load() < total)
    throw std::invalid_argument("primitive " + std::to_string(bad.load()) + " has bounds that are not finite");
  Range root{0, n, {}, {}};
  for (const Range& share : shares) {
    root.bounds.extend(share.bounds);
    root.centroids.extend(share.centroids);
  }
  std::vector<BinaryNode> binary;
  binary.reserve(2 * static_cast<size_t>(n));  // the most a tree of n leaves can have: never regrown
  // Triangles alone (a mesh's, or a top level of flattened instances only) are counted four a
  // quad leaf.
  const bool triangles_only =
      prims.shapes.empty() && prims.csgs.empty() &&
      std::all_of(instances_.begin(), instances_.end(), [](const MeshInstance& i) { return i.flattened; });
  const uint32_t block = triangles_only ? 4 : 1;
  BinaryBuilder(records.get(), threads - 1, block).build(root, 0, binary);
  bounds_ = root.bounds.aabb();
  binary_sah_cost_ = binary_sah_cost(binary, block);
  nodes_.reserve(binary.size() / kBvhWidth + 1);  // interior nodes / (width / 2): seldom regrown
  root_ = collapse_binary_tree(binary, threads, nodes_);

  // The primitives in build order, for the leaves' arrays.
  FillVector<uint32_t> order(n);
  parallel_for(n, threads, 4096, [&](unsigned, size_t i) { order[i] = records[i].id(); });
  fill_leaves(prims, order.data(), threads);
  interiors_ = find_shape_interiors(*this);
}

}  // namespace rt
