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

// Eight 32-bit lanes (GCC/Clang vector extensions): the Owen scramble of eight dimensions at once
// (core/owen_sobol_batch.h), the same bits lane by lane as the scalar functions below.
typedef uint32_t Uint8 __attribute__((vector_size(32)));

// The bits within each byte reversed: the step reverse_bits takes after swapping the bytes.
template <class U>
inline U reverse_bits_in_bytes(U x) {
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
}
inline uint32_t reverse_bits(uint32_t x) { return reverse_bits_in_bytes(__builtin_bswap32(x)); }
// Vector registers have no byte swap: the halves, then the bytes, by shifts and masks.
inline Uint8 reverse_bits(Uint8 x) {
  x = (x >> 16) | (x << 16);
  return reverse_bits_in_bytes(((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8));
}

// A hash whose every bit depends only on the bits below it (carries only go up): Laine and
// Karras's construction, with Vegdahl's constants. For one number or eight lanes.
template <class U>
inline U upward_hash(U x, U seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

// A nested uniform (Owen) scramble of x's bits, most significant first: each bit flipped by a
// hash of the bits above it, the upward hash on the reversed bits.
inline uint32_t owen_scramble(uint32_t x, uint32_t seed) { return reverse_bits(upward_hash(reverse_bits(x), seed)); }

// The first Sobol dimension: the van der Corput sequence (the index's bits mirrored).
inline uint32_t sobol_dimension0(uint32_t index) { return reverse_bits(index); }

// The second Sobol dimension (primitive polynomial x + 1: direction numbers v_k = v_{k-1} ^ v_{k-1} >> 1),
// bit by bit: the definition, which the tests hold the tables below to.
inline uint32_t sobol_dimension1_bitwise(uint32_t index) {
  uint32_t result = 0;
  for (uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1) result ^= v & (0u - (index & 1u));
  return result;
}

// The same with its bits mirrored, in five shift-and-xor steps on all 32 bits at once. Direction
// number k is (1 + shift)^k applied to the top bit, so bit 31 - j of the result is the xor of the
// index's bits k with C(k, j) odd: by Lucas's theorem, those k whose set bits include j's (a
// superset sum). Step b xors into each bit j whose bit b is clear the bit j + 2^b; after the five,
// bit j holds the xor over all k that include j. The mirrored form is what the Owen scramble
// starts from, so owen_sobol_y needs no reversal; byte tables did it in four lookups, which eight
// vector lanes took one lane at a time (docs/benchmark.md, "Round two, a fifteenth session").
template <class U>
inline U sobol_dimension1_reversed(U index) {
  index ^= (index >> 1) & 0x55555555u;
  index ^= (index >> 2) & 0x33333333u;
  index ^= (index >> 4) & 0x0f0f0f0fu;
  index ^= (index >> 8) & 0x00ff00ffu;
  index ^= (index >> 16) & 0x0000ffffu;
  return index;
}
inline uint32_t sobol_dimension1(uint32_t index) { return reverse_bits(sobol_dimension1_reversed(index)); }

// The top 24 bits as a float in [0, 1): never rounded up to 1.
inline float unit_float(uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

// Point `index` of the scrambled sequence that the three seeds pick: the index shuffled (by an
// Owen scramble, which keeps every aligned power-of-two block of indices a block), then both
// coordinates scrambled. Written without the bit reversals that cancel: the shuffled index's
// first dimension is its reversal, which the coordinate's scramble reverses back.
// `reversed_index`: reverse_bits(index), which a sample's many dimensions share.
template <class U>
inline U shuffled_index(U reversed_index, U shuffle_seed) {
  return reverse_bits(upward_hash(reversed_index, shuffle_seed));
}
// Both coordinates' 32 bits, for one number or eight lanes (core/owen_sobol_batch.cpp).
template <class U>
inline U owen_sobol_x_bits(U shuffled, U x_seed) {
  return reverse_bits(upward_hash(shuffled, x_seed));  // owen_scramble(sobol_dimension0(i), x_seed)
}
template <class U>
inline U owen_sobol_y_bits(U shuffled, U y_seed) {
  // owen_scramble(sobol_dimension1(shuffled), y_seed), the reversal that starts it left out.
  return reverse_bits(upward_hash(sobol_dimension1_reversed(shuffled), y_seed));
}
inline float owen_sobol_x(uint32_t shuffled, uint32_t x_seed) {
  return unit_float(owen_sobol_x_bits(shuffled, x_seed));
}
inline float owen_sobol_y(uint32_t shuffled, uint32_t y_seed) {
  return unit_float(owen_sobol_y_bits(shuffled, y_seed));
}
inline Vec2 owen_sobol2(uint32_t index, uint32_t shuffle_seed, uint32_t x_seed, uint32_t y_seed) {
  const uint32_t i = shuffled_index(reverse_bits(index), shuffle_seed);
  return Vec2(owen_sobol_x(i, x_seed), owen_sobol_y(i, y_seed));
}

}  // namespace rt
