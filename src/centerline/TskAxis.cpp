#include "centerline/TskAxis.h"
#include "centerline/TubeSections.h"
#include "centerline/TubularClusters.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <limits>
#include <thread>

namespace medial {

namespace {

// One-dimensional squared distance transform of f (Felzenszwalb and Huttenlocher 2012), sample step h.
void distanceTransform1d(std::vector<double>& f, double h, std::vector<double>& out, std::vector<int>& v,
                         std::vector<double>& z) {
  const int n = int(f.size());
  v.assign(size_t(n), 0);
  z.assign(size_t(n) + 1, 0);
  out.assign(size_t(n), 0);
  int k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<double>::infinity();
  z[1] = std::numeric_limits<double>::infinity();
  auto intersection = [&](int q, int p) {
    return ((f[size_t(q)] + (q * h) * (q * h)) - (f[size_t(p)] + (p * h) * (p * h))) / (2 * h * (q - p));
  };
  for (int q = 1; q < n; ++q) {
    if (!std::isfinite(f[size_t(q)])) continue;
    if (!std::isfinite(f[size_t(v[size_t(k)])])) {  // no finite parabola yet
      v[size_t(k)] = q;
      continue;
    }
    double s = intersection(q, v[size_t(k)]);
    while (k > 0 && s <= z[size_t(k)]) {
      --k;
      s = intersection(q, v[size_t(k)]);
    }
    ++k;
    v[size_t(k)] = q;
    z[size_t(k)] = s;
    z[size_t(k) + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[size_t(k) + 1] < q * h) ++k;
    const double d = (q - v[size_t(k)]) * h;
    out[size_t(q)] = std::isfinite(f[size_t(v[size_t(k)])]) ? d * d + f[size_t(v[size_t(k)])]
                                                            : std::numeric_limits<double>::infinity();
  }
}

// The voxels around a continuous index that lie in the volume, with their trilinear weights.
struct Corner {
  int64_t voxel;
  double weight;
};
std::vector<Corner> trilinearCorners(const BinaryVolume& v, const Eigen::Vector3d& index) {
  const int i0 = int(std::floor(index.x())), j0 = int(std::floor(index.y())), k0 = int(std::floor(index.z()));
  const double fx = index.x() - i0, fy = index.y() - j0, fz = index.z() - k0;
  std::vector<Corner> corners;
  for (int dz = 0; dz <= 1; ++dz)
    for (int dy = 0; dy <= 1; ++dy)
      for (int dx = 0; dx <= 1; ++dx)
        if (v.contains(i0 + dx, j0 + dy, k0 + dz))
          corners.push_back({v.index(i0 + dx, j0 + dy, k0 + dz),
                             (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy) * (dz ? fz : 1 - fz)});
  return corners;
}

// distanceToOutside at the given voxels only: the transform along x runs on every line, along y only on
// the lines of the voxels' x columns, along z only on the voxels' own (x, y) lines, which is all the last
// two passes need for them. The values are those of the full transform.
std::vector<float> distanceAtVoxels(const BinaryVolume& v, const std::vector<int64_t>& voxels) {
  const int nx = v.size[0], ny = v.size[1], nz = v.size[2];
  std::vector<double> squared(size_t(v.voxelCount()));
  for (int64_t i = 0; i < v.voxelCount(); ++i)
    squared[size_t(i)] = v.inside[size_t(i)] ? std::numeric_limits<double>::infinity() : 0.0;
  std::vector<double> line, out, z;
  std::vector<int> stack;
  auto transform = [&](int64_t first, int64_t stride, int count, double step) {
    line.resize(size_t(count));
    bool any = false;
    for (int p = 0; p < count; ++p) {
      line[size_t(p)] = squared[size_t(first + p * stride)];
      any = any || line[size_t(p)] != 0;
    }
    if (!any) return;
    distanceTransform1d(line, step, out, stack, z);
    for (int p = 0; p < count; ++p) squared[size_t(first + p * stride)] = out[size_t(p)];
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j) transform(v.index(0, j, k), 1, nx, v.spacing[0]);
  std::vector<bool> column(size_t(nx), false), pillar(size_t(nx) * size_t(ny), false);
  for (int64_t voxel : voxels) {
    const auto c = v.coordinates(voxel);
    column[size_t(c[0])] = true;
    pillar[size_t(c[0]) + size_t(nx) * size_t(c[1])] = true;
  }
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i)
      if (column[size_t(i)]) transform(v.index(i, 0, k), nx, ny, v.spacing[1]);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (pillar[size_t(i) + size_t(nx) * size_t(j)])
        transform(v.index(i, j, 0), int64_t(nx) * ny, nz, v.spacing[2]);
  std::vector<float> distance;
  for (int64_t voxel : voxels) distance.push_back(float(std::sqrt(squared[size_t(voxel)])));
  return distance;
}

}  // namespace

// The distance to the outside at each point (trilinear between the voxels around it), as
// trilinear(distanceToOutside(volume)) gives it, but with the transform run in small boxes only: for a run
// of consecutive points, the box around their voxels grown by a bound of those voxels' distances (the
// six-direction distance, never less than the Euclidean one) holds each one's nearest outside voxel, so
// its distance there is exact. A full-size CT's box is 35 million voxels; the boxes around a 1 m colon's
// axis hold a fraction of that.
std::vector<double> distanceAtPoints(const BinaryVolume& volume, const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> out;
  constexpr size_t kRun = 32;
  for (size_t begin = 0; begin < points.size(); begin += kRun) {
    const size_t end = std::min(points.size(), begin + kRun);
    std::array<int, 3> lo{INT32_MAX, INT32_MAX, INT32_MAX}, hi{-1, -1, -1};
    double bound = 0;
    for (size_t s = begin; s < end; ++s)
      for (const Corner& corner : trilinearCorners(volume, volume.continuousIndex(points[s]))) {
        if (volume.inside[size_t(corner.voxel)])
          bound = std::max(bound, double(sixDirectionBorderDistance(volume, corner.voxel)));
        const auto c = volume.coordinates(corner.voxel);
        for (size_t a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c[a]), hi[a] = std::max(hi[a], c[a]);
      }
    if (hi[0] < 0) {  // every point outside the volume
      out.insert(out.end(), end - begin, 0.0);
      continue;
    }
    BinaryVolume box;
    for (size_t a = 0; a < 3; ++a) {
      const int grow = int(std::ceil(bound / volume.spacing[int(a)])) + 1;
      lo[a] = std::max(0, lo[a] - grow);
      hi[a] = std::min(volume.size[a] - 1, hi[a] + grow);
      box.size[a] = hi[a] - lo[a] + 1;
    }
    box.spacing = volume.spacing;
    box.direction = volume.direction;
    box.origin = volume.physical(Eigen::Vector3d(lo[0], lo[1], lo[2]));
    box.inside.resize(size_t(box.voxelCount()));
    for (int k = 0; k < box.size[2]; ++k)
      for (int j = 0; j < box.size[1]; ++j)
        std::copy_n(volume.inside.begin() + volume.index(lo[0], lo[1] + j, lo[2] + k), box.size[0],
                    box.inside.begin() + box.index(0, j, k));
    // The points' corners in the box, their distances, and each point's weighted mean of them.
    std::vector<std::vector<Corner>> around;
    std::vector<int64_t> voxels;
    for (size_t s = begin; s < end; ++s) {
      around.push_back(trilinearCorners(box, box.continuousIndex(points[s])));
      for (const Corner& corner : around.back()) voxels.push_back(corner.voxel);
    }
    const std::vector<float> values = distanceAtVoxels(box, voxels);
    size_t next = 0;
    for (const auto& corners : around) {
      double sum = 0, weights = 0;
      for (const Corner& corner : corners) {
        sum += corner.weight * values[next++];
        weights += corner.weight;
      }
      out.push_back(weights > 0 ? sum / weights : 0);
    }
  }
  return out;
}

std::vector<float> distanceToOutside(const BinaryVolume& volume) {
  const int64_t count = volume.voxelCount();
  std::vector<double> squared(static_cast<size_t>(count));
  for (int64_t i = 0; i < count; ++i)
    squared[size_t(i)] = volume.inside[size_t(i)] ? std::numeric_limits<double>::infinity() : 0.0;
  // One pass per axis; its lines are independent, so two threads take half of them each.
  const auto pass = [&](int axis, int from, int to) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    std::vector<double> line(size_t(volume.size[size_t(axis)])), out, z;
    std::vector<int> v;
    std::array<int, 3> c{};
    for (c[size_t(a2)] = from; c[size_t(a2)] < to; ++c[size_t(a2)])
      for (c[size_t(a1)] = 0; c[size_t(a1)] < volume.size[size_t(a1)]; ++c[size_t(a1)]) {
        bool any = false;  // a line with no inside voxel (most of a CT around a colon) stays all zero
        for (int p = 0; p < volume.size[size_t(axis)]; ++p) {
          c[size_t(axis)] = p;
          line[size_t(p)] = squared[size_t(volume.index(c[0], c[1], c[2]))];
          any = any || line[size_t(p)] != 0;
        }
        if (!any) continue;
        distanceTransform1d(line, volume.spacing[axis], out, v, z);
        for (int p = 0; p < volume.size[size_t(axis)]; ++p) {
          c[size_t(axis)] = p;
          squared[size_t(volume.index(c[0], c[1], c[2]))] = out[size_t(p)];
        }
      }
  };
  // Along z the lines' voxels lie a slice apart: for each y, the (x, z) plane is copied row by row into a
  // buffer first, transformed there column by column (in cache), and copied back.
  const auto passZ = [&](int from, int to) {
    const int nx = volume.size[0], nz = volume.size[2];
    std::vector<double> plane(static_cast<size_t>(nx) * static_cast<size_t>(nz)),
        line(static_cast<size_t>(nz)), out, z;
    std::vector<int> v;
    for (int y = from; y < to; ++y) {
      for (int k = 0; k < nz; ++k)
        std::copy_n(squared.begin() + volume.index(0, y, k), nx, plane.begin() + int64_t(k) * nx);
      for (int x = 0; x < nx; ++x) {
        bool any = false;
        for (int k = 0; k < nz; ++k) {
          line[size_t(k)] = plane[size_t(k) * size_t(nx) + size_t(x)];
          any = any || line[size_t(k)] != 0;
        }
        if (!any) continue;
        distanceTransform1d(line, volume.spacing[2], out, v, z);
        for (int k = 0; k < nz; ++k) plane[size_t(k) * size_t(nx) + size_t(x)] = out[size_t(k)];
      }
      for (int k = 0; k < nz; ++k)
        std::copy_n(plane.begin() + int64_t(k) * nx, nx, squared.begin() + volume.index(0, y, k));
    }
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int lines = volume.size[size_t((axis + 2) % 3)], half = lines / 2;
    if (axis == 2) {
      std::thread second(passZ, half, lines);
      passZ(0, half);
      second.join();
    } else {
      std::thread second(pass, axis, half, lines);
      pass(axis, 0, half);
      second.join();
    }
  }
  std::vector<float> distance(static_cast<size_t>(count));
  for (int64_t i = 0; i < count; ++i) distance[size_t(i)] = float(std::sqrt(squared[size_t(i)]));
  return distance;
}

Centerline tskAxis(const BinaryVolume& volume, const TubularClusters& clusters, const TskParameters& p,
                   TskModelSamples* modelSamples) {
  Centerline result;
  const size_t count = clusters.orderedVoxels.size();
  if (count < 2) return result;
  const int n = clusters.orderedCluster.back() + 1;

  // Per cluster: its run in the order, the Gaussian antecedent and the three linear consequents.
  struct Rule {
    double centre = 0, sigma = 0;
    Eigen::Vector3d slope = Eigen::Vector3d::Zero(), intercept = Eigen::Vector3d::Zero();
    bool used = false;
  };
  std::vector<Rule> rules(static_cast<size_t>(n));
  size_t begin = 0;
  while (begin < count) {
    const int j = clusters.orderedCluster[begin];
    size_t end = begin;
    double sumT = 0, sumTT = 0;
    Eigen::Vector3d sumX = Eigen::Vector3d::Zero(), sumTX = Eigen::Vector3d::Zero();
    while (end < count && clusters.orderedCluster[end] == j) {
      const double t = double(end) / double(count - 1);
      const Eigen::Vector3d x = volume.physical(clusters.orderedVoxels[end]);
      sumT += t;
      sumTT += t * t;
      sumX += x;
      sumTX += t * x;
      ++end;
    }
    const double m = double(end - begin), meanT = sumT / m, varT = sumTT / m - meanT * meanT;
    Rule& rule = rules[size_t(j)];
    rule.used = true;
    rule.centre = meanT;
    rule.sigma = std::max(p.antecedentWidth * double(end - begin) / double(count - 1), 1e-9);
    rule.slope =
        varT > 1e-18 ? Eigen::Vector3d((sumTX / m - meanT * sumX / m) / varT) : Eigen::Vector3d::Zero();
    rule.intercept = sumX / m - rule.slope * meanT;
    begin = end;
  }
  auto model = [&](double t) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double weights = 0;
    for (const Rule& rule : rules) {
      if (!rule.used) continue;
      const double u = (t - rule.centre) / rule.sigma;
      if (u * u > 80) continue;  // exp(-40): nothing
      const double w = std::exp(-0.5 * u * u);
      sum += w * (rule.slope * t + rule.intercept);
      weights += w;
    }
    return weights > 0 ? Eigen::Vector3d(sum / weights) : Eigen::Vector3d::Zero();
  };

  // Dense samples of the model between the first and the last cluster's centre (beyond them the end
  // clusters' lines would be extrapolated into the tube's caps and hook), then uniform arc length.
  // The end clusters are left out while their chosen point lies near the wall (border distance below half
  // the median of the chosen points): P0 is on the wall of a cap (the lowest voxel), and the Manhattan
  // layers reach a far cap first at its rim, so the end clusters are lopsided and would hook the axis.
  const std::vector<float>& border = clusters.primitiveBorderDistance;
  std::vector<float> sorted = border;
  std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
  const float enough = 0.5f * sorted[sorted.size() / 2];
  int firstRule = 0, lastRule = n - 1;
  while (firstRule < lastRule && (!rules[size_t(firstRule)].used || border[size_t(firstRule)] < enough))
    ++firstRule;
  while (lastRule > firstRule && (!rules[size_t(lastRule)].used || border[size_t(lastRule)] < enough))
    --lastRule;
  double first = rules[size_t(firstRule)].centre, last = rules[size_t(lastRule)].centre;
  if (!(last > first)) {
    first = 0;
    last = 1;
  }
  const int dense = std::max(200, 16 * n);
  std::vector<Eigen::Vector3d> curve;
  std::vector<double> length{0};
  for (int s = 0; s <= dense; ++s) {
    const double t = first + (last - first) * double(s) / dense;
    curve.push_back(model(t));
    if (s > 0) length.push_back(length.back() + (curve[size_t(s)] - curve[size_t(s) - 1]).norm());
    if (modelSamples) modelSamples->t.push_back(t), modelSamples->point.push_back(curve.back());
  }
  // Beyond the paper's two phases: the centricity criterion of its §2 enforced on the TSK curve (each point
  // moved towards the centre of its perpendicular section, the moves smoothed along the curve).
  if (p.centeringIterations > 0) {
    curve = centerInSections(volume, curve, 36, p.centeringIterations);
    curve = extendToCaps(volume, std::move(curve));
    length.assign(curve.size(), 0.0);
    for (size_t k = 1; k < curve.size(); ++k) length[k] = length[k - 1] + (curve[k] - curve[k - 1]).norm();
  }
  const double step = p.sampleSpacing > 0 ? p.sampleSpacing : volume.spacing.minCoeff();
  const double total = length.back();
  const int samples = std::max(2, int(std::ceil(total / step)) + 1);
  size_t segment = 0;
  for (int s = 0; s < samples; ++s) {
    const double at = total * double(s) / double(samples - 1);
    while (segment + 2 < length.size() && length[segment + 1] < at) ++segment;
    const double span = length[segment + 1] - length[segment];
    const double f = span > 0 ? std::clamp((at - length[segment]) / span, 0.0, 1.0) : 0.0;
    result.points.push_back((1 - f) * curve[segment] + f * curve[segment + 1]);
    result.arcLength.push_back(at);
  }
  const double halfVoxel = 0.5 * volume.spacing.minCoeff();
  const std::vector<double> distance = distanceAtPoints(volume, result.points);
  for (double d : distance) result.radius.push_back(std::max(d - halfVoxel, halfVoxel));
  return result;
}

}  // namespace medial
