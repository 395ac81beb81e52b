// The median wall time of `repeat` runs, shared by the benchmark runners.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

inline double medianSeconds(int repeat, const std::function<void()>& run) {
  std::vector<double> times;
  for (int i = 0; i < repeat; ++i) {
    const auto start = std::chrono::steady_clock::now();
    run();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}
