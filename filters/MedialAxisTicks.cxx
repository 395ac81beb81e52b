#include "MedialAxisTicks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace medial {

std::string AxisTicks::label(double value) const {
  const int decimals = std::max(0, int(std::ceil(-std::log10(step) - 1e-9)));
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, std::abs(value) < 1e-9 * step ? 0.0 : value);
  return text;
}

AxisTicks roundTicks(double low, double high, int target) {
  AxisTicks ticks;
  if (!(high > low) || !std::isfinite(low) || !std::isfinite(high)) {
    if (std::isfinite(low)) ticks.values = {low};
    return ticks;
  }
  // Of the round steps near (high - low) / target, the one whose tick count is nearest the target (ties:
  // the longer step).
  const double rough = (high - low) / std::max(1, target);
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  int bestMiss = 1 << 30;
  for (const double factor : {1.0, 2.0, 5.0, 10.0, 20.0}) {
    const double step = factor * power;
    const int count = int(std::floor(high / step + 1e-9) - std::ceil(low / step - 1e-9)) + 1;
    if (std::abs(count - target) <= bestMiss) {
      bestMiss = std::abs(count - target);
      ticks.step = step;
    }
  }
  for (double k = std::ceil(low / ticks.step - 1e-9); k * ticks.step <= high + 1e-9 * ticks.step; ++k)
    ticks.values.push_back(k * ticks.step + 0.0);  // + 0.0: no "-0"
  return ticks;
}

}  // namespace medial
