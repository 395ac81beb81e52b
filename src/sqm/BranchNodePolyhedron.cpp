#include "sqm/BranchNodePolyhedron.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <cmath>
#include <map>
#include <set>

namespace medial {

namespace {

// A hull face whose plane lies closer to the centre than this (in radii), or beyond it, gets a Steiner
// point: its cap is wider than acos(0.25) = 75.5 degrees. (A regular tetrahedron's faces lie at 1/3.)
constexpr double kCapPlaneDistance = 0.25;

Eigen::Vector3d toEigen(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }
OpenMesh::Vec3d toMesh(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

// Where the ray x + t d (t >= 0) leaves the sphere; x lies inside it. Radial projection when d vanishes.
Eigen::Vector3d projectAlongRay(const Eigen::Vector3d& x, Eigen::Vector3d d, const Eigen::Vector3d& centre,
                                double radius) {
  if (d.squaredNorm() < 1e-24) {
    const Eigen::Vector3d radial = x - centre;
    return centre + radius * (radial.squaredNorm() > 0 ? radial.normalized() : Eigen::Vector3d::UnitZ());
  }
  d.normalize();
  const Eigen::Vector3d fromCentre = x - centre;
  const double b = d.dot(fromCentre), c = fromCentre.squaredNorm() - radius * radius;
  const double t = -b + std::sqrt(std::max(0.0, b * b - c));
  return x + t * d;
}

// Triangles of the convex hull of points on a sphere, oriented outwards. Points sharing a supporting
// plane are fanned once; when every point lies on one plane the result is a closed pillow (two fans from
// different apexes, so that no diagonal is shared by four triangles).
std::vector<std::array<int, 3>> hullTriangles(const std::vector<Eigen::Vector3d>& q,
                                              const Eigen::Vector3d& centre, double radius) {
  const int n = int(q.size());
  const double tolerance = 1e-9 * radius;
  std::vector<std::array<int, 3>> faces;
  std::set<std::vector<int>> donePlanes;
  // The polygon's points in counter-clockwise order about `outward`.
  auto counterClockwise = [&](std::vector<int> polygon, const Eigen::Vector3d& outward) {
    Eigen::Vector3d mid = Eigen::Vector3d::Zero();
    for (int i : polygon) mid += q[size_t(i)];
    mid /= double(polygon.size());
    const Eigen::Vector3d u = (q[size_t(polygon[0])] - mid).normalized(), v = outward.cross(u);
    std::sort(polygon.begin(), polygon.end(), [&](int a, int b) {
      const Eigen::Vector3d da = q[size_t(a)] - mid, db = q[size_t(b)] - mid;
      return std::atan2(da.dot(v), da.dot(u)) < std::atan2(db.dot(v), db.dot(u));
    });
    return polygon;
  };
  // Triangles fanned from `apex` over a polygon in counter-clockwise order.
  auto fan = [&](std::vector<int> polygon, int apex) {
    std::rotate(polygon.begin(), std::find(polygon.begin(), polygon.end(), apex), polygon.end());
    for (size_t k = 1; k + 1 < polygon.size(); ++k) faces.push_back({polygon[0], polygon[k], polygon[k + 1]});
  };
  bool allCoplanar = false;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        Eigen::Vector3d normal = (q[size_t(j)] - q[size_t(i)]).cross(q[size_t(k)] - q[size_t(i)]);
        if (normal.norm() < 1e-12 * radius * radius) continue;
        normal.normalize();
        int above = 0, below = 0;
        std::vector<int> onPlane;
        for (int m = 0; m < n; ++m) {
          const double d = normal.dot(q[size_t(m)] - q[size_t(i)]);
          if (d > tolerance)
            ++above;
          else if (d < -tolerance)
            ++below;
          else
            onPlane.push_back(m);
        }
        if (above > 0 && below > 0) continue;
        if (above == 0 && below == 0) allCoplanar = true;
        if (!donePlanes.insert(onPlane).second) continue;
        if (allCoplanar) {
          // Both sides of the one plane: the side facing away from the centre first.
          // The two fans start at neighbouring points so that they share no diagonal (a shared one would
          // carry four triangles: a non-manifold edge).
          const Eigen::Vector3d side =
              normal.dot(q[size_t(i)] - centre) >= 0 ? normal : Eigen::Vector3d(-normal);
          std::vector<int> ring = counterClockwise(onPlane, side);
          fan(ring, ring[0]);
          const int otherApex = ring[1];
          std::reverse(ring.begin(), ring.end());
          fan(ring, otherApex);
          return faces;
        }
        const std::vector<int> ring =
            counterClockwise(onPlane, above == 0 ? normal : Eigen::Vector3d(-normal));
        fan(ring, ring[0]);
      }
  return faces;
}

// The LIE of intersection vertices a and b: the chain of common neighbours, from its end of lower index.
std::vector<BnpMesh::VertexHandle> lieChain(const BnpMesh& mesh, BnpMesh::VertexHandle a,
                                            BnpMesh::VertexHandle b) {
  std::set<int> ofA, common;
  for (auto v : mesh.vv_range(a)) ofA.insert(v.idx());
  for (auto v : mesh.vv_range(b))
    if (ofA.count(v.idx())) common.insert(v.idx());
  auto linked = [&](int v) {
    std::vector<int> result;
    for (auto w : mesh.vv_range(BnpMesh::VertexHandle(v)))
      if (common.count(w.idx())) result.push_back(w.idx());
    return result;
  };
  int start = -1;
  for (int v : common)
    if (linked(v).size() == 1 && (start < 0 || v < start)) start = v;
  std::vector<BnpMesh::VertexHandle> chain;
  if (start < 0) return chain;
  int previous = -1, current = start;
  while (current >= 0) {
    chain.emplace_back(current);
    int next = -1;
    for (int w : linked(current))
      if (w != previous) next = w;
    previous = current;
    current = next;
    if (chain.size() > common.size()) break;  // not a chain: stop rather than loop
  }
  return chain;
}

double oneRingArea(const BnpMesh& mesh, BnpMesh::VertexHandle v) {
  double area = 0;
  for (auto f : mesh.vf_range(v)) {
    std::vector<Eigen::Vector3d> p;
    for (auto w : mesh.fv_range(f)) p.push_back(toEigen(mesh.point(w)));
    area += 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
  }
  return area;
}

void smoothLie(BranchNodePolyhedron& bnp, const std::vector<BnpMesh::VertexHandle>& chain,
               LieSmoothing smoothing) {
  if (chain.size() < 3) return;
  BnpMesh& mesh = bnp.mesh;
  const Eigen::Vector3d c = bnp.centre;
  auto onSphere = [&](const Eigen::Vector3d& p) {
    return projectAlongRay(p, Eigen::Vector3d::Zero(), c, bnp.radius);
  };
  const size_t last = chain.size() - 1;
  switch (smoothing) {
    case LieSmoothing::Quaternion: {
      // Equal angles along the arc from the first to the last vertex of the LIE. The axis is the chain's
      // mean turning axis, not the shortest rotation from first to last: on a pillow the two ends are
      // antipodal and only the chain says which half circle the LIE runs along.
      const Eigen::Vector3d first = toEigen(mesh.point(chain.front())) - c,
                            end = toEigen(mesh.point(chain.back())) - c;
      Eigen::Vector3d axis = Eigen::Vector3d::Zero();
      for (size_t i = 0; i < last; ++i)
        axis += (toEigen(mesh.point(chain[i])) - c).cross(toEigen(mesh.point(chain[i + 1])) - c);
      if (axis.squaredNorm() < 1e-30) break;
      axis.normalize();
      const Eigen::Vector3d f = first - first.dot(axis) * axis, e = end - end.dot(axis) * axis;
      double angle = std::atan2(f.cross(e).dot(axis), f.dot(e));
      if (angle < 0) angle += 2 * M_PI;
      for (size_t i = 1; i < last; ++i) {
        const Eigen::AngleAxisd step(angle * double(i) / double(last), axis);
        mesh.set_point(chain[i], toMesh(onSphere(c + step * first)));
      }
      break;
    }
    case LieSmoothing::Averaging:
      for (size_t i = last - 1; i >= 1; --i) {  // from the last vertex towards the first
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        int count = 0;
        for (auto w : mesh.vv_range(chain[i])) {
          sum += toEigen(mesh.point(w));
          ++count;
        }
        mesh.set_point(chain[i], toMesh(onSphere(sum / count)));
      }
      break;
    case LieSmoothing::AreaLaplacian:
    case LieSmoothing::ValencyLaplacian: {
      std::vector<Eigen::Vector3d> moved(chain.size());
      for (size_t i = 1; i < last; ++i) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        double weights = 0;
        for (auto w : mesh.vv_range(chain[i])) {
          const double weight =
              smoothing == LieSmoothing::AreaLaplacian ? oneRingArea(mesh, w) : double(mesh.valence(w));
          sum += weight * toEigen(mesh.point(w));
          weights += weight;
        }
        moved[i] = onSphere(sum / weights);
      }
      for (size_t i = 1; i < last; ++i) mesh.set_point(chain[i], toMesh(moved[i]));
      break;
    }
  }
}

}  // namespace

const char* lieSmoothingName(LieSmoothing smoothing) {
  switch (smoothing) {
    case LieSmoothing::Averaging:
      return "averaging";
    case LieSmoothing::Quaternion:
      return "quaternion";
    case LieSmoothing::AreaLaplacian:
      return "area-laplacian";
    case LieSmoothing::ValencyLaplacian:
      return "valency-laplacian";
  }
  return "";
}

namespace {
const LieSmoothing kSmoothings[] = {LieSmoothing::Quaternion, LieSmoothing::Averaging,
                                    LieSmoothing::AreaLaplacian, LieSmoothing::ValencyLaplacian};
}

bool parseLieSmoothing(const std::string& name, LieSmoothing& smoothing) {
  for (LieSmoothing s : kSmoothings)
    if (name == lieSmoothingName(s)) {
      smoothing = s;
      return true;
    }
  return false;
}

std::vector<std::string> lieSmoothingNames() {
  std::vector<std::string> names;
  for (LieSmoothing s : kSmoothings) names.push_back(lieSmoothingName(s));
  return names;
}

std::vector<BnpMesh::VertexHandle> BranchNodePolyhedron::orderedRing(int i) const {
  const auto v = intersection[size_t(i)];
  std::vector<BnpMesh::VertexHandle> ring;
  for (auto w : mesh.vv_ccw_range(v)) ring.push_back(w);
  // Orientation check: counter-clockwise about the outward direction through v.
  const Eigen::Vector3d axis = toEigen(mesh.point(v)) - centre;
  Eigen::Vector3d turn = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < ring.size(); ++k)
    turn += (toEigen(mesh.point(ring[k])) - toEigen(mesh.point(v)))
                .cross(toEigen(mesh.point(ring[(k + 1) % ring.size()])) - toEigen(mesh.point(v)));
  if (turn.dot(axis) < 0) std::reverse(ring.begin(), ring.end());
  return ring;
}

bool generateBnp(int node, const Eigen::Vector3d& centre, double radius,
                 const std::vector<int>& neighbourNodes,
                 const std::vector<Eigen::Vector3d>& neighbourPositions, BranchNodePolyhedron& bnp,
                 std::string& error) {
  bnp = BranchNodePolyhedron();
  bnp.node = node;
  bnp.centre = centre;
  bnp.radius = radius;
  bnp.neighbourNodes = neighbourNodes;
  std::vector<Eigen::Vector3d> q;
  for (const auto& p : neighbourPositions) q.push_back(centre + radius * (p - centre).normalized());
  for (size_t i = 0; i < q.size(); ++i)
    for (size_t j = i + 1; j < q.size(); ++j)
      if ((q[i] - q[j]).norm() < 1e-6 * radius) {
        error = "node " + std::to_string(node) + ": the edges to nodes " + std::to_string(neighbourNodes[i]) +
                " and " + std::to_string(neighbourNodes[j]) + " leave it in the same direction";
        return false;
      }
  // Steiner points (beyond the papers): a hull face whose plane passes near the centre, or beyond it, spans
  // a spherical cap wider than 75 degrees (every face of a pillow: coplanar arms, any three arms), and the
  // one-rings of its corners would reach across it, making tube ends that fold. So does a polygon of four
  // or more coplanar points (an octopus's ring of tentacles), fanned from one of them into thin triangles.
  // A point at the cap's middle covers it; it belongs to no tube and its faces stay in the mesh. Up to
  // three rounds.
  const int count = int(q.size());
  std::vector<std::array<int, 3>> hull = hullTriangles(q, centre, radius);
  for (int round = 0; round < 3; ++round) {
    const size_t before = q.size();
    for (const auto& f : hull) {
      const Eigen::Vector3d normal =
          (q[size_t(f[1])] - q[size_t(f[0])]).cross(q[size_t(f[2])] - q[size_t(f[0])]).normalized();
      const double planeDistance = normal.dot(q[size_t(f[0])] - centre);
      const auto onPlane = std::count_if(q.begin(), q.end(), [&](const Eigen::Vector3d& x) {
        return std::abs(normal.dot(x - centre) - planeDistance) < 1e-9 * radius;
      });
      if (planeDistance >= kCapPlaneDistance * radius && onPlane < 4) continue;
      const Eigen::Vector3d pole = centre + radius * normal;
      if (std::none_of(q.begin() + std::ptrdiff_t(before), q.end(),
                       [&](const Eigen::Vector3d& x) { return (x - pole).norm() < 1e-6 * radius; }))
        q.push_back(pole);  // once per plane: a pillow's fan has several triangles on it
    }
    if (q.size() == before) break;
    hull = hullTriangles(q, centre, radius);
  }

  // 1-to-6 subdivision with the projections described in the header.
  std::map<std::pair<int, int>, Eigen::Vector3d> edgeNormal;
  std::vector<Eigen::Vector3d> faceNormal;
  for (const auto& f : hull) {
    faceNormal.push_back(
        (q[size_t(f[1])] - q[size_t(f[0])]).cross(q[size_t(f[2])] - q[size_t(f[0])]).normalized());
    for (int c = 0; c < 3; ++c) {
      const auto key = std::minmax(f[size_t(c)], f[size_t((c + 1) % 3)]);
      // Eigen vectors start uninitialized: the first face sets the sum, the second adds to it.
      const auto [at, fresh] = edgeNormal.try_emplace({key.first, key.second}, faceNormal.back());
      if (!fresh) at->second += faceNormal.back();
    }
  }
  for (size_t i = 0; i < q.size(); ++i)
    (int(i) < count ? bnp.intersection : bnp.steiner).push_back(bnp.mesh.add_vertex(toMesh(q[i])));
  std::map<std::pair<int, int>, BnpMesh::VertexHandle> middle;
  std::map<std::pair<int, int>, Eigen::Vector3d> middlePoint;
  for (const auto& [edge, normal] : edgeNormal) {
    const Eigen::Vector3d p =
        projectAlongRay(0.5 * (q[size_t(edge.first)] + q[size_t(edge.second)]), normal, centre, radius);
    middlePoint[edge] = p;
    middle[edge] = bnp.mesh.add_vertex(toMesh(p));
    bnp.hullEdges.push_back(edge);
  }
  bnp.lieSplits.assign(bnp.hullEdges.size(), 0);
  for (size_t f = 0; f < hull.size(); ++f) {
    const auto& t = hull[f];
    std::array<std::pair<int, int>, 3> e;
    for (int c = 0; c < 3; ++c) {
      const auto key = std::minmax(t[size_t(c)], t[size_t((c + 1) % 3)]);
      e[size_t(c)] = {key.first, key.second};
    }
    const Eigen::Vector3d fixDirection =
        (middlePoint[e[1]] - middlePoint[e[0]]).cross(middlePoint[e[2]] - middlePoint[e[0]]);
    const Eigen::Vector3d centroid = (q[size_t(t[0])] + q[size_t(t[1])] + q[size_t(t[2])]) / 3.0;
    const auto centreVertex = bnp.mesh.add_vertex(toMesh(projectAlongRay(
        centroid, fixDirection.dot(faceNormal[f]) > 0 ? fixDirection : faceNormal[f], centre, radius)));
    for (int c = 0; c < 3; ++c) {
      const int index = t[size_t(c)];
      const auto corner =
          index < count ? bnp.intersection[size_t(index)] : bnp.steiner[size_t(index - count)];
      const auto after = middle[e[size_t(c)]], before = middle[e[size_t((c + 2) % 3)]];
      bnp.mesh.add_face(corner, after, centreVertex);
      bnp.mesh.add_face(before, corner, centreVertex);
    }
  }
  return true;
}

bool refineBnp(BranchNodePolyhedron& bnp, const std::vector<int>& target, const std::vector<bool>& exact,
               LieSmoothing smoothing, std::string& error) {
  const int count = int(bnp.intersection.size());
  std::vector<int> order;
  for (int i = 0; i < count; ++i)
    if (exact[size_t(i)]) order.push_back(i);
  for (int i = 0; i < count; ++i)
    if (!exact[size_t(i)]) order.push_back(i);
  for (int x : order) {
    if (exact[size_t(x)] && bnp.valence(x) > target[size_t(x)]) {
      error = "node " + std::to_string(bnp.node) +
              ": its polyhedron has more edges around the tube to node " +
              std::to_string(bnp.neighbourNodes[size_t(x)]) + " than the other end can match";
      return false;
    }
    while (bnp.valence(x) < target[size_t(x)]) {
      // Filter 1: the LIE whose other vertex needs the most splits; filter 2: the LIE split least so far.
      int best = -1, bestNeed = 0, bestSplits = 0;
      for (size_t e = 0; e < bnp.hullEdges.size(); ++e) {
        const auto [a, b] = bnp.hullEdges[e];
        if (a != x && b != x) continue;
        const int y = a == x ? b : a;
        // A Steiner point has no tube, so any number of splits will do; its LIEs come last, so that its
        // valence stays even where it can and its cap closes with quads only.
        const bool steiner = y >= count;
        const int need = steiner ? std::numeric_limits<int>::min() / 2 : target[size_t(y)] - bnp.valence(y);
        if (!steiner && exact[size_t(y)] && need <= 0) continue;
        if (best < 0 || need > bestNeed || (need == bestNeed && bnp.lieSplits[e] < bestSplits)) {
          best = int(e);
          bestNeed = need;
          bestSplits = bnp.lieSplits[e];
        }
      }
      if (best < 0) {
        error = "node " + std::to_string(bnp.node) +
                ": no edge of its polyhedron can be split to match the tube to node " +
                std::to_string(bnp.neighbourNodes[size_t(x)]);
        return false;
      }
      const auto [a, b] = bnp.hullEdges[size_t(best)];
      const auto chain = lieChain(bnp.mesh, bnp.hullVertex(a), bnp.hullVertex(b));
      if (chain.size() < 2) {
        error = "node " + std::to_string(bnp.node) +
                ": broken polyhedron (no link between two intersection vertices)";
        return false;
      }
      const auto edge = bnp.mesh.edge_handle(bnp.mesh.find_halfedge(chain[0], chain[1]));
      bnp.mesh.split(edge, (bnp.mesh.point(chain[0]) + bnp.mesh.point(chain[1])) * 0.5);
      ++bnp.lieSplits[size_t(best)];
      smoothLie(bnp, lieChain(bnp.mesh, bnp.hullVertex(a), bnp.hullVertex(b)), smoothing);
    }
  }
  return true;
}

}  // namespace medial
