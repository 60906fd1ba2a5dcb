/**
 * @file QueryTiming.hpp
 * @brief Timing of distance queries: the mean from batch loops (no timer in
 *        the loop) and the per-query median from individually timed calls
 *        (the timer's own cost, calibrated, is subtracted).
 */
#ifndef DISTANCEBENCHMARK_QUERYTIMING_HPP
#define DISTANCEBENCHMARK_QUERYTIMING_HPP

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <vector>

namespace benchmark_support {

using Clock = std::chrono::steady_clock;

/// Median cost (ns) of two consecutive Clock::now() calls.
inline double timerOverheadNs() {
  std::vector<double> d(2001);
  for (double& x : d) {
    const auto a = Clock::now();
    const auto b = Clock::now();
    x = std::chrono::duration<double, std::nano>(b - a).count();
  }
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  return d[d.size() / 2];
}

struct QueryTimes {
  double meanUs = 0;    ///< batch: total time / (repetitions x queries)
  double medianUs = 0;  ///< per query: min over sweeps of its own time, then the median over queries
  double p90Us = 0;     ///< 90th percentile of the per-query times
};

/**
 * @param run    runs query q and returns a value to keep the call observable
 * @param count  number of queries
 * @param minBatchSeconds the batch loops repeat until this much time has passed
 * @param sweeps individually timed sweeps over all queries
 */
inline QueryTimes timeQueries(const std::function<double(std::size_t)>& run, std::size_t count,
                              double minBatchSeconds, int sweeps, double& sink) {
  QueryTimes t;
  if (count == 0) return t;
  // batch mean
  long reps = 0;
  const auto start = Clock::now();
  double elapsed = 0;
  do {
    for (std::size_t q = 0; q < count; ++q) sink += run(q);
    ++reps;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < minBatchSeconds);
  t.meanUs = 1e6 * elapsed / (double(reps) * double(count));
  // per-query
  const double overhead = timerOverheadNs();
  std::vector<double> best(count, 1e300);
  for (int s = 0; s < sweeps; ++s) {
    for (std::size_t q = 0; q < count; ++q) {
      const auto a = Clock::now();
      sink += run(q);
      const auto b = Clock::now();
      best[q] = std::min(best[q], std::chrono::duration<double, std::nano>(b - a).count() - overhead);
    }
  }
  std::vector<double> sorted = best;
  std::nth_element(sorted.begin(), sorted.begin() + count / 2, sorted.end());
  t.medianUs = 1e-3 * sorted[count / 2];
  std::nth_element(sorted.begin(), sorted.begin() + (9 * count) / 10, sorted.end());
  t.p90Us = 1e-3 * sorted[(9 * count) / 10];
  return t;
}

}  // namespace benchmark_support

#endif
