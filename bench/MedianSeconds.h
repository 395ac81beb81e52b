// The median wall time of `repeat` runs, shared by the benchmark runners.
#pragma once

#include "common/Stopwatch.h"

#include <algorithm>
#include <functional>
#include <vector>

inline double medianSeconds(int repeat, const std::function<void()>& run) {
  std::vector<double> times;
  for (int i = 0; i < repeat; ++i) {
    const medial::Stopwatch stopwatch;
    run();
    times.push_back(stopwatch.seconds());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}
