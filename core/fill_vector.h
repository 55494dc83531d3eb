// A std::vector whose resize leaves new elements default-initialised (for a plain struct:
// untouched) instead of zeroed, for an array that is written in full on many threads right
// after: each page is then first touched by the thread that fills it, and no thread zeroes the
// whole array first (the BVH's slots and quads: a tenth of a 300k-triangle build went to filling
// them on one thread). Blocks of kFreshPagesMin and more are fresh pages in 2 MiB pages where
// the kernel has them (core/fresh_pages.h): each page's first touch is a fault, and there are
// 512 times fewer.
#pragma once

#include <memory>
#include <new>
#include <utility>
#include <vector>

#include "core/fresh_pages.h"

namespace rt {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  using std::allocator<T>::allocator;
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  T* allocate(size_t n) {
    if (!fresh_pages_for<T>(n)) return std::allocator<T>::allocate(n);
    void* p = fresh_pages(n * sizeof(T));
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t n) noexcept {
    if (fresh_pages_for<T>(n)) release_fresh_pages(p, n * sizeof(T));
    else std::allocator<T>::deallocate(p, n);
  }
  template <class U>
  void construct(U* p) {
    ::new (static_cast<void*>(p)) U;  // default-initialised: no value written
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T>
using FillVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace rt
