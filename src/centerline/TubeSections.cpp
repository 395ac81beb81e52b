#include "TubeSections.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

namespace medial {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The structure's mask at a physical point, trilinearly interpolated between voxel centres (0 outside).
double maskAt(const BinaryVolume& volume, const Eigen::Matrix3d& toIndex, const Eigen::Vector3d& point) {
  const Eigen::Vector3d c = toIndex * (point - volume.origin);
  const int i = int(std::floor(c.x())), j = int(std::floor(c.y())), k = int(std::floor(c.z()));
  const double fx = c.x() - i, fy = c.y() - j, fz = c.z() - k;
  double value = 0;
  if (i >= 0 && j >= 0 && k >= 0 && i + 1 < volume.size[0] && j + 1 < volume.size[1] &&
      k + 1 < volume.size[2]) {
    // All eight voxels in the volume (nearly always): offsets from the first, no bounds to check.
    const int64_t at = volume.index(i, j, k), row = volume.size[0],
                  slice = int64_t(volume.size[0]) * volume.size[1];
    const uint8_t* m = volume.inside.data() + at;
    const double x0 = 1 - fx, y0 = 1 - fy, z0 = 1 - fz;
    return z0 * (y0 * (x0 * m[0] + fx * m[1]) + fy * (x0 * m[row] + fx * m[row + 1])) +
           fz * (y0 * (x0 * m[slice] + fx * m[slice + 1]) +
                 fy * (x0 * m[slice + row] + fx * m[slice + row + 1]));
  }
  for (int dk = 0; dk < 2; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di) {
        if (!volume.contains(i + di, j + dj, k + dk) ||
            !volume.inside[size_t(volume.index(i + di, j + dj, k + dk))])
          continue;
        value += (di ? fx : 1 - fx) * (dj ? fy : 1 - fy) * (dk ? fz : 1 - fz);
      }
  return value;
}

// Distance from `start` along `direction` to where the mask falls below 1/2, or NaN when it does not within
// `limit`. The ray advances by `step` (half the smallest voxel spacing: a background voxel's dip below 1/2
// is a voxel wide, so no wall is stepped over); the step that crosses is halved twice (an interval of an
// eighth of a voxel) and the crossing interpolated linearly in it. The mask is read about 2.5 times less
// often than with fixed fifth-of-a-voxel steps, for the same precision.
double wallDistance(const BinaryVolume& volume, const Eigen::Matrix3d& toIndex, const Eigen::Vector3d& start,
                    const Eigen::Vector3d& direction, double step, double limit) {
  double previous = maskAt(volume, toIndex, start);
  if (previous < 0.5) return 0.0;  // the axis point itself lies on or outside the wall
  for (double t = step; t <= limit + 1e-12; t += step) {
    const double value = maskAt(volume, toIndex, start + t * direction);
    if (value >= 0.5) {
      previous = value;
      continue;
    }
    double inside = t - step, outside = t, insideValue = previous, outsideValue = value;
    for (int halving = 0; halving < 2; ++halving) {
      const double middle = 0.5 * (inside + outside);
      const double m = maskAt(volume, toIndex, start + middle * direction);
      if (m >= 0.5)
        inside = middle, insideValue = m;
      else
        outside = middle, outsideValue = m;
    }
    return inside + (outside - inside) * (insideValue - 0.5) / (insideValue - outsideValue);
  }
  return kNaN;
}

// Rays cast in sections of the structure: the wall distance along each of `rays` directions, evenly spaced
// in angle from `normal` towards `binormal` (NaN where no wall lies within the limit).
struct SectionRays {
  SectionRays(const BinaryVolume& volume, double maxRadius)
      : volume(volume),
        toIndex(volume.spacing.cwiseInverse().asDiagonal() * volume.direction.inverse()),
        step(0.5 * volume.spacing.minCoeff()),
        limit(maxRadius > 0 ? maxRadius : 100.0 * volume.spacing.minCoeff()) {}

  std::vector<double> walls(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                            const Eigen::Vector3d& binormal, int rays) const {
    std::vector<double> wall(static_cast<size_t>(rays));
    for (int r = 0; r < rays; ++r) {
      const double angle = 2 * M_PI * r / rays;
      wall[size_t(r)] = wallDistance(volume, toIndex, centre,
                                     std::cos(angle) * normal + std::sin(angle) * binormal, step, limit);
    }
    return wall;
  }

  const BinaryVolume& volume;
  const Eigen::Matrix3d toIndex;
  const double step, limit;
};

// Angle 0 of the sections transported along the axis: the previous normal without its tangential part (a
// rotation-minimizing frame for fine spacing), so that sections and the unfolded image do not twist.
Eigen::Vector3d transportNormal(const Eigen::Vector3d& previous, const Eigen::Vector3d& tangent, bool first) {
  const Eigen::Vector3d normal = first ? tangent.unitOrthogonal() : previous;
  return (normal - normal.dot(tangent) * tangent).normalized();
}

std::vector<double> arcLengths(const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> arc(points.size(), 0.0);
  for (size_t i = 1; i < points.size(); ++i) arc[i] = arc[i - 1] + (points[i] - points[i - 1]).norm();
  return arc;
}

// The point at arc length s of the polyline, and the unit tangent of its segment.
void pointAt(const std::vector<Eigen::Vector3d>& axis, const std::vector<double>& arc, double s,
             Eigen::Vector3d& point, Eigen::Vector3d& tangent) {
  size_t i = size_t(std::upper_bound(arc.begin(), arc.end(), s) - arc.begin());
  i = std::clamp<size_t>(i, 1, axis.size() - 1);
  const double span = arc[i] - arc[i - 1];
  const double t = span > 0 ? std::clamp((s - arc[i - 1]) / span, 0.0, 1.0) : 0.0;
  point = axis[i - 1] + t * (axis[i] - axis[i - 1]);
  // Tangent from a central difference over about two segments, smoother than one segment's direction.
  const Eigen::Vector3d ahead = axis[std::min(i + 1, axis.size() - 1)], behind = axis[i >= 2 ? i - 2 : 0];
  tangent = (ahead - behind).normalized();
}

}  // namespace

TubeSections tubeSections(const BinaryVolume& volume, const std::vector<Eigen::Vector3d>& axis,
                          const SectionParameters& parameters, const std::function<bool(double)>& keepGoing) {
  TubeSections result;
  if (axis.size() < 2 || parameters.spacing <= 0 || parameters.rays < 4) return result;
  const std::vector<double> arc = arcLengths(axis);
  if (arc.back() <= 0) return result;

  const int rays = parameters.rays + parameters.rays % 2;  // even: opposite rays pair into diameters
  result.rays = rays;
  const SectionRays caster(volume, parameters.maxRadius);

  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  const int sections = int(std::floor(arc.back() / parameters.spacing)) + 1;
  for (int n = 0; n < sections; ++n) {
    if (keepGoing && n % 16 == 0 && !keepGoing(double(n) / sections)) return TubeSections{};
    const double s = n * parameters.spacing;
    Eigen::Vector3d center, tangent;
    pointAt(axis, arc, s, center, tangent);
    normal = transportNormal(normal, tangent, n == 0);
    std::vector<double> wall = caster.walls(center, normal, tangent.cross(normal), rays);
    // The perimeter is measured on the wall distances smoothed over the angle ([1 2 1] / 4, circular): the
    // voxel staircase makes consecutive rays jitter by a fraction of a voxel, and chords through that
    // jitter overestimate the length by several per cent. Diameters and area use the raw distances.
    std::vector<double> smooth(static_cast<size_t>(rays));
    for (int r = 0; r < rays; ++r)
      smooth[size_t(r)] = 0.25 * wall[size_t((r + rays - 1) % rays)] + 0.5 * wall[size_t(r)] +
                          0.25 * wall[size_t((r + 1) % rays)];
    double minDiameter = std::numeric_limits<double>::infinity(), maxDiameter = 0, perimeter = 0, area = 0;
    const double sinStep = std::sin(2 * M_PI / rays), cosStep = std::cos(2 * M_PI / rays);
    for (int r = 0; r < rays; ++r) {
      const double a = wall[size_t(r)], b = wall[size_t((r + 1) % rays)];
      if (r < rays / 2) {
        const double d = a + wall[size_t(r + rays / 2)];
        minDiameter = std::min(minDiameter, d);
        maxDiameter = std::max(maxDiameter, d);
      }
      // Chord between consecutive wall points (law of cosines) and the triangle they span with the axis.
      const double sa = smooth[size_t(r)], sb = smooth[size_t((r + 1) % rays)];
      perimeter += std::sqrt(std::max(0.0, sa * sa + sb * sb - 2 * sa * sb * cosStep));
      area += 0.5 * a * b * sinStep;
    }
    const bool complete = std::none_of(wall.begin(), wall.end(), [](double w) { return std::isnan(w); });
    result.arcLength.push_back(s);
    result.center.push_back(center);
    result.tangent.push_back(tangent);
    result.normal.push_back(normal);
    result.wall.push_back(std::move(wall));
    result.minDiameter.push_back(complete ? minDiameter : kNaN);
    result.maxDiameter.push_back(complete ? maxDiameter : kNaN);
    result.perimeter.push_back(complete ? perimeter : kNaN);
    result.area.push_back(complete ? area : kNaN);
  }
  if (keepGoing) keepGoing(1.0);
  return result;
}

namespace {

// The area centroid of a section's wall polygon (ray lengths `distances` at equal angles), in the section's
// (normal, binormal) coordinates, and the median ray length; false for a section that says little about
// the centre. Where the plane cuts a bend obliquely, or reaches another loop, a few rays run far: rays
// longer than 1.5 x the median are clipped, and a section with more than a quarter of them clipped is
// skipped. An elongated section (an oblique cut through a bend, or a polyp reaching in) does not locate
// the centre either: skipped when the longest ray exceeds the shortest by more than 1.8 times. A section
// kept whose polygon has no area gives its median but no centroid.
enum class Section { Skipped, NoArea, Centred };

Section sectionCentroid(const std::vector<double>& distances, int rays, Eigen::Vector2d& centroid,
                        double& median) {
  if (std::any_of(distances.begin(), distances.end(), [](double d) { return std::isnan(d); }))
    return Section::Skipped;
  std::vector<Eigen::Vector2d> wall;
  for (int r = 0; r < rays; ++r) {
    const double angle = 2 * M_PI * r / rays;
    wall.emplace_back(distances[size_t(r)] * std::cos(angle), distances[size_t(r)] * std::sin(angle));
  }
  std::vector<double> lengths;
  for (const auto& w : wall) lengths.push_back(w.norm());
  std::nth_element(lengths.begin(), lengths.begin() + rays / 2, lengths.end());
  median = lengths[size_t(rays / 2)];
  const double cap = 1.5 * median;
  int clipped = 0;
  for (auto& w : wall)
    if (w.norm() > cap) w *= cap / w.norm(), ++clipped;
  if (clipped > rays / 4) return Section::Skipped;
  double shortest = std::numeric_limits<double>::infinity(), longest = 0;
  for (const auto& w : wall) shortest = std::min(shortest, w.norm()), longest = std::max(longest, w.norm());
  if (longest > 1.8 * shortest) return Section::Skipped;
  double area = 0;
  centroid = Eigen::Vector2d::Zero();
  for (int r = 0; r < rays; ++r) {
    const Eigen::Vector2d& a = wall[size_t(r)];
    const Eigen::Vector2d& b = wall[size_t((r + 1) % rays)];
    const double cross = a.x() * b.y() - a.y() * b.x();
    area += cross;
    centroid += cross * (a + b);
  }
  if (std::abs(area) < 1e-12) return Section::NoArea;
  centroid /= 3 * area;
  return Section::Centred;
}

// Skipped sections (oblique cuts at sharp bends) take the move interpolated between their measured
// neighbours: a zero move among moved neighbours would put a kink in the line.
void interpolateSkippedMoves(const std::vector<char>& measured, const std::vector<double>& arc,
                             std::vector<Eigen::Vector3d>& offset) {
  const size_t n = offset.size();
  size_t previous = n;  // last measured index
  for (size_t i = 0; i <= n; ++i) {
    if (i < n && !measured[i]) continue;
    const size_t first = previous == n ? 0 : previous + 1;
    for (size_t k = first; k < i; ++k) {
      if (previous == n && i == n) break;  // nothing measured at all
      if (previous == n)
        offset[k] = offset[i];
      else if (i == n)
        offset[k] = offset[previous];
      else {
        const double span = arc[i] - arc[previous];
        const double t = span > 0 ? (arc[k] - arc[previous]) / span : 0.0;
        offset[k] = (1 - t) * offset[previous] + t * offset[i];
      }
    }
    previous = i;
  }
}

// Sections that disagree from one point to the next (a bend cut obliquely) leave sub-voxel wiggles: one
// moving average of the positions over +-window of arc length smooths them without flattening the bends,
// symmetric so that the ends stay where they are.
std::vector<Eigen::Vector3d> symmetricAverage(const std::vector<Eigen::Vector3d>& axis, double window) {
  const size_t n = axis.size();
  const std::vector<double> arc = arcLengths(axis);
  std::vector<Eigen::Vector3d> smooth(axis);
  size_t lo = 0, hi = 0;
  for (size_t i = 0; i < n; ++i) {
    while (arc[i] - arc[lo] > window) ++lo;
    while (hi + 1 < n && arc[hi + 1] - arc[i] <= window) ++hi;
    const size_t reach = std::min(i - lo, hi - i);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (size_t k = i - reach; k <= i + reach; ++k) sum += axis[k];
    smooth[i] = sum / double(2 * reach + 1);
  }
  return smooth;
}

}  // namespace

std::vector<Eigen::Vector3d> centerInSections(const BinaryVolume& volume, std::vector<Eigen::Vector3d> axis,
                                              int rays, int iterations, double smoothing) {
  const size_t n = axis.size();
  if (n < 3 || rays < 8) return axis;
  const SectionRays caster(volume, 0.0);
  for (int iteration = 0; iteration < iterations; ++iteration) {
    std::vector<Eigen::Vector3d> offset(n, Eigen::Vector3d::Zero());
    std::vector<char> measured(n, 0);  // the section gave a centre
    std::vector<double> radii;         // median ray length of every section used
    // The sections' frames, transported along the axis (in order), then their walls (two threads: the
    // rays are most of the time).
    std::vector<Eigen::Vector3d> normals(n), binormals(n);
    Eigen::Vector3d transported = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d tangent = (axis[std::min(i + 1, n - 1)] - axis[i > 0 ? i - 1 : 0]).normalized();
      normals[i] = transported = transportNormal(transported, tangent, i == 0);
      binormals[i] = tangent.cross(transported);
    }
    std::vector<std::vector<double>> walls(n);
    const auto cast = [&](size_t from, size_t to) {
      for (size_t i = from; i < to; ++i) walls[i] = caster.walls(axis[i], normals[i], binormals[i], rays);
    };
    std::thread second(cast, n / 2, n);
    cast(0, n / 2);
    second.join();
    for (size_t i = 0; i < n; ++i) {
      Eigen::Vector2d centroid;
      double median = 0;
      const Section section = sectionCentroid(walls[i], rays, centroid, median);
      if (section != Section::Skipped) radii.push_back(median);
      if (section != Section::Centred) continue;
      if (centroid.norm() > 0.5 * median) centroid *= 0.5 * median / centroid.norm();  // small steps
      offset[i] = centroid.x() * normals[i] + centroid.y() * binormals[i];
      measured[i] = 1;
    }
    if (radii.empty()) break;
    const std::vector<double> arc = arcLengths(axis);
    interpolateSkippedMoves(measured, arc, offset);
    // Within a radius of either end the sections cut the end caps: the moves fade out towards the ends.
    std::nth_element(radii.begin(), radii.begin() + long(radii.size() / 2), radii.end());
    const double typical = std::max(radii[radii.size() / 2], 1e-9);
    for (size_t i = 0; i < n; ++i)
      offset[i] *= std::clamp(std::min(arc[i], arc.back() - arc[i]) / typical, 0.0, 1.0);
    // Moving average of the moves over +-smoothing mm of arc length.
    std::vector<Eigen::Vector3d> moved(axis);
    size_t lo = 0, hi = 0;
    for (size_t i = 0; i < n; ++i) {
      while (arc[i] - arc[lo] > smoothing) ++lo;
      while (hi + 1 < n && arc[hi + 1] - arc[i] <= smoothing) ++hi;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (size_t k = lo; k <= hi; ++k) sum += offset[k];
      moved[i] = axis[i] + sum / double(hi - lo + 1);
    }
    axis = std::move(moved);
  }
  return symmetricAverage(axis, volume.spacing.maxCoeff());  // +-1 voxel
}

namespace {

// The axis grown from its last point towards the cap ahead (see extendToCaps), the new points only.
std::vector<Eigen::Vector3d> growTowardsCap(const SectionRays& caster,
                                            const std::vector<Eigen::Vector3d>& axis, int rays) {
  std::vector<Eigen::Vector3d> grown;
  const double step = caster.volume.spacing.minCoeff();
  const std::vector<double> arc = arcLengths(axis);
  // The end's direction over the last two voxels of arc length (or the whole line when shorter).
  size_t back = axis.size() - 1;
  while (back > 0 && arc.back() - arc[back] < 2 * step) --back;
  if (back == axis.size() - 1) return grown;
  Eigen::Vector3d direction = (axis.back() - axis[back]).normalized(), at = axis.back();
  double travelled = 0, median = 0;
  for (int k = 0; k < 100000; ++k) {
    Eigen::Vector3d next = at + step * direction;
    const Eigen::Vector3d normal = direction.unitOrthogonal(), binormal = direction.cross(normal);
    bool centred = true;
    for (int refine = 0; refine < 3 && centred; ++refine) {  // the centroid of the section, found again
      Eigen::Vector2d centroid;
      centred = sectionCentroid(caster.walls(next, normal, binormal, rays), rays, centroid, median) ==
                Section::Centred;
      if (centred)
        next += std::min(1.0, 0.5 * median / std::max(centroid.norm(), 1e-12)) *
                (centroid.x() * normal + centroid.y() * binormal);
    }
    if (!centred || !(median > 0)) break;
    // One radius before the cap: the wall straight ahead nearer than the section's median radius.
    const double ahead =
        wallDistance(caster.volume, caster.toIndex, next, direction, caster.step, caster.limit);
    if (!(ahead >= median) || travelled > 10 * median) break;
    direction = (0.7 * direction + 0.3 * (next - at).normalized()).normalized();
    travelled += (next - at).norm();
    grown.push_back(next);
    at = next;
  }
  return grown;
}

}  // namespace

std::vector<Eigen::Vector3d> extendToCaps(const BinaryVolume& volume, std::vector<Eigen::Vector3d> axis,
                                          int rays) {
  if (axis.size() < 2) return axis;
  const SectionRays caster(volume, 0.0);
  const std::vector<Eigen::Vector3d> after = growTowardsCap(caster, axis, rays);
  axis.insert(axis.end(), after.begin(), after.end());
  std::reverse(axis.begin(), axis.end());
  const std::vector<Eigen::Vector3d> before = growTowardsCap(caster, axis, rays);
  axis.insert(axis.end(), before.begin(), before.end());
  std::reverse(axis.begin(), axis.end());
  return axis;
}

}  // namespace medial
