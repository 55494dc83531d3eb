// A std::vector whose resize leaves new elements default-initialised (for a plain struct:
// untouched) instead of zeroed, for an array that is written in full on many threads right
// after: each page is then first touched by the thread that fills it, and no thread zeroes the
// whole array first (the BVH's slots and quads: a tenth of a 300k-triangle build went to filling
// them on one thread).
#pragma once

#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace rt {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  using std::allocator<T>::allocator;
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
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
