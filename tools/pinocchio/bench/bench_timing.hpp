// The timing loop of the Pinocchio side of compare_suite.sh: the
// calibration of rodyn-bench's, median of five runs.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <vector>

namespace bench
{
  inline double ns_per_call(std::size_t calls, std::size_t states, const std::function<void(std::size_t)> & body)
  {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < calls; ++i)
      body(i % states);
    const auto stop = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::nano>(stop - start).count() / double(calls);
  }

  // Nanoseconds per call over about `ms` milliseconds, median of five runs.
  inline double time(double ms, std::size_t states, const std::function<void(std::size_t)> & body)
  {
    std::size_t calls = 16;
    for (;;)
    {
      const double per_call = ns_per_call(calls, states, body);
      if (per_call * double(calls) > 2.0e6 || calls >= (std::size_t(1) << 24))
      {
        std::size_t n = std::size_t(ms * 1e6 / std::max(per_call, 1.0));
        n = std::min(std::max(n, std::size_t(16)), std::size_t(1) << 26);
        std::vector<double> runs;
        for (int r = 0; r < 5; ++r)
          runs.push_back(ns_per_call(n, states, body));
        std::sort(runs.begin(), runs.end());
        return runs[2];
      }
      calls *= 4;
    }
  }
} // namespace bench
