// The one way rtcli spreads work over threads. run_workers starts `threads` workers and waits for
// them, optionally doing something on the calling thread while it waits (the renderer's progress
// reports); parallel_for hands out the items of a range from a shared counter, `chunk` at a time,
// so that fast and slow items balance out. Which worker does which item never changes a result:
// callers write each item's output to its own place. (The BVH builder's fork-join recursion is
// not a loop over items and keeps its own threads: core/accel/bvh_build.cpp.)
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>

namespace rt {

// work(worker) on workers 0 .. threads-1, each on its own thread; returns when all have. If
// while_waiting is given, the calling thread runs it every `period` until then (and once more
// at the end); otherwise the calling thread is worker 0.
void run_workers(unsigned threads, const std::function<void(unsigned worker)>& work,
                 const std::function<void()>& while_waiting = {},
                 std::chrono::milliseconds period = std::chrono::milliseconds(100));

// body(worker, item) for every item in [0, count), on min(threads, chunks) workers.
template <class Body>
void parallel_for(size_t count, unsigned threads, size_t chunk, const Body& body) {
  chunk = std::max<size_t>(1, chunk);
  const size_t chunks = (count + chunk - 1) / chunk;
  const auto workers = static_cast<unsigned>(std::clamp<size_t>(chunks, 1, std::max(1u, threads)));
  std::atomic<size_t> next{0};
  run_workers(workers, [&](unsigned worker) {
    for (size_t begin = next.fetch_add(chunk); begin < count; begin = next.fetch_add(chunk))
      for (size_t i = begin, end = std::min(count, begin + chunk); i < end; ++i) body(worker, i);
  });
}

}  // namespace rt
