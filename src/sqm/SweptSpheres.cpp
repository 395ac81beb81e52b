#include "sqm/SweptSpheres.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace medial {

namespace {

// `away`: the direction for the centre itself - the fan apex that closes a leaf lies at the leaf's centre
// and goes out along the edge, so that the leaf's tube ends in its sphere (a zero vector: none).
SweptPoint onSphere(const Eigen::Vector3d& p, const Eigen::Vector3d& centre, double radius,
                    const Eigen::Vector3d& away = Eigen::Vector3d::Zero()) {
  SweptPoint s;
  s.centre = centre;
  s.radius = radius;
  s.distance = (p - centre).norm();
  s.found = true;
  if (s.distance > 1e-12 * radius)
    s.direction = (p - centre) / s.distance;
  else if (away.squaredNorm() > 0)
    s.direction = away;
  else
    s.found = false;
  return s;
}

// Extension 3: the cross-section at t interpolates the ends' ellipsoid matrices; along a unit direction u
// perpendicular to the axis its radius is 1 / |M(t)^-1 u| (r for M = r I).
SweptPoint onEllipsoidCone(const Eigen::Vector3d& p, const Skeleton& s, int edge) {
  const auto& e = s.edges[size_t(edge)];
  const Eigen::Vector3d a = s.nodes[size_t(e[0])], ab = s.nodes[size_t(e[1])] - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  SweptPoint c = onSphere(p, a + t * ab, (1 - t) * s.radii[size_t(e[0])] + t * s.radii[size_t(e[1])]);
  if (!c.found) return c;
  const Eigen::Matrix3d m = (1 - t) * s.ellipsoidAxes[size_t(e[0])] + t * s.ellipsoidAxes[size_t(e[1])];
  // Eigen's closed-form 3x3 inverse (cofactors) where m is well conditioned, a pivoting LU otherwise: this
  // runs for every refined vertex of an ellipsoid's tubes (the fish refined three times, without the fold
  // repair: 26.6 ms with the LU for all, 18.5 ms so).
  double determinant = 0;
  bool invertible = false;
  Eigen::Matrix3d inverse;
  const double size = m.norm();  // cubed by hand: std::pow took 9 % of the fish refined three times
  m.computeInverseAndDetWithCheck(inverse, determinant, invertible, 1e-12 * size * size * size);
  const Eigen::Vector3d local =
      invertible ? Eigen::Vector3d(inverse * c.direction) : m.fullPivLu().solve(c.direction);
  if (local.norm() > 0) c.radius = 1 / local.norm();
  return c;
}

}  // namespace

SweptSpheres::SweptSpheres(const Skeleton& skeleton) : skeleton_(skeleton) {
  for (const auto& e : skeleton.edges) {
    const Eigen::Vector3d a = skeleton.nodes[size_t(e[0])], b = skeleton.nodes[size_t(e[1])];
    double r = std::max(skeleton.radii[size_t(e[0])], skeleton.radii[size_t(e[1])]);
    if (!skeleton.ellipsoidAxes.empty())  // the largest semi-axis of either end
      for (int n : e) r = std::max(r, skeleton.ellipsoidAxes[size_t(n)].colwise().norm().maxCoeff());
    low_.push_back(a.cwiseMin(b).array() - r);
    high_.push_back(a.cwiseMax(b).array() + r);
  }
}

SweptPoint SweptSpheres::project(const Eigen::Vector3d& p, int edge) const {
  const Skeleton& s = skeleton_;
  if (!s.ellipsoidAxes.empty()) return onEllipsoidCone(p, s, edge);
  const auto& e = s.edges[size_t(edge)];
  const Eigen::Vector3d a = s.nodes[size_t(e[0])], b = s.nodes[size_t(e[1])];
  const double r1 = s.radii[size_t(e[0])], r2 = s.radii[size_t(e[1])], length = (b - a).norm();
  if (!(length > 0)) return onSphere(p, a, std::max(r1, r2));  // coincident ends: one sphere
  // One sphere holds the other: the larger one is the whole swept volume.
  const Eigen::Vector3d axis = (b - a) / length;
  if (std::abs(r1 - r2) >= length) return r1 >= r2 ? onSphere(p, a, r1, -axis) : onSphere(p, b, r2, axis);
  // In the plane of the axis and p: y along the axis from a, x the distance from it. The tangent cone
  // touches the spheres where the outward normal is (cos phi, sin phi), sin phi = (r1 - r2) / length;
  // w is p's coordinate along the cone's generator from its tangent point on sphere a.
  const double y = (p - a).dot(axis);
  const Eigen::Vector3d across = p - a - y * axis;
  const double x = across.norm(), sinPhi = (r1 - r2) / length, cosPhi = std::sqrt(1 - sinPhi * sinPhi);
  const double w = -x * sinPhi + y * cosPhi;
  if (w <= 0) return onSphere(p, a, r1, -axis);
  if (w >= length * cosPhi) return onSphere(p, b, r2, axis);
  SweptPoint c;
  if (x <= 1e-12 * std::max(r1, r2)) {  // on the axis: no direction
    c.radius = r1 + (r2 - r1) * y / length;
    return c;
  }
  c.direction = cosPhi * across / x + sinPhi * axis;  // the cone's outward normal through p
  c.distance = x / cosPhi;                            // from the axis point the normal comes from
  c.centre = p - c.distance * c.direction;
  c.radius = r1 - (y - c.distance * sinPhi) * sinPhi;
  c.found = true;
  return c;
}

std::vector<int> SweptSpheres::edgesNear(const Eigen::Vector3d& low, const Eigen::Vector3d& high,
                                         double margin) const {
  std::vector<int> edges;
  for (size_t e = 0; e < low_.size(); ++e)
    if (((low_[e].array() - margin) <= high.array()).all() &&
        ((high_[e].array() + margin) >= low.array()).all())
      edges.push_back(int(e));
  return edges;
}

double SweptSpheres::signedDistance(const Eigen::Vector3d& p) const {
  double nearest = INFINITY;
  for (int e = 0; e < skeleton_.edgeCount(); ++e) {
    const SweptPoint c = project(p, e);
    nearest = std::min(nearest, c.found ? c.signedDistance() : -c.radius);
  }
  return nearest;
}

}  // namespace medial
