#pragma once
// How the experiment sections time a configuration: one warm-up run, then runs until
// timing.max_runs runs or timing.max_seconds seconds (steady_clock), each checked for interruption.

#include <simpson/verify/interruption.hpp>
#include <simpson/verify/work_precision_section.hpp>  // timing_policy

#include <algorithm>
#include <chrono>
#include <vector>

namespace simpson::verify::detail {

struct run_times {
  long long runs = 0;
  double minimum = 0, median = 0, maximum = 0;  // seconds: the spread is [minimum, maximum]
};

/// Times `one_run`, which returns a double derived from its result (kept, so that the run is not
/// optimized away). Needs timing.max_runs ≥ 1.
template <class Run>
run_times time_runs(const timing_policy& timing, Run&& one_run) {
  using clock = std::chrono::steady_clock;
  volatile double sink = one_run();  // the warm-up
  std::vector<double> seconds;
  const auto start = clock::now();
  while (seconds.size() < timing.max_runs &&
         (seconds.empty() || std::chrono::duration<double>(clock::now() - start).count() < timing.max_seconds)) {
    throw_if_interrupted();
    const auto t0 = clock::now();
    sink = sink + one_run();
    seconds.push_back(std::chrono::duration<double>(clock::now() - t0).count());
  }
  std::sort(seconds.begin(), seconds.end());
  const std::size_t n = seconds.size();
  return {static_cast<long long>(n), seconds.front(), n % 2 ? seconds[n / 2] : (seconds[n / 2 - 1] + seconds[n / 2]) / 2, seconds.back()};
}

}  // namespace simpson::verify::detail
