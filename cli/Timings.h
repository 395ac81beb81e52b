// Stage times for --timings: one JSON object of seconds on stdout (docs/ARCHITECTURE.md §6).
#pragma once

#include "common/Stopwatch.h"

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
  // A count a filter reports beside its times (the paper's Table 1 for SQM): printed as "stage.name", an
  // integer.
  void count(const std::string& stage, const std::string& name, long long value);
  std::string json() const;

 private:
  std::vector<std::pair<std::string, double>> stages_;
  std::vector<std::pair<std::string, double>> details_;
  std::vector<std::pair<std::string, long long>> counts_;
  std::string current_;
  Stopwatch stopwatch_;
};

}  // namespace medial::cli
