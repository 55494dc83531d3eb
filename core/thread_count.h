// How many worker threads a request for `requested` threads means (0 = all the CPUs this process
// may run on). Shared by the BVH build and the renderer.
#pragma once

#include <algorithm>
#include <thread>

#if defined(__linux__)
#include <sched.h>
#endif

namespace rt {

// The CPUs this process may run on: its affinity mask (taskset, a container's or Slurm's cpuset),
// not the machine's count, which hardware_concurrency gives and which would start more threads
// than there are CPUs to run them.
inline unsigned usable_cpu_count() {
#if defined(__linux__)
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) {
    const int n = CPU_COUNT(&set);
    if (n > 0) return static_cast<unsigned>(n);
  }
#endif
  return std::max(1u, std::thread::hardware_concurrency());
}

inline unsigned resolve_thread_count(unsigned requested) {
  if (requested > 0) return requested;
  return usable_cpu_count();
}

}  // namespace rt
