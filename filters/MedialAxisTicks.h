/// \file
/// MedialAxisTicks: round tick values for the axes of Medial's charts and figures (the unfolded wall, the
/// diameter profile): steps of 1, 2 or 5 times a power of ten, labels with just the digits the step needs.
#pragma once

#include <string>
#include <vector>

namespace medial {

/// Round tick values over an interval (axisTicks()).
struct AxisTicks {
  std::vector<double> values;             ///< in [low, high], ascending
  double step = 1;                        ///< the distance between ticks
  std::string label(double value) const;  ///< "0", "50", "0.25": as many decimals as the step has
};

/// About `target` round ticks over [low, high] (at least 2 values when high > low).
AxisTicks roundTicks(double low, double high, int target = 6);

}  // namespace medial
