#include "core/fresh_pages.h"

#include <cstdint>
#include <cstdlib>

// Under AddressSanitizer, calloc's: its allocator guards the block's ends and finds its leaks.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RT_FRESH_PAGES_CALLOC 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || !defined(__linux__)
#define RT_FRESH_PAGES_CALLOC 1
#endif

#if !defined(RT_FRESH_PAGES_CALLOC)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace rt {

#if !defined(RT_FRESH_PAGES_CALLOC)

namespace {

constexpr size_t kHugePage = size_t{2} << 20;

// In the system's pages (4 KiB on x86-64; 16 or 64 KiB on some ARM kernels), so that every
// munmap below starts and ends on a page boundary.
size_t whole_pages(size_t bytes) {
  const auto page = static_cast<size_t>(getpagesize());
  return (bytes + page - 1) / page * page;
}

}  // namespace

void* fresh_pages(size_t bytes) noexcept {
  const size_t size = whole_pages(bytes);
  if (size < bytes || size + kHugePage < size) return nullptr;  // overflow: no such block
  // A 2 MiB-aligned block cut from one a huge page longer: the ends beyond it go back at once.
  void* mapped = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) return nullptr;
  const uintptr_t start = reinterpret_cast<uintptr_t>(mapped);
  const uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) munmap(mapped, aligned - start);
  const uintptr_t end = start + size + kHugePage;
  if (end > aligned + size) munmap(reinterpret_cast<void*>(aligned + size), end - (aligned + size));
  void* block = reinterpret_cast<void*>(aligned);
  madvise(block, size, MADV_HUGEPAGE);  // a hint: without it (or without huge pages) still zeros
  return block;
}

void release_fresh_pages(void* block, size_t bytes) noexcept { munmap(block, whole_pages(bytes)); }

bool fresh_pages_from_kernel() { return true; }

#else

void* fresh_pages(size_t bytes) noexcept { return std::calloc(bytes, 1); }
void release_fresh_pages(void* block, size_t) noexcept { std::free(block); }
bool fresh_pages_from_kernel() { return false; }

#endif

}  // namespace rt
