// Large zero-filled blocks straight from the kernel, in 2 MiB pages where it has them. A film or
// an image of a 1920 x 1440 render is 8-33 MB that the render threads touch for the first time:
// each 4 KiB page's first touch is a fault that the kernel answers with a zeroed page, and on the
// development machine's virtual CPUs that cost 2 us a page, 100 ms of CPU for antialias.json's
// 50 MB. Asked for huge pages (Linux's madvise(MADV_HUGEPAGE)), the kernel answers one fault per
// 2 MiB (docs/benchmark.md, "Round two, a tenth session"). Where that is not available the block
// is still fresh, zeroed pages; on other systems, and under AddressSanitizer, calloc's.
#pragma once

#include <cstddef>

namespace rt {

// Blocks at least this large come from fresh_pages; smaller ones from calloc.
inline constexpr size_t kFreshPagesMin = size_t{4} << 20;

// Whether n elements of T make a block for fresh_pages (ZeroedVector's and FillVector's
// allocators ask), without working out n * sizeof(T), which may overflow.
template <class T>
constexpr bool fresh_pages_for(size_t n) {
  return n >= kFreshPagesMin / sizeof(T);
}

// `bytes` of zeros, aligned to 2 MiB; nullptr when the system has no such memory to give.
void* fresh_pages(size_t bytes) noexcept;
// Gives back a block of fresh_pages(bytes).
void release_fresh_pages(void* block, size_t bytes) noexcept;
// Whether blocks come from the kernel (2 MiB-aligned), not calloc.
bool fresh_pages_from_kernel();

}  // namespace rt
