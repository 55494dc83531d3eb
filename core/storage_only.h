// Room for N objects of T, none of them made: for the arrays a packet of rays fills before it
// reads them (rays, hits, surfaces, contexts). Made as plain arrays, each element's default
// member initialisers ran for every packet: a memset (`rep stos`) or a run of stores, 1-3% of a
// Whitted render each (docs/benchmark.md, "Round two, a twenty-seventh session"). The elements
// are written whole (or made in place with placement new) before they are read.
#pragma once

#include <cstddef>
#include <type_traits>

namespace rt {

template <class T, size_t N>
union StorageOnly {
  static_assert(std::is_trivially_destructible_v<T>, "nothing is destroyed: T must need no destructor");
  StorageOnly() {}
  T at[N];
};

}  // namespace rt
