// A 64-bit mixer and a small sequential generator for benchmarks and tests. The renderer's own
// random numbers are keyed hashes built on mix64 (core/sampling.h), never a sequential stream.
#pragma once

#include <cstdint>

namespace rt {

// SplitMix64 finaliser: a strong 64-bit mixer used to derive stream seeds from keys. For one
// number or vector lanes of 64 bits (core/owen_sobol_batch.cpp).
template <class U>
constexpr U splitmix64_finaliser(U z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
constexpr uint64_t mix64(uint64_t z) { return splitmix64_finaliser(z); }

// PCG32 (O'Neill, pcg-random.org): small state, good statistics, cheap to construct per pixel.
class Rng {
 public:
  explicit Rng(uint64_t seed, uint64_t stream = 0) : inc_((stream << 1u) | 1u) {
    next_u32();
    state_ += seed;
    next_u32();
  }

  uint32_t next_u32() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
  }

  // Uniform in [0, 1): the top 24 bits, so the result is never rounded up to 1.
  float next_float() { return static_cast<float>(next_u32() >> 8) * 0x1p-24f; }

 private:
  uint64_t state_ = 0;
  uint64_t inc_;
};

}  // namespace rt
