// How many worker threads a request for `requested` threads means (0 = all hardware threads).
// Shared by the BVH build and the renderer.
#pragma once

#include <algorithm>
#include <thread>

namespace rt {

inline unsigned resolve_thread_count(unsigned requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace rt
