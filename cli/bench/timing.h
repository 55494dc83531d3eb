// Timings as `rtcli bench` reports them on a shared, noisy machine: one warm-up run that is not
// counted, then N runs; the median, with the fastest and slowest beside it.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace rt {

struct Timing {
  double median = 0.0, min = 0.0, max = 0.0;  // seconds
};

inline Timing summarise(std::vector<double> seconds) {
  if (seconds.empty()) return {};
  std::sort(seconds.begin(), seconds.end());
  const size_t n = seconds.size();
  const double median = n % 2 ? seconds[n / 2] : 0.5 * (seconds[n / 2 - 1] + seconds[n / 2]);
  return {median, seconds.front(), seconds.back()};
}

// run() once to warm up, then `repeats` more times, timed.
template <class Run>
Timing time_runs(int repeats, const Run& run) {
  using Clock = std::chrono::steady_clock;
  run();
  std::vector<double> seconds;
  for (int i = 0; i < std::max(1, repeats); ++i) {
    const auto start = Clock::now();
    run();
    seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  return summarise(seconds);
}

// The seconds run() takes in a child process forked for it: memory it allocates is fresh there,
// page faults and all, whatever this process has done since (a "cold" BVH build). Call it while
// no other thread runs. A negative value when the child could not be made or did not report.
double time_in_fresh_process(const std::function<void()>& run);
// What run() returns (a time it measured itself), run in a forked child; negative as above.
double run_in_fresh_process(const std::function<double()>& run);

}  // namespace rt
