// Owen-scrambled Sobol points, hashed rather than tabled (Burley 2020, "Practical Hash-based Owen
// Scrambling", JCGT 9(4)): the first two Sobol dimensions make a (0, 2)-sequence in base 2, so
// the first n points of one pixel fill the unit square evenly at every power of two. Each pair of
// dimensions a render asks for shuffles the point's index and scrambles both coordinates with
// seeds of its own, so pairs are as independent as independent random numbers and no dimension
// has to be numbered in advance: any 64-bit key names one (core/sampling.h).
#pragma once

#include <cstdint>

#include "core/math.h"

namespace rt {

inline uint32_t reverse_bits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// A nested uniform (Owen) scramble of x's bits, most significant first: each bit flipped by a
// hash of the bits above it. Done as a hash that only carries upwards (Laine and Karras's
// construction, with Vegdahl's constants) on the reversed bits.
inline uint32_t owen_scramble(uint32_t x, uint32_t seed) {
  x = reverse_bits(x);
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return reverse_bits(x);
}

// The first Sobol dimension: the van der Corput sequence (the index's bits mirrored).
inline uint32_t sobol_dimension0(uint32_t index) { return reverse_bits(index); }

// The second Sobol dimension (primitive polynomial x + 1: direction numbers v_k = v_{k-1} ^ v_{k-1} >> 1).
inline uint32_t sobol_dimension1(uint32_t index) {
  uint32_t result = 0;
  for (uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1u) result ^= v;
  return result;
}

// The top 24 bits as a float in [0, 1): never rounded up to 1.
inline float unit_float(uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

// Point `index` of the scrambled sequence that the three seeds pick: the index shuffled (by an
// Owen scramble, which keeps every aligned power-of-two block of indices a block), then both
// coordinates scrambled.
inline Vec2 owen_sobol2(uint32_t index, uint32_t shuffle_seed, uint32_t x_seed, uint32_t y_seed) {
  const uint32_t i = owen_scramble(index, shuffle_seed);
  return Vec2(unit_float(owen_scramble(sobol_dimension0(i), x_seed)),
              unit_float(owen_scramble(sobol_dimension1(i), y_seed)));
}

}  // namespace rt
