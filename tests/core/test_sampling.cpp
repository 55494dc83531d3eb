// The sample sequences: Owen-scrambled Sobol pairs keep the (0, 2)-sequence's stratification, and
// the keyed streams are what a pixel's samples read.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "core/direction_sampling.h"
#include "core/lights/stratified_grid_batch.h"
#include "core/owen_sobol.h"
#include "core/sampling.h"

using namespace rt;

namespace {

// Whether the points fill every elementary interval of area 1 / points.size() (2^k points:
// every 2^a x 2^b grid of cells with a + b = k) exactly once.
bool is_net(const std::vector<Vec2>& points) {
  int k = 0;
  while ((size_t{1} << k) < points.size()) ++k;
  for (int a = 0; a <= k; ++a) {
    const int cols = 1 << a, rows = 1 << (k - a);
    std::set<int> cells;
    for (const Vec2 p : points)
      cells.insert(static_cast<int>(p.y * static_cast<float>(rows)) * cols +
                   static_cast<int>(p.x * static_cast<float>(cols)));
    if (cells.size() != points.size()) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("Owen scrambling is a permutation that keeps blocks of indices together", "[sampling]") {
  // Every aligned block of 16 indices maps onto an aligned block of 16 (bits are flipped by the
  // bits above them only), so a shuffled index run of 2^k is still a run of 2^k points.
  for (uint32_t seed : {1u, 0x9e3779b9u, 12345u}) {
    std::set<uint32_t> images, blocks;
    for (uint32_t i = 0; i < 256; ++i) {
      const uint32_t v = owen_scramble(i << 24, seed);
      images.insert(v);
      if (i < 16) blocks.insert(v >> 28);
    }
    CHECK(images.size() == 256);
    CHECK(blocks.size() == 1);
  }
  CHECK(reverse_bits(1u) == 0x80000000u);
  CHECK(reverse_bits(0x0000f00du) == 0xb00f0000u);
}

TEST_CASE("Sobol's first two dimensions make a (0, 2)-sequence, scrambled or not", "[sampling]") {
  CHECK(sobol_dimension1(1) == 0x80000000u);
  CHECK(sobol_dimension1(2) == 0xc0000000u);
  CHECK(sobol_dimension1(3) == 0x40000000u);
  for (const uint32_t n : {16u, 64u, 256u, 1024u}) {
    std::vector<Vec2> plain, scrambled;
    for (uint32_t i = 0; i < n; ++i) {
      plain.push_back(Vec2(unit_float(sobol_dimension0(i)), unit_float(sobol_dimension1(i))));
      scrambled.push_back(owen_sobol2(i, 0x1234567u, 0xdeadbeefu, 0x7654321u));
    }
    CHECK(is_net(plain));
    CHECK(is_net(scrambled));
    // A second run of n points (n..2n-1) is a net too: a pixel's later samples fill in evenly.
    std::vector<Vec2> next;
    for (uint32_t i = n; i < 2 * n; ++i) next.push_back(owen_sobol2(i, 99u, 7u, 3u));
    CHECK(is_net(next));
  }
}

TEST_CASE("Sobol's second dimension by superset sums is the bit-by-bit definition, for every bit", "[sampling]") {
  for (uint32_t bit = 0; bit < 32; ++bit) CHECK(sobol_dimension1(1u << bit) == sobol_dimension1_bitwise(1u << bit));
  uint32_t x = 0x9e3779b9u;
  for (int i = 0; i < 100000; ++i) {
    x = x * 1664525u + 1013904223u;  // every bit of the index in play
    REQUIRE(sobol_dimension1(x) == sobol_dimension1_bitwise(x));
    REQUIRE(sobol_dimension1_reversed(x) == reverse_bits(sobol_dimension1_bitwise(x)));
  }
  CHECK(sobol_dimension1(0xffffffffu) == sobol_dimension1_bitwise(0xffffffffu));
  CHECK(sobol_dimension1(0) == 0u);
  // Eight lanes at once (the batch's form), each its own index's.
  Uint8 lanes;
  for (int j = 0; j < 8; ++j) lanes[j] = 0x01000193u * static_cast<uint32_t>(j + 1) ^ (1u << (4 * j));
  const Uint8 reversed = sobol_dimension1_reversed(lanes);
  for (int j = 0; j < 8; ++j) CHECK(reversed[j] == reverse_bits(sobol_dimension1_bitwise(lanes[j])));
}

TEST_CASE("a pixel's Sobol samples stratify every pair of dimensions, independent ones do not", "[sampling]") {
  const auto points = [](SampleSequence sequence, SamplePurpose purpose, uint64_t path, uint64_t index) {
    std::vector<Vec2> p;
    for (uint32_t s = 0; s < 64; ++s) p.push_back(SampleStream(7, 2, 1234, s, sequence).get2(purpose, path, index));
    return p;
  };
  CHECK(is_net(points(SampleSequence::kSobol, SamplePurpose::kPixel, 0, 0)));
  CHECK(is_net(points(SampleSequence::kSobol, SamplePurpose::kBsdf, 3, 1)));
  CHECK(is_net(points(SampleSequence::kSobol, SamplePurpose::kLight, 5, light_dimension(2, 7))));
  CHECK_FALSE(is_net(points(SampleSequence::kIndependent, SamplePurpose::kPixel, 0, 0)));
  // Pairs are decorrelated: two dimensions of the same sample do not repeat each other.
  const std::vector<Vec2> a = points(SampleSequence::kSobol, SamplePurpose::kBsdf, 0, 0);
  const std::vector<Vec2> b = points(SampleSequence::kSobol, SamplePurpose::kBsdf, 1, 0);
  int same = 0;
  for (size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
  CHECK(same == 0);
  // Another pixel draws another scramble of the sequence.
  CHECK(SampleStream(7, 2, 1234, 0).get2(SamplePurpose::kPixel, 0, 0) !=
        SampleStream(7, 2, 1235, 0).get2(SamplePurpose::kPixel, 0, 0));
}

TEST_CASE("sampling: the tabled dimension keys are the mixed ones, inside the table and out", "[sampling]") {
  for (uint32_t p = 1; p <= static_cast<uint32_t>(SamplePurpose::kWavelength); ++p)
    for (const uint64_t path : std::initializer_list<uint64_t>{0, 1, 7, 15, 16, 0x9e3779b97f4a7c15ull})
      for (const uint64_t index :
           std::initializer_list<uint64_t>{0, 1, 15, 16, light_dimension(1, 3), light_dimension(0, 63)}) {
        const auto purpose = static_cast<SamplePurpose>(p);
        INFO("purpose " << p << ", path " << path << ", index " << index);
        CHECK(tabled_dimension_key(purpose, path, index) ==
              mix64(path ^ mix64((static_cast<uint64_t>(p) << 56) ^ index)));
      }
}

TEST_CASE("sampling: get2_batch gives get2's numbers, 1 to 16 at a time, both sequences", "[sampling]") {
  for (const SampleSequence sequence : {SampleSequence::kSobol, SampleSequence::kIndependent})
    for (const uint32_t sample : {0u, 1u, 5u, 255u, 70000u})
      for (const uint64_t path : std::initializer_list<uint64_t>{0, 3, 16, 0x9e3779b97f4a7c15ull})
        for (const uint64_t first : {light_dimension(0, 0), light_dimension(0, 8), light_dimension(0, 12),
                                     light_dimension(2, 0), light_dimension(1, 1016)})
          for (const int count : {1, 5, 8, 9, 16}) {
            const SampleStream stream(11, 3, 4567, sample, sequence);
            float x[kMaxSobolPairs + 1], y[kMaxSobolPairs + 1];
            x[count] = y[count] = -1.0f;  // past the count: left alone
            stream.get2_batch(SamplePurpose::kLight, path, first, count, x, y);
            int differ = 0;
            for (int j = 0; j < count; ++j) {
              const Vec2 u = stream.get2(SamplePurpose::kLight, path, first + static_cast<uint64_t>(j));
              differ += u.x != x[j] || u.y != y[j];
            }
            INFO("sample " << sample << ", path " << path << ", first index " << first << ", count " << count);
            CHECK(differ == 0);
            CHECK(x[count] == -1.0f);
            CHECK(y[count] == -1.0f);
          }
}

TEST_CASE("sampling: stratified_points_batch gives StratifiedGrid::point's floats, eight at a time", "[sampling]") {
  // Every grid of 1 to 1024 samples (the shadow_samples a scene may ask), each batch of eight
  // from sample 0 past the grid's end, and near 2^22 where the quotient's float is tightest.
  uint64_t state = 5;
  const auto unit = [&state] { return static_cast<float>(mix64(++state) >> 40) * 0x1p-24f; };
  long differ = 0, tested = 0;
  for (int n = 1; n <= 1024; ++n) {
    const StratifiedGrid grid(n);
    std::vector<int> firsts;
    for (int first = 0; first < n; first += kPacketSize) firsts.push_back(first);
    firsts.push_back((1 << 22) - kPacketSize);
    for (const int first : firsts) {
      alignas(32) float jx[kPacketSize], jy[kPacketSize];
      for (int j = 0; j < kPacketSize; ++j) {
        jx[j] = j == 0 ? 0.0f : j == 1 ? 0x1.fffffep-1f : unit();  // the ends of [0, 1) too
        jy[j] = j == 0 ? 0x1.fffffep-1f : j == 1 ? 0.0f : unit();
      }
      float u[2][kPacketSize];
      stratified_points_batch(grid, first, jx, jy, u);
      for (int j = 0; j < kPacketSize; ++j) {
        const Vec2 p = grid.point(first + j, Vec2(jx[j], jy[j]));
        ++tested;
        differ += p.x != u[0][j] || p.y != u[1][j];
      }
    }
  }
  CHECK(tested > 70000);
  CHECK(differ == 0);
}

TEST_CASE("Owen-Sobol: eight lanes of reverse_bits and upward_hash are the scalar ones", "[sampling]") {
  Uint8 x, seed;
  uint32_t v = 0x12345678u;
  for (int round = 0; round < 1000; ++round) {
    for (int j = 0; j < 8; ++j) {
      v = v * 1664525u + 1013904223u;
      x[j] = v;
      seed[j] = v ^ 0xa5a5a5a5u;
    }
    const Uint8 reversed = reverse_bits(x), hashed = upward_hash(x, seed);
    for (int j = 0; j < 8; ++j) {
      REQUIRE(reversed[j] == reverse_bits(x[j]));
      REQUIRE(hashed[j] == upward_hash(x[j], seed[j]));
    }
  }
}

TEST_CASE("direction sampling: the quarter-range cos and sin are within 2 ulp of the library's", "[sampling]") {
  // Every float angle in [-pi/4, pi/4] would take long; a million evenly spaced ones and the ends.
  const auto ulps = [](float got, double want) {
    const float w = static_cast<float>(want);
    const float step = std::nextafter(std::fabs(w), 2.0f) - std::fabs(w);
    return std::fabs(static_cast<double>(got) - want) / step;
  };
  double worst_cos = 0.0, worst_sin = 0.0;
  constexpr int kSteps = 1 << 20;
  for (int i = 0; i <= kSteps; ++i) {
    const float x = -kPi / 4.0f + (kPi / 2.0f) * static_cast<float>(i) / static_cast<float>(kSteps);
    const Vec2 cs = cos_sin_quarter(x);
    worst_cos = std::max(worst_cos, ulps(cs.x, std::cos(static_cast<double>(x))));
    if (x != 0.0f) worst_sin = std::max(worst_sin, ulps(cs.y, std::sin(static_cast<double>(x))));
  }
  CHECK(worst_cos < 2.0);
  CHECK(worst_sin < 2.0);
  CHECK(cos_sin_quarter(0.0f) == Vec2(1.0f, 0.0f));
  // The disk's points keep their radius: |p| is max(|a|, |b|) for the square's point (a, b).
  const Vec2 p = concentric_disk(Vec2(0.9f, 0.3f));
  CHECK(glm::length(p) == Approx(0.8f).epsilon(1e-6));
  const Vec2 q = concentric_disk(Vec2(0.55f, 0.05f));  // |b| > |a|: measured from the y axis
  CHECK(glm::length(q) == Approx(0.9f).epsilon(1e-6));
  CHECK(q.y < 0.0f);
  CHECK(std::fabs(q.x) < std::fabs(q.y));
}

TEST_CASE("sampling: a point's key made once gives its samples the numbers they had", "[sampling]") {
  const SampleStream::FrameKey frame = SampleStream::frame_key(11, 3);
  for (const SampleSequence sequence : {SampleSequence::kSobol, SampleSequence::kIndependent})
    for (const uint64_t point : std::initializer_list<uint64_t>{0, 4567, uint64_t{1} << 62}) {
      const SampleStream::PointKey key = SampleStream::point_key(frame, point);
      std::set<float> seen;
      for (const uint32_t sample : {0u, 1u, 2u, 3u, 70000u}) {
        const SampleStream whole(11, 3, point, sample, sequence), keyed(key, sample, sequence);
        for (const uint64_t index : {0u, 1u, 9u}) {
          const Vec2 a = whole.get2(SamplePurpose::kPixel, 0, index), b = keyed.get2(SamplePurpose::kPixel, 0, index);
          INFO("sequence " << static_cast<int>(sequence) << ", point " << point << ", sample " << sample);
          CHECK(a.x == b.x);
          CHECK(a.y == b.y);
          CHECK(whole.get1(SamplePurpose::kLight, 5, index) == keyed.get1(SamplePurpose::kLight, 5, index));
        }
        seen.insert(keyed.get2(SamplePurpose::kPixel, 0, 0).x);
      }
      CHECK(seen.size() == 5);  // each sample its own numbers, in either sequence
    }
}
