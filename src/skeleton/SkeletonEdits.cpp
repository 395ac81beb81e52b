#include "skeleton/SkeletonEdits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace medial {

namespace {

bool isNode(const Skeleton& s, int node) { return node >= 0 && node < s.nodeCount(); }

// 1 % of the bounding-box diagonal: the radius of nodes that had none.
double defaultRadius(const Skeleton& s) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = -low;
  for (const Eigen::Vector3d& p : s.nodes) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double diagonal = s.nodes.empty() ? 0 : (high - low).norm();
  return diagonal > 0 ? 0.01 * diagonal : 1.0;
}

int addNode(Skeleton& s, const Eigen::Vector3d& position, double radius, const Eigen::Matrix3d* axes) {
  s.nodes.push_back(position);
  if (!s.radii.empty()) s.radii.push_back(radius);
  if (!s.ellipsoidAxes.empty())
    s.ellipsoidAxes.push_back(axes ? *axes : Eigen::Matrix3d::Identity() * radius);
  return s.nodeCount() - 1;
}

}  // namespace

bool moveNode(Skeleton& s, int node, const Eigen::Vector3d& position) {
  if (!isNode(s, node)) return false;
  s.nodes[size_t(node)] = position;
  return true;
}

void ensureRadii(Skeleton& s) {
  if (s.radii.empty()) s.radii.assign(s.nodes.size(), defaultRadius(s));
}

bool setNodeRadius(Skeleton& s, int node, double radius) {
  if (!isNode(s, node) || !(radius > 0) || !std::isfinite(radius)) return false;
  ensureRadii(s);
  // An ellipsoid node keeps its shape, scaled with its radius.
  if (!s.ellipsoidAxes.empty()) s.ellipsoidAxes[size_t(node)] *= radius / s.radii[size_t(node)];
  s.radii[size_t(node)] = radius;
  return true;
}

int splitEdge(Skeleton& s, int edge, double t) {
  if (edge < 0 || edge >= s.edgeCount()) return -1;
  t = std::clamp(t, 0.0, 1.0);
  const auto [a, b] = s.edges[size_t(edge)];
  const Eigen::Vector3d position = (1 - t) * s.nodes[size_t(a)] + t * s.nodes[size_t(b)];
  const double radius = s.radii.empty() ? 0 : (1 - t) * s.radii[size_t(a)] + t * s.radii[size_t(b)];
  Eigen::Matrix3d axes;
  if (!s.ellipsoidAxes.empty()) axes = (1 - t) * s.ellipsoidAxes[size_t(a)] + t * s.ellipsoidAxes[size_t(b)];
  const int middle = addNode(s, position, radius, s.ellipsoidAxes.empty() ? nullptr : &axes);
  s.edges[size_t(edge)] = {a, middle};
  s.edges.push_back({middle, b});
  return middle;
}

int addBranch(Skeleton& s, int node, const Eigen::Vector3d& position) {
  if (!isNode(s, node)) return -1;
  const double radius = s.radii.empty() ? 0 : s.radii[size_t(node)];
  const int leaf =
      addNode(s, position, radius, s.ellipsoidAxes.empty() ? nullptr : &s.ellipsoidAxes[size_t(node)]);
  s.edges.push_back({node, leaf});
  return leaf;
}

bool deleteNode(Skeleton& s, int node) {
  if (!isNode(s, node)) return false;
  std::vector<int> neighbours;
  std::vector<std::array<int, 2>> kept;
  for (const auto& e : s.edges) {
    if (e[0] == node)
      neighbours.push_back(e[1]);
    else if (e[1] == node)
      neighbours.push_back(e[0]);
    else
      kept.push_back(e);
  }
  if (neighbours.size() == 2 && neighbours[0] != neighbours[1])
    kept.push_back({neighbours[0], neighbours[1]});
  const auto renumber = [node](int id) { return id > node ? id - 1 : id; };
  for (auto& e : kept) e = {renumber(e[0]), renumber(e[1])};
  s.edges = std::move(kept);
  s.nodes.erase(s.nodes.begin() + node);
  if (!s.radii.empty()) s.radii.erase(s.radii.begin() + node);
  if (!s.ellipsoidAxes.empty()) s.ellipsoidAxes.erase(s.ellipsoidAxes.begin() + node);
  if (s.root == node)
    s.root = neighbours.empty() ? -1 : renumber(neighbours.front());
  else if (s.root > node)
    --s.root;
  if (s.root >= s.nodeCount()) s.root = -1;
  return true;
}

bool setRoot(Skeleton& s, int node) {
  if (!isNode(s, node)) return false;
  s.root = node;
  return true;
}

EdgeNearRay nearestEdgeToRay(const Skeleton& s, const Eigen::Vector3d& origin,
                             const Eigen::Vector3d& direction) {
  EdgeNearRay best;
  best.distance = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d d = direction.normalized();
  for (int i = 0; i < s.edgeCount(); ++i) {
    const Eigen::Vector3d a = s.nodes[size_t(s.edges[size_t(i)][0])],
                          b = s.nodes[size_t(s.edges[size_t(i)][1])];
    // Closest points of the segment a + t (b - a) and the line origin + s d (t clamped to the segment).
    const Eigen::Vector3d u = b - a, w = a - origin;
    const double uu = u.dot(u), ud = u.dot(d), uw = u.dot(w), dw = d.dot(w);
    const double denominator = uu - ud * ud;
    double t = denominator > 1e-12 * std::max(uu, 1e-300) ? (ud * dw - uw) / denominator : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const Eigen::Vector3d p = a + t * u;
    const double distance = ((p - origin) - (p - origin).dot(d) * d).norm();
    if (distance < best.distance) best = {i, t, distance};
  }
  return best;
}

}  // namespace medial
