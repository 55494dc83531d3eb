// A std::vector whose spare capacity always holds zero bytes, so that growing it with resize(n)
// writes nothing: storage comes from calloc, which hands a large block over as fresh pages that
// the kernel zeroes when each is first touched, and an element the vector gives up (clear, a
// shrinking resize, a reallocation's old copy) is zeroed as it goes. For images written in full
// by the render threads right after: a 1920 x 1440 film is 41 MB, and zeroing it on the main
// thread before the workers started took 8% of antialias.json's wall time; now each page is
// first touched by the thread that renders into it. T: a type whose all-zero bytes are its zero
// value (floats, integers, Vec3).
#pragma once

#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace rt {

template <class T>
struct ZeroedAllocator {
  static_assert(std::is_trivially_copyable_v<T>, "zero bytes must be a valid value");
  using value_type = T;

  ZeroedAllocator() = default;
  template <class U>
  ZeroedAllocator(const ZeroedAllocator<U>&) noexcept {}

  T* allocate(size_t n) {
    void* p = std::calloc(n, sizeof(T));
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t) noexcept { std::free(p); }
  template <class U>
  void construct(U*) noexcept {}  // the bytes are zero already
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  void destroy(U* p) noexcept {
    std::memset(static_cast<void*>(p), 0, sizeof(U));  // trivially destructible: only the bytes to restore
  }
  friend bool operator==(const ZeroedAllocator&, const ZeroedAllocator&) { return true; }
};

template <class T>
using ZeroedVector = std::vector<T, ZeroedAllocator<T>>;

}  // namespace rt
