#include "contraction/CycleRepair.h"

#include "mesh/HomologyLoops.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace medial {

namespace {

using Polygon = std::vector<Eigen::Vector3d>;

struct Box {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = Eigen::Vector3d::Constant(-INFINITY);
  explicit Box(const Polygon& p) {
    for (const auto& x : p) {
      low = low.cwiseMin(x);
      high = high.cwiseMax(x);
    }
  }
  bool overlaps(const Box& o) const {
    return (low.array() <= o.high.array()).all() && (o.low.array() <= high.array()).all();
  }
};

// Curves in disjoint boxes are split by a plane, so they do not link.
double linkingNumberOrZero(const Polygon& a, const Box& boxA, const Polygon& b, const Box& boxB) {
  return boxA.overlaps(boxB) ? linkingNumber(a, b) : 0.0;
}

struct Normals {
  Vertices vertex, face;  // unit, outward
  std::vector<std::vector<int>> facesAround;
};

Normals meshNormals(const TriangleMesh& mesh) {
  Normals n{Vertices::Zero(mesh.vertices.rows(), 3), Vertices::Zero(mesh.faces.rows(), 3),
            std::vector<std::vector<int>>(size_t(mesh.vertices.rows()))};
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    const Eigen::RowVector3d p0 = mesh.vertices.row(mesh.faces(f, 0)),
                             p1 = mesh.vertices.row(mesh.faces(f, 1)),
                             p2 = mesh.vertices.row(mesh.faces(f, 2));
    const Eigen::RowVector3d areaNormal = (p1 - p0).cross(p2 - p0);  // twice the area
    n.face.row(f) = areaNormal.norm() > 0 ? Eigen::RowVector3d(areaNormal.normalized()) : areaNormal;
    for (int c = 0; c < 3; ++c) {
      n.vertex.row(mesh.faces(f, c)) += areaNormal;
      n.facesAround[size_t(mesh.faces(f, c))].push_back(int(f));
    }
  }
  for (Eigen::Index v = 0; v < n.vertex.rows(); ++v)
    if (n.vertex.row(v).norm() > 0) n.vertex.row(v).normalize();
  return n;
}

struct PushedLoop {
  Polygon out, in, deep;                  // pushed out, in (as far as out), and deep into the material
  double length = 0;                      // of the loop
  bool inside = true, deepInside = true;  // every pushed-in (deep) point found inside the mesh
};

// Out and in by a tenth of the loop's shortest edge at the vertex (a push that keeps the loop's shape, and
// so its class, around the smallest tunnel), and deep: half the material's thickness along the inward
// normal (the middle of the material, where a skeleton belongs). In-pushes are halved until inside.
// Where the inverted vertex normal does not lead inside (a fold of flipped triangles, the tip of a spike, a
// mesh oriented inward), the first that does of the vertex normal and the incident face normals, either
// way round, from the vertex or else from the face's centroid.
PushedLoop pushLoop(const std::vector<int>& loop, const TriangleMesh& mesh, const Normals& normals,
                    const InsideTest& inside) {
  PushedLoop pushed;
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i) {
    const int vertex = loop[i];
    const double edge =
        std::min((mesh.vertices.row(loop[(i + 1) % n]) - mesh.vertices.row(vertex)).norm(),
                 (mesh.vertices.row(loop[(i + n - 1) % n]) - mesh.vertices.row(vertex)).norm());
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> starts{
        {mesh.vertices.row(vertex).transpose(), normals.vertex.row(vertex).transpose()}};
    for (int f : normals.facesAround[size_t(vertex)])
      starts.emplace_back(mesh.vertices.row(vertex).transpose(), normals.face.row(f).transpose());
    for (int f : normals.facesAround[size_t(vertex)]) {
      const Eigen::Vector3d centroid =
          (mesh.vertices.row(mesh.faces(f, 0)) + mesh.vertices.row(mesh.faces(f, 1)) +
           mesh.vertices.row(mesh.faces(f, 2)))
              .transpose() /
          3;
      starts.emplace_back(centroid, normals.face.row(f).transpose());
    }
    Eigen::Vector3d p = starts.front().first, normal = starts.front().second;
    double thickness = INFINITY;
    bool found = false;
    for (size_t k = 0; k < 2 * starts.size() && !found; ++k) {
      p = starts[k / 2].first;
      normal =
          k % 2 == 0 ? starts[k / 2].second : Eigen::Vector3d(-starts[k / 2].second);  // either orientation
      const double start = 1e-3 * edge;
      thickness = start + inside.distanceAlongRay(p - start * normal, -normal);
      found = inside.contains(p - std::min(0.1 * edge, 0.5 * (std::isfinite(thickness) ? thickness : edge)) *
                                      normal);
    }
    pushed.out.push_back(p + 0.1 * edge * normal);
    auto pushIn = [&](double depth, bool& allInside) {
      if (!std::isfinite(depth)) depth = edge;
      Eigen::Vector3d q = p - depth * normal;
      for (int halving = 0; halving < 8 && !inside.contains(q); ++halving) q = p - (depth *= 0.5) * normal;
      allInside = allInside && inside.contains(q);
      return q;
    };
    pushed.in.push_back(pushIn(std::min(0.1 * edge, 0.5 * thickness), pushed.inside));
    pushed.deep.push_back(pushIn(0.5 * thickness, pushed.deepInside));
    pushed.length += (mesh.vertices.row(loop[(i + 1) % n]) - mesh.vertices.row(vertex)).norm();
  }
  return pushed;
}

// One polygon per independent cycle of the graph: each edge outside a spanning forest closed by the tree
// paths of its ends (a repeated edge makes a cycle of two).
std::vector<Polygon> fundamentalCycles(const CurveSkeleton& skeleton) {
  const size_t n = size_t(skeleton.nodes.rows());
  std::vector<std::vector<std::pair<int, int>>> around(n);  // (neighbour, edge index)
  for (size_t e = 0; e < skeleton.edges.size(); ++e) {
    const auto [a, b] = skeleton.edges[e];
    around[size_t(a)].emplace_back(b, int(e));
    around[size_t(b)].emplace_back(a, int(e));
  }
  std::vector<int> parent(n, -2), depth(n, 0);
  std::vector<bool> inTree(skeleton.edges.size(), false);
  for (size_t root = 0; root < n; ++root) {
    if (parent[root] != -2) continue;
    parent[root] = -1;
    std::vector<int> stack{int(root)};
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      for (const auto& [v, e] : around[size_t(u)])
        if (parent[size_t(v)] == -2) {
          parent[size_t(v)] = u;
          depth[size_t(v)] = depth[size_t(u)] + 1;
          inTree[size_t(e)] = true;
          stack.push_back(v);
        }
    }
  }
  std::vector<Polygon> cycles;
  for (size_t e = 0; e < skeleton.edges.size(); ++e) {
    const auto [a, b] = skeleton.edges[e];
    if (inTree[e] || a == b) continue;
    Polygon cycle;
    for (int node : loopThroughTree(a, b, parent, depth))
      cycle.push_back(skeleton.nodes.row(node).transpose());
    cycles.push_back(std::move(cycle));
  }
  return cycles;
}

// Rows of linking numbers, reduced one by one (Gaussian elimination on integer-valued rows).
class RankTracker {
 public:
  explicit RankTracker(size_t columns) : columns_(columns) {}
  // Adds the row when it is independent of the rows so far; returns whether it did.
  bool add(std::vector<double> row) {
    for (const auto& [pivot, basis] : rows_) {
      const double factor = row[pivot] / basis[pivot];
      for (size_t j = 0; j < columns_; ++j) row[j] -= factor * basis[j];
    }
    size_t pivot = 0;
    for (size_t j = 1; j < columns_; ++j)
      if (std::abs(row[j]) > std::abs(row[pivot])) pivot = j;
    if (columns_ == 0 || std::abs(row[pivot]) < 0.5) return false;  // entries are integers: 0.5 is no noise
    rows_.emplace_back(pivot, std::move(row));
    return true;
  }
  int rank() const { return int(rows_.size()); }

 private:
  size_t columns_;
  std::vector<std::pair<size_t, std::vector<double>>> rows_;
};

// Joins the new cycle (nodes first..last) to the nearest older node it sees from inside the mesh; the
// nearest pair of all when none does.
void tieToSkeleton(CurveSkeleton& skeleton, int first, int last, const InsideTest& inside) {
  struct Pair {
    double distance;
    int a, b;
  };
  std::vector<Pair> pairs;
  for (int a = first; a < last; ++a)
    for (int b = 0; b < first; ++b)
      pairs.push_back({(skeleton.nodes.row(a) - skeleton.nodes.row(b)).norm(), a, b});
  if (pairs.empty()) return;
  // Nearest first, from a heap: the first few pairs usually see each other, and sorting all of them (new
  // cycle x every older node) took more time than the tests.
  auto farther = [](const Pair& x, const Pair& y) {
    return std::tie(x.distance, x.a, x.b) > std::tie(y.distance, y.a, y.b);
  };
  std::make_heap(pairs.begin(), pairs.end(), farther);
  const Pair nearest = pairs.front();
  for (auto end = pairs.end(); end != pairs.begin(); --end) {
    std::pop_heap(pairs.begin(), end, farther);
    const Pair& p = *(end - 1);
    if (inside.segmentIsClear(skeleton.nodes.row(p.a).transpose(), skeleton.nodes.row(p.b).transpose())) {
      skeleton.edges.emplace_back(p.a, p.b);
      return;
    }
  }
  skeleton.edges.emplace_back(nearest.a, nearest.b);
}

}  // namespace

double linkingNumber(const Polygon& a, const Polygon& b) {
  // Half the signed crossings of a with b seen along a direction no sample's geometry favours (Rolfsen,
  // Knots and Links, 5.D): equal to Gauss's integral for disjoint curves, in 2-D segment tests instead of
  // four arcsines per pair of segments, which dominate the repair of high-genus meshes.
  const Eigen::Vector3d view = Eigen::Vector3d(0.2113249, 0.5773503, 0.7886751).normalized();
  const Eigen::Vector3d across = view.unitOrthogonal(), up = view.cross(across);
  struct Projected {
    std::vector<Eigen::Vector2d> points;
    std::vector<double> depth;
    explicit Projected(const Polygon& p, const Eigen::Vector3d& x, const Eigen::Vector3d& y,
                       const Eigen::Vector3d& z) {
      for (const auto& q : p) {
        points.emplace_back(q.dot(x), q.dot(y));
        depth.push_back(q.dot(z));
      }
    }
  };
  const Projected pa(a, across, up, view), pb(b, across, up, view);
  auto cross2 = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return u.x() * v.y() - u.y() * v.x();
  };
  // Each segment of b's 2-D box, to skip the pairs that cannot cross.
  std::vector<Eigen::AlignedBox2d> boxes;
  for (size_t j = 0; j < b.size(); ++j) {
    Eigen::AlignedBox2d box(pb.points[j]);
    boxes.push_back(box.extend(pb.points[(j + 1) % b.size()]));
  }
  int doubled = 0;  // the sum of the crossings' signs: twice the linking number
  for (size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector2d& p = pa.points[i];
    const Eigen::Vector2d& q = pa.points[(i + 1) % a.size()];
    Eigen::AlignedBox2d box(p);
    box.extend(q);
    const Eigen::Vector2d da = q - p;
    for (size_t j = 0; j < b.size(); ++j) {
      if (!box.intersects(boxes[j])) continue;
      const Eigen::Vector2d& r = pb.points[j];
      const Eigen::Vector2d& t = pb.points[(j + 1) % b.size()];
      const Eigen::Vector2d db = t - r;
      const double sideR = cross2(da, r - p), sideT = cross2(da, t - p);
      const double sideP = cross2(db, p - r), sideQ = cross2(db, q - r);
      if (!((sideR > 0) != (sideT > 0) && (sideP > 0) != (sideQ > 0)) || sideR == 0 || sideT == 0 ||
          sideP == 0 || sideQ == 0)
        continue;  // no crossing (or a touching one, which a generic view does not meet)
      const double s = sideP / (sideP - sideQ), u = sideR / (sideR - sideT);  // along a, along b
      const double depthA = pa.depth[i] + s * (pa.depth[(i + 1) % a.size()] - pa.depth[i]);
      const double depthB = pb.depth[j] + u * (pb.depth[(j + 1) % b.size()] - pb.depth[j]);
      // Right-handed crossings count +1 (the sign of Gauss's integral): looking along `view`, the strand in
      // front (smaller depth) turns clockwise onto the one behind.
      const double turn = depthA < depthB ? cross2(db, da) : cross2(da, db);
      doubled += turn > 0 ? 1 : -1;
    }
  }
  return 0.5 * doubled;
}

CycleRepairResult restoreMissingCycles(CurveSkeleton& skeleton, const TriangleMesh& mesh,
                                       const InsideTest& inside) {
  CycleRepairResult result;
  result.genus = closedGenus(mesh);
  const std::vector<Polygon> skeletonCycles = fundamentalCycles(skeleton);
  result.cyclesBefore = int(skeletonCycles.size());
  if (result.cyclesBefore >= result.genus) return result;
  const std::vector<std::vector<int>> loops = homologyBasisLoops(mesh);

  const Normals normals = meshNormals(mesh);
  std::vector<PushedLoop> pushed;
  std::vector<Box> outBoxes;
  for (const auto& loop : loops) {
    pushed.push_back(pushLoop(loop, mesh, normals, inside));
    outBoxes.emplace_back(pushed.back().out);
  }
  auto row = [&](const Polygon& curve) {
    const Box box(curve);
    std::vector<double> r;
    for (size_t j = 0; j < pushed.size(); ++j)
      r.push_back(std::round(linkingNumberOrZero(curve, box, pushed[j].out, outBoxes[j])));
    return r;
  };
  RankTracker classes(pushed.size());
  for (const Polygon& cycle : skeletonCycles) classes.add(row(cycle));

  std::vector<size_t> order(pushed.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](size_t x, size_t y) { return pushed[x].length < pushed[y].length; });
  for (size_t k : order) {
    // Never more cycles than the genus: a skeleton cycle that links no pushed-out loop (one that leaves
    // the mesh, or a knot of surgery around nothing) still counts.
    if (classes.rank() >= result.genus || result.cyclesBefore + result.cyclesAdded >= result.genus) break;
    const std::vector<double> inRow = row(pushed[k].in);
    if (!pushed[k].inside || !classes.add(inRow)) continue;
    // The deep loop where it keeps the class (a tunnel wider than the material is thick).
    const Polygon& cycle =
        pushed[k].deepInside && row(pushed[k].deep) == inRow ? pushed[k].deep : pushed[k].in;
    const int first = int(skeleton.nodes.rows()), count = int(cycle.size());
    skeleton.nodes.conservativeResize(first + count, 3);
    for (int i = 0; i < count; ++i) {
      skeleton.nodes.row(first + i) = cycle[size_t(i)].transpose();
      skeleton.edges.emplace_back(first + i, first + (i + 1) % count);
    }
    tieToSkeleton(skeleton, first, first + count, inside);
    ++result.cyclesAdded;
  }
  return result;
}

}  // namespace medial
