// TrueAxis: the true axes the phantoms come with, for tests that measure a centerline against them: the
// colon phantom's axis.txt ("x y z radius" in mm per line, '#' comments) and the distance to a polyline.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace medial::test {

using Point3 = std::array<double, 3>;

struct AxisPoint {
  Point3 p{};
  double radius = 0;
};

inline std::vector<AxisPoint> readAxisFile(const std::string& path) {
  std::vector<AxisPoint> axis;
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line))
    if (!line.empty() && line[0] != '#') {
      AxisPoint a;
      std::istringstream(line) >> a.p[0] >> a.p[1] >> a.p[2] >> a.radius;
      axis.push_back(a);
    }
  return axis;
}

inline std::vector<Point3> pointsOf(const std::vector<AxisPoint>& axis) {
  std::vector<Point3> points;
  for (const AxisPoint& a : axis) points.push_back(a.p);
  return points;
}

inline double distance(const Point3& a, const Point3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

/// Distance from `p` to the polyline through `line`; `nearest` (optional) gets the first point of the
/// nearest segment.
inline double distanceToPolyline(const Point3& p, const std::vector<Point3>& line,
                                 size_t* nearest = nullptr) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k + 1 < line.size(); ++k) {
    double t = 0, length2 = 0;
    for (size_t i = 0; i < 3; ++i) {
      t += (line[k + 1][i] - line[k][i]) * (p[i] - line[k][i]);
      length2 += (line[k + 1][i] - line[k][i]) * (line[k + 1][i] - line[k][i]);
    }
    t = length2 > 0 ? std::clamp(t / length2, 0.0, 1.0) : 0.0;
    Point3 q{};
    for (size_t i = 0; i < 3; ++i) q[i] = line[k][i] + t * (line[k + 1][i] - line[k][i]);
    const double d = distance(p, q);
    if (d < best) {
      best = d;
      if (nearest) *nearest = k;
    }
  }
  return best;
}

}  // namespace medial::test
