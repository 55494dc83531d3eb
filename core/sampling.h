// Keyed sample numbers and stratification. Every number a render uses is named by what it is for:
// the sample's key (seed, frame, pixel or lattice point), its purpose (lens, light, glossy, ...),
// the path through the ray tree that asks (bounce by bounce) and an index; the pair of dimensions
// those name is drawn at the sample's number. Nothing is drawn from a sequential stream, so adding
// shadow samples does not reshuffle glossy noise, and the image never depends on which thread
// traced what (docs/rendering.md, "Random numbers").
//
// Two sequences (render.sampler): Owen-scrambled Sobol (the default; core/owen_sobol.h), whose
// points for samples 0..n-1 of a pixel cover each pair of dimensions evenly, and independent
// hashes, every number on its own (the images of rtcli before 0.9, kept for comparison).
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>

#include "core/math.h"
#include "core/owen_sobol.h"
#include "core/owen_sobol_batch.h"
#include "core/rng.h"

namespace rt {

enum class SamplePurpose : uint32_t { kPixel = 1, kLens, kLight, kGlossy, kBsdf, kRoulette, kWavelength };

// render.sampler: how a pixel's samples draw their numbers (names in core/render_settings.h).
enum class SampleSequence { kSobol, kIndependent };

// The key of the pair of dimensions (purpose, path, index) names, mix64(path ^ mix64(purpose,
// index)): the same for every pixel and sample, so the most asked are tabled at compile time
// (16 KiB): paths 0-15 (the camera ray's hits in Whitted, the path tracer's bounces) and indices
// 0-15 (a BSDF's two pairs, the first light's shadow samples up to 16). Two of the five 64-bit
// mixes of a soft shadow's light sample went there.
constexpr uint64_t dimension_key(SamplePurpose purpose, uint64_t path, uint64_t index) {
  return mix64(path ^ mix64((static_cast<uint64_t>(purpose) << 56) ^ index));
}
struct DimensionKeys {
  static constexpr int kPurposes = 8, kPaths = 16, kIndices = 16;
  uint64_t keys[kPurposes][kPaths][kIndices];
};
constexpr DimensionKeys make_dimension_keys() {
  DimensionKeys t{};
  for (int p = 0; p < DimensionKeys::kPurposes; ++p)
    for (int path = 0; path < DimensionKeys::kPaths; ++path)
      for (int i = 0; i < DimensionKeys::kIndices; ++i)
        t.keys[p][path][i] =
            dimension_key(static_cast<SamplePurpose>(p), static_cast<uint64_t>(path), static_cast<uint64_t>(i));
  return t;
}
inline constexpr DimensionKeys kDimensionKeys = make_dimension_keys();

inline uint64_t tabled_dimension_key(SamplePurpose purpose, uint64_t path, uint64_t index) {
  const auto p = static_cast<uint64_t>(purpose);
  if (p < DimensionKeys::kPurposes && path < DimensionKeys::kPaths && index < DimensionKeys::kIndices)
    return kDimensionKeys.keys[p][path][index];
  return dimension_key(purpose, path, index);
}

class SampleStream {
 public:
  SampleStream() = default;
  // What a render's seed and frame make of every point's key, worked out once for many samples.
  struct FrameKey {
    uint64_t key = 0;
  };
  static FrameKey frame_key(uint64_t seed, uint32_t frame) { return {mix64(mix64(seed) ^ frame)}; }
  // And of one point (a pixel), worked out once for its samples.
  struct PointKey {
    uint64_t key = 0;
  };
  static PointKey point_key(FrameKey frame, uint64_t point) { return {mix64(frame.key ^ point)}; }
  // The numbers of one camera sample: the same for the same (seed, frame, point, sample) anywhere.
  SampleStream(uint64_t seed, uint32_t frame, uint64_t point, uint32_t sample,
               SampleSequence sequence = SampleSequence::kSobol)
      : SampleStream(frame_key(seed, frame), point, sample, sequence) {}
  SampleStream(FrameKey frame, uint64_t point, uint32_t sample, SampleSequence sequence = SampleSequence::kSobol)
      : SampleStream(point_key(frame, point), sample, sequence) {}
  SampleStream(PointKey point, uint32_t sample, SampleSequence sequence = SampleSequence::kSobol)
      : point_key_(point.key),
        // Only the independent sequence reads it: not hashed for the Sobol points.
        key_(sequence == SampleSequence::kSobol ? 0 : mix64(point_key_ ^ sample)),
        reversed_sample_(reverse_bits(sample)),
        sequence_(sequence) {}

  // Two numbers in [0, 1) for (purpose, path, index); `path` identifies the ray's place in the
  // tree (see child_path), `index` the sample within its purpose (light_dimension...).
  Vec2 get2(SamplePurpose purpose, uint64_t path, uint64_t index) const {
    const uint64_t dimension = tabled_dimension_key(purpose, path, index);
    if (sequence_ == SampleSequence::kSobol) {
      // The pair's seeds, the same for every sample of the point: its samples are one sequence.
      const uint64_t h = mix64(point_key_ ^ dimension);
      const uint32_t i = shuffled_index(reversed_sample_, static_cast<uint32_t>(h));
      return Vec2(owen_sobol_x(i, static_cast<uint32_t>(h >> 32)), owen_sobol_y(i, static_cast<uint32_t>(mix64(h))));
    }
    const uint64_t h = mix64(key_ ^ dimension);
    return Vec2(static_cast<float>(h >> 40) * 0x1p-24f, static_cast<float>((h >> 16) & 0xffffffu) * 0x1p-24f);
  }
  // get2(purpose, path, first + j) for j in [0, count), into x[j] and y[j], count at most
  // kMaxSobolPairs: the same numbers, the Sobol sequence's work for all of them at once in vector
  // registers (core/owen_sobol_batch.h; a soft shadow's 16 samples a point spent a quarter of the
  // render in get2).
  void get2_batch(SamplePurpose purpose, uint64_t path, uint64_t first, int count, float* x, float* y) const {
    if (sequence_ != SampleSequence::kSobol) {
      for (int j = 0; j < count; ++j) {
        const Vec2 u = get2(purpose, path, first + static_cast<uint64_t>(j));
        x[j] = u.x;
        y[j] = u.y;
      }
      return;
    }
    assert(count <= kMaxSobolPairs);
    uint64_t dimension[kMaxSobolPairs];
    for (int j = 0; j < count; ++j)
      dimension[j] = tabled_dimension_key(purpose, path, first + static_cast<uint64_t>(j));
    owen_sobol_pairs(point_key_, dimension, count, reversed_sample_, x, y);
  }
  // get2(...).x alone, for a choice that needs one number (a lobe, a light, roulette): the same
  // value, without the second coordinate's work.
  float get1(SamplePurpose purpose, uint64_t path, uint64_t index) const {
    if (sequence_ != SampleSequence::kSobol) return get2(purpose, path, index).x;
    const uint64_t dimension = tabled_dimension_key(purpose, path, index);
    const uint64_t h = mix64(point_key_ ^ dimension);
    return owen_sobol_x(shuffled_index(reversed_sample_, static_cast<uint32_t>(h)), static_cast<uint32_t>(h >> 32));
  }

 private:
  uint64_t point_key_ = 0;        // (seed, frame, point)
  uint64_t key_ = 0;              // and the sample: the independent sequence's key
  uint32_t reversed_sample_ = 0;  // its bits mirrored, where the Sobol points start
  SampleSequence sequence_ = SampleSequence::kSobol;
};

// The index of sample `sample` of light `light` among a purpose's numbers (SamplePurpose::kLight):
// the one layout Whitted's shadow samples and the path tracer's light list share.
inline uint64_t light_dimension(uint64_t light, uint32_t sample = 0) { return light << 32 | sample; }

// The path id of a child ray: which kind of branch (reflection, refraction, glossy, ...) and its
// index among its siblings. The camera ray's path is 0.
inline uint64_t child_path(uint64_t parent, uint32_t branch, uint32_t index) {
  return mix64(parent + 0x9e3779b97f4a7c15ull * (static_cast<uint64_t>(branch) << 32 | index) + 1);
}

// n samples stratified over the unit square: a rows x cols grid, one jittered sample per cell.
// n = 4, 9, 16, 64 give sqrt(n) x sqrt(n); other counts the squarest grid with enough cells
// (8 -> 2 x 4; 7 -> 2 x 4 with one cell unused).
struct StratifiedGrid {
  int rows = 1, cols = 1;

  explicit StratifiedGrid(int n) {
    rows = std::max(1, static_cast<int>(std::sqrt(static_cast<float>(n)) + 1e-4f));
    cols = (n + rows - 1) / rows;
  }
  // Sample `index` of the grid, jittered by j in [0, 1)^2: a point of the unit square.
  Vec2 point(int index, Vec2 j) const {
    const int row = index / cols, col = index % cols;
    return Vec2((static_cast<float>(col) + j.x) / static_cast<float>(cols),
                (static_cast<float>(row) + j.y) / static_cast<float>(rows));
  }
};

}  // namespace rt
