/// \file
/// Stopwatch: wall-clock seconds since it started (or restarted), for the stage times that results and
/// `--timings` report and for the benchmarks.
#pragma once

#include <chrono>

namespace medial {

/// Wall-clock seconds since start (see the file).
class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  /// Seconds since construction or the last restart().
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  /// Starts counting again from now.
  void restart() { start_ = Clock::now(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

}  // namespace medial
