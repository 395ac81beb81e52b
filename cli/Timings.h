// Stage times for --timings: one JSON object of seconds on stdout (GUIDE §3).
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace medial::cli {

class Timings {
 public:
  // Ends the previous stage (if any) and starts `stage`.
  void start(const std::string& stage);
  void stop();
  std::string json() const;

 private:
  using Clock = std::chrono::steady_clock;
  std::vector<std::pair<std::string, double>> stages_;
  std::string current_;
  Clock::time_point begin_;
};

}  // namespace medial::cli
