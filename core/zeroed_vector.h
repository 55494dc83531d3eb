// A std::vector whose growth into fresh storage writes nothing: storage comes from calloc, which
// hands a large block over as fresh pages that the kernel zeroes when each is first touched, and
// resize(n) constructs nothing (the bytes are zero already). For images written in full by the
// render threads right after: a 1920 x 1440 film is 41 MB, and zeroing it on the main thread
// before the workers started took 8% of antialias.json's wall time; now each page is first
// touched by the thread that renders into it.
//
// The zeros are only those of storage never used: memory given up by clear() or a shrinking
// resize keeps its old values, so resize(n) after them would show them again. Release the
// storage first (release(v)) to grow from zero. Elements are not zeroed as they go: a film of
// 8192 x 8192 would then write a gigabyte, touching pages never rendered, as Ctrl-C ends the
// render. T: a type whose all-zero bytes are its zero value (floats, integers, Vec3).
#pragma once

#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/fresh_pages.h"

namespace rt {

template <class T>
struct ZeroedAllocator {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "zero bytes must be a valid value");
  using value_type = T;

  ZeroedAllocator() = default;
  template <class U>
  ZeroedAllocator(const ZeroedAllocator<U>&) noexcept {}

  T* allocate(size_t n) {
    // Large blocks: fresh pages, in 2 MiB pages where the kernel has them (core/fresh_pages.h).
    void* p = fresh_pages_for<T>(n) ? fresh_pages(n * sizeof(T)) : std::calloc(n, sizeof(T));
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t n) noexcept {
    if (fresh_pages_for<T>(n)) release_fresh_pages(p, n * sizeof(T));
    else std::free(p);
  }
  template <class U>
  void construct(U*) noexcept {}  // fresh storage's bytes are zero already
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  friend bool operator==(const ZeroedAllocator&, const ZeroedAllocator&) { return true; }
};

template <class T>
using ZeroedVector = std::vector<T, ZeroedAllocator<T>>;

// Empties `v` and gives its storage back, so that it grows from zero again.
template <class T>
void release(ZeroedVector<T>& v) {
  ZeroedVector<T>().swap(v);
}

}  // namespace rt
