#include "sqm/RingAngles.h"

#include <algorithm>
#include <cmath>

namespace medial {

bool untangleAngles(std::vector<double>& angle, int wantedSense) {
  const int m = int(angle.size());
  if (m < 3) return false;
  std::vector<double> step(static_cast<size_t>(m));
  double total = 0;
  for (int k = 0; k < m; ++k) {
    step[size_t(k)] = std::remainder(angle[size_t((k + 1) % m)] - angle[size_t(k)], 2 * M_PI);
    total += step[size_t(k)];
  }
  const double sense = wantedSense != 0 ? double(wantedSense) : total >= 0 ? 1.0 : -1.0;
  const double equal = 2 * M_PI / m, minimum = 0.2 * equal;
  double blend = 0;
  if (std::abs(sense * total - 2 * M_PI) > 1e-6) {
    blend = 1;  // tangled beyond repair by blending: equal spacing
  } else {
    for (double s : step)
      if (sense * s < minimum) blend = std::max(blend, (minimum - sense * s) / (equal - sense * s));
  }
  if (blend == 0) return false;
  double a = angle[0];
  for (int k = 1; k < m; ++k) {
    a += sense * ((1 - blend) * sense * step[size_t(k - 1)] + blend * equal);
    angle[size_t(k)] = a;
  }
  return true;
}

}  // namespace medial
