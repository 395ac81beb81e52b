#include "Timings.h"

#include <cstdio>

namespace medial::cli {

void Timings::start(const std::string& stage) {
  stop();
  current_ = stage;
  stopwatch_.restart();
}

void Timings::stop() {
  if (current_.empty()) return;
  const double seconds = stopwatch_.seconds();
  for (auto& [name, total] : stages_)  // a stage run several times (one read per input) adds up
    if (name == current_) {
      total += seconds;
      current_.clear();
      return;
    }
  stages_.emplace_back(current_, seconds);
  current_.clear();
}

void Timings::detail(const std::string& stage, const std::string& part, double seconds) {
  details_.emplace_back(stage + "." + part, seconds);
}

void Timings::count(const std::string& stage, const std::string& name, long long value) {
  counts_.emplace_back(stage + "." + name, value);
}

std::string Timings::json() const {
  std::string out = "{";
  double total = 0;
  auto add = [&out](const std::string& name, double seconds) {
    char number[64];
    std::snprintf(number, sizeof number, "%.6f", seconds);
    out += "\"" + name + "\": " + number + ", ";
  };
  for (const auto& [name, seconds] : stages_) {
    add(name, seconds);
    total += seconds;
  }
  for (const auto& [name, seconds] : details_) add(name, seconds);
  for (const auto& [name, value] : counts_) out += "\"" + name + "\": " + std::to_string(value) + ", ";
  char number[64];
  std::snprintf(number, sizeof number, "%.6f", total);
  return out + "\"total\": " + number + "}";
}

}  // namespace medial::cli
