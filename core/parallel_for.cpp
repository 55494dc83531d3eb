#include "core/parallel_for.h"

#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace rt {

void run_workers(unsigned threads, const std::function<void(unsigned)>& work,
                 const std::function<void()>& while_waiting, std::chrono::milliseconds period) {
  threads = std::max(1u, threads);
  if (!while_waiting) {
    std::vector<std::jthread> pool;
    pool.reserve(threads - 1);
    for (unsigned i = 1; i < threads; ++i) pool.emplace_back(work, i);
    work(0);
    return;  // the pool joins as it goes out of scope
  }
  std::mutex mutex;
  std::condition_variable finished;
  unsigned running = threads;
  {
    std::vector<std::jthread> pool;
    pool.reserve(threads);
    for (unsigned i = 0; i < threads; ++i)
      pool.emplace_back([&, i] {
        work(i);
        std::lock_guard lock(mutex);
        if (--running == 0) finished.notify_all();
      });
    std::unique_lock lock(mutex);
    while (!finished.wait_for(lock, period, [&] { return running == 0; })) {
      lock.unlock();
      while_waiting();
      lock.lock();
    }
  }
  while_waiting();
}

}  // namespace rt
