#include "centerline/GapBridges.h"

#include "centerline/TubeSections.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace medial {

std::vector<std::array<int, 3>> leastCostPath(const CostBox& box, const Eigen::Vector3d& spacing,
                                              const std::array<int, 3>& from, const std::array<int, 3>& to) {
  const auto& n = box.size;
  const int64_t count = int64_t(n[0]) * n[1] * n[2];
  auto local = [&](const std::array<int, 3>& v) -> int64_t {
    const int x = v[0] - box.first[0], y = v[1] - box.first[1], z = v[2] - box.first[2];
    if (x < 0 || y < 0 || z < 0 || x >= n[0] || y >= n[1] || z >= n[2]) return -1;
    return x + int64_t(n[0]) * (y + int64_t(n[1]) * z);
  };
  const int64_t start = local(from), goal = local(to);
  if (start < 0 || goal < 0 || count > std::numeric_limits<int32_t>::max()) return {};
  const Eigen::Vector3d target(to[0] - box.first[0], to[1] - box.first[1], to[2] - box.first[2]);
  auto coordinates = [&](int64_t i) {
    return Eigen::Vector3d(double(i % n[0]), double((i / n[0]) % n[1]), double(i / (int64_t(n[0]) * n[1])));
  };
  auto heuristic = [&](int64_t i) { return (coordinates(i) - target).cwiseProduct(spacing).norm(); };

  struct Step {
    int dx, dy, dz;
    double length;
  };
  std::vector<Step> steps;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (dx || dy || dz)
          steps.push_back({dx, dy, dz, Eigen::Vector3d(dx, dy, dz).cwiseProduct(spacing).norm()});

  std::vector<float> reached(size_t(count), std::numeric_limits<float>::infinity());
  std::vector<int32_t> previous(size_t(count), -1);
  std::vector<uint8_t> closed(size_t(count), 0);
  using Entry = std::pair<double, int32_t>;  // estimated total cost, voxel
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  reached[size_t(start)] = 0;
  open.push({heuristic(start), int32_t(start)});
  while (!open.empty()) {
    const int32_t at = open.top().second;
    open.pop();
    if (closed[size_t(at)]) continue;
    closed[size_t(at)] = 1;
    if (at == goal) break;
    const int x = int(at % n[0]), y = int((at / n[0]) % n[1]), z = int(at / (int64_t(n[0]) * n[1]));
    for (const Step& s : steps) {
      const int u = x + s.dx, v = y + s.dy, w = z + s.dz;
      if (u < 0 || v < 0 || w < 0 || u >= n[0] || v >= n[1] || w >= n[2]) continue;
      const int32_t next = int32_t(u + int64_t(n[0]) * (v + int64_t(n[1]) * w));
      if (closed[size_t(next)]) continue;
      const double g = reached[size_t(at)] + s.length * 0.5 * (box.cost[size_t(at)] + box.cost[size_t(next)]);
      if (g < reached[size_t(next)]) {
        reached[size_t(next)] = float(g);
        previous[size_t(next)] = at;
        open.push({g + heuristic(next), next});
      }
    }
  }
  if (!closed[size_t(goal)]) return {};
  std::vector<std::array<int, 3>> path;
  for (int64_t i = goal; i >= 0; i = previous[size_t(i)]) {
    const Eigen::Vector3d c = coordinates(i);
    path.push_back({int(c.x()) + box.first[0], int(c.y()) + box.first[1], int(c.z()) + box.first[2]});
    if (i == start) break;
  }
  std::reverse(path.begin(), path.end());
  return path;
}

namespace {

struct End {
  int part;
  bool last;  // the part's last point (else its first)
};

const Eigen::Vector3d& endPoint(const std::vector<Centerline>& parts, const End& e) {
  const auto& points = parts[size_t(e.part)].points;
  return e.last ? points.back() : points.front();
}

// The unit direction out of the line at an end, over its last `reach` mm (or the whole line when shorter).
Eigen::Vector3d outward(const std::vector<Centerline>& parts, const End& e, double reach = 3.0) {
  const Centerline& line = parts[size_t(e.part)];
  const size_t n = line.points.size(), end = e.last ? n - 1 : 0;
  size_t k = end;
  while (std::abs(line.arcLength[k] - line.arcLength[end]) < reach && (e.last ? k > 0 : k + 1 < n))
    e.last ? --k : ++k;
  const Eigen::Vector3d d = line.points[end] - line.points[k];
  return d.norm() > 0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitZ();
}

}  // namespace

PartChains chainParts(const std::vector<Centerline>& parts, int startPart, double maxGap,
                      const BridgeFunction& bridge) {
  PartChains result;
  std::vector<uint8_t> used(parts.size(), 0);
  std::vector<double> widest(parts.size(), 0);  // a part's largest radius
  size_t left = 0;
  for (size_t p = 0; p < parts.size(); ++p) {
    used[p] = parts[p].points.empty();
    left += used[p] ? 0 : 1;
    for (double r : parts[p].radius) widest[p] = std::max(widest[p], r);
  }
  double gapBefore = 0;
  while (left > 0) {
    // The chain's start: the seed's part, or the lowest end of the parts left.
    End start{-1, false};
    if (result.chains.empty() && startPart >= 0 && !used[size_t(startPart)]) {
      start = {startPart, false};
    } else {
      for (size_t p = 0; p < parts.size(); ++p)
        for (bool last : {false, true}) {
          if (used[p]) continue;
          const End e{int(p), last};
          if (start.part < 0 || endPoint(parts, e).z() < endPoint(parts, start).z()) start = e;
        }
    }
    if (!result.chains.empty()) result.brokenGaps.push_back(gapBefore);
    std::vector<ChainLink> chain{{start.part, start.last, {}}};  // starting at its last point: reversed
    used[size_t(start.part)] = 1;
    --left;
    // Then the nearest end of a part left, while the gap to it is at most the maximum.
    while (left > 0) {
      const ChainLink& tail = chain.back();
      const Eigen::Vector3d& at = endPoint(parts, {tail.part, !tail.reversed});
      End best{-1, false};
      double nearest = std::numeric_limits<double>::infinity();
      for (size_t p = 0; p < parts.size(); ++p)
        for (bool last : {false, true}) {
          if (used[p]) continue;
          const double d = (endPoint(parts, {int(p), last}) - at).norm();
          if (d < nearest) nearest = d, best = {int(p), last};
        }
      const double reach = maxGap + 2.0 * (widest[size_t(tail.part)] + widest[size_t(best.part)]);
      Bridge across;
      if (nearest <= reach)
        across = bridge(
            {at, outward(parts, {tail.part, !tail.reversed}), endPoint(parts, best), -outward(parts, best)});
      if (!(across.gap <= maxGap)) {
        gapBefore = std::isfinite(across.gap) ? across.gap : nearest;
        break;
      }
      chain.push_back({best.part, best.last, std::move(across)});
      used[size_t(best.part)] = 1;
      --left;
    }
    result.chains.push_back(std::move(chain));
  }
  return result;
}

std::vector<Eigen::Vector3d> hermiteCurve(const Eigen::Vector3d& from, const Eigen::Vector3d& fromDirection,
                                          const Eigen::Vector3d& to, const Eigen::Vector3d& toDirection,
                                          double spacing, double tangentScale) {
  const double chord = (to - from).norm() * tangentScale;
  const int n = std::max(1, int(std::lround((to - from).norm() / std::max(spacing, 1e-9))));
  std::vector<Eigen::Vector3d> points;
  for (int s = 1; s < n; ++s) {
    const double t = double(s) / n, t2 = t * t, t3 = t2 * t;
    points.push_back((2 * t3 - 3 * t2 + 1) * from + (t3 - 2 * t2 + t) * chord * fromDirection +
                     (-2 * t3 + 3 * t2) * to + (t3 - t2) * chord * toDirection);
  }
  return points;
}

std::vector<Eigen::Vector3d> bridgePoints(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                          std::vector<Eigen::Vector3d> path, double spacing) {
  // The staircase of voxel centres smoothed (ends held at the two centerlines' ends), then resampled.
  if (path.size() < 2) path = {from, to};
  path.front() = from;
  path.back() = to;
  for (int pass = 0; pass < 20; ++pass) {
    std::vector<Eigen::Vector3d> next = path;
    for (size_t k = 1; k + 1 < path.size(); ++k)
      next[k] = 0.25 * path[k - 1] + 0.5 * path[k] + 0.25 * path[k + 1];
    path.swap(next);
  }
  std::vector<double> arc(path.size(), 0);
  for (size_t k = 1; k < path.size(); ++k) arc[k] = arc[k - 1] + (path[k] - path[k - 1]).norm();
  const double length = arc.back();
  const int pieces = std::max(1, int(std::lround(length / std::max(spacing, 1e-9))));
  std::vector<Eigen::Vector3d> points;
  size_t k = 0;
  for (int i = 1; i < pieces; ++i) {
    const double s = length * i / pieces;
    while (k + 2 < path.size() && arc[k + 1] < s) ++k;
    const double span = arc[k + 1] - arc[k];
    const double t = span > 0 ? (s - arc[k]) / span : 0.0;
    points.push_back((1 - t) * path[k] + t * path[k + 1]);
  }
  return points;
}

Centerline joinChain(const std::vector<Centerline>& parts, const std::vector<ChainLink>& chain) {
  Centerline joined;
  auto add = [&](const Eigen::Vector3d& p, double radius, bool bridged) {
    joined.points.push_back(p);
    joined.radius.push_back(radius);
    joined.bridged.push_back(bridged ? 1 : 0);
  };
  for (const ChainLink& link : chain) {
    const Centerline& part = parts[size_t(link.part)];
    const size_t n = part.points.size();
    for (const Eigen::Vector3d& p : link.bridge.points) add(p, 0.0, true);
    for (size_t k = 0; k < n; ++k) {
      const size_t at = link.reversed ? n - 1 - k : k;
      add(part.points[at], part.radius[at], false);
    }
  }
  joined.arcLength.assign(joined.points.size(), 0.0);
  for (size_t k = 1; k < joined.points.size(); ++k)
    joined.arcLength[k] = joined.arcLength[k - 1] + (joined.points[k] - joined.points[k - 1]).norm();
  return joined;
}

void refineBridges(const BinaryVolume& volume, Centerline& line) {
  const size_t n = line.points.size();
  if (line.bridged.size() != n) return;
  const double halfVoxel = 0.5 * volume.spacing.minCoeff();
  for (size_t begin = 0; begin < n;) {
    if (!line.bridged[begin]) {
      ++begin;
      continue;
    }
    size_t end = begin;
    while (end < n && line.bridged[end]) ++end;
    // The bridge begin..end-1 with three points of each part around it (held: already centred).
    const size_t from = begin >= 3 ? begin - 3 : 0, to = std::min(n, end + 3);
    std::vector<Eigen::Vector3d> stretch(line.points.begin() + long(from), line.points.begin() + long(to));
    stretch = centerInSections(volume, stretch, 36, 2);
    const std::vector<Eigen::Vector3d> moved(stretch.begin() + long(begin - from),
                                             stretch.begin() + long(end - from));
    const std::vector<double> distance = distanceAtPoints(volume, moved);
    for (size_t k = begin; k < end; ++k) {
      const Eigen::Vector3d c = volume.continuousIndex(moved[k - begin]);
      const int i = int(std::lround(c.x())), j = int(std::lround(c.y())), l = int(std::lround(c.z()));
      const bool lumen = volume.contains(i, j, l) && volume.inside[size_t(volume.index(i, j, l))];
      line.bridged[k] = lumen ? 0 : 1;
      if (lumen) line.points[k] = moved[k - begin];  // a point in tissue stays on the least-cost path
      line.radius[k] = lumen ? std::max(distance[k - begin] - halfVoxel, halfVoxel) : 0.0;
    }
    begin = end;
  }
  for (size_t k = 1; k < n; ++k)
    line.arcLength[k] = line.arcLength[k - 1] + (line.points[k] - line.points[k - 1]).norm();
}

}  // namespace medial
