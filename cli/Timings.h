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
  // A part of a stage measured elsewhere (a filter's own stage times): printed as "stage.part", not
  // added to the total.
  void detail(const std::string& stage, const std::string& part, double seconds);
  std::string json() const;

 private:
  using Clock = std::chrono::steady_clock;
  std::vector<std::pair<std::string, double>> stages_;
  std::vector<std::pair<std::string, double>> details_;
  std::string current_;
  Clock::time_point begin_;
};

}  // namespace medial::cli
