// Up to sixteen Owen-scrambled Sobol pairs at once (SampleStream::get2_batch): the scalar
// functions of core/owen_sobol.h lane by lane, the same bits. Compiled for x86-64's baseline, for
// AVX2 and for x86-64-v4 (GCC's target_clones: the loader picks the one this CPU runs, once);
// integer work only, so each gives the same numbers. In the baseline's 4-lane registers a soft-shadow render spent a
// fifth of its time here; sixteen lanes at once overlap two chains of dependent multiplies
// (docs/benchmark.md, "Round two, a sixth session").
#pragma once

#include <cstdint>

namespace rt {

constexpr int kMaxSobolPairs = 16;

// Pair j < count (at most kMaxSobolPairs): the sample's point key mixed with dimension[j] (the
// pair's key), its index shuffled from `reversed_sample` and both coordinates scrambled into x[j]
// and y[j], as SampleStream::get2 makes them.
void owen_sobol_pairs(uint64_t point_key, const uint64_t* dimension, int count, uint32_t reversed_sample, float* x,
                      float* y);

}  // namespace rt
