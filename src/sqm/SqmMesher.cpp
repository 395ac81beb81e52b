#include "sqm/SqmMesher.h"

#include "common/Stopwatch.h"

#include "common/UnionFind.h"

#include "sqm/CycleClosing.h"
#include "sqm/RingAngles.h"
#include "mesh/PolygonOrientation.h"
#include "sqm/SkeletonStraightening.h"
#include "sqm/SqmRefinement.h"
#include "sqm/TrianglePairing.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

namespace medial {

namespace {

Eigen::Vector3d toEigen(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }

// A unit vector perpendicular to d.
Eigen::Vector3d perpendicular(const Eigen::Vector3d& d) {
  const Eigen::Vector3d axis = std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return d.cross(axis).normalized();
}

// The skeleton SQM meshes: input checks, documented repairs (self-loops dropped, repeated edges merged),
// capsule nodes added. `origin` maps every node back to the input node it stands for.
struct PreparedSkeleton {
  Skeleton skeleton;
  std::vector<int> origin;
  std::vector<bool> pseudo;                    // the pseudo children of cut cycle edges (no geometry)
  std::vector<std::pair<int, int>> cycleCuts;  // pseudo child at one end, at the other (extension 5)
  std::vector<bool> merged;                    // swallowed nodes, merged into a neighbour (no geometry)
};

// Repair: a node whose centre lies inside the sphere of a neighbouring branch node is swallowed by it: the
// branch node's polyhedron lies on its sphere, so the tube between them would have to run backwards out of
// it, folding the surface. The node is merged into the branch node: its other edges move there, it is left
// out of the mesh, and the branch node keeps the larger of the two radii (a sketch's body is a chain of
// large, dense spheres; its wing joint sits inside the next body sphere, which is larger). Merges stop
// where the next node lies outside the sphere, so a chain does not collapse. (Between connection nodes,
// whose rings sit at their centres, overlapping spheres do no harm.) Skeletons from sketches and
// contraction have such nodes where thin parts join a thick one (fingers at a palm). Two neighbouring
// branch nodes merge already when their spheres overlap by more than half the smaller radius: their
// polyhedra then cut into each other and the tube between them runs backwards (the elephant's
// contraction skeleton: 0.12 apart, radii 0.099 and 0.115). Not when the two share a neighbour: merging
// would close a cycle of three onto one edge.
void mergeSwallowedNodes(Skeleton& s, std::vector<bool>& merged) {
  merged.assign(s.nodes.size(), false);
  std::vector<std::set<int>> neighbours(s.nodes.size());
  for (const auto& e : s.edges) {
    neighbours[size_t(e[0])].insert(e[1]);
    neighbours[size_t(e[1])].insert(e[0]);
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& e : s.edges) {
      // The big end: a branch node (rings of connection nodes sit at their centres); of two branch nodes
      // the larger, or the first.
      auto isBranch = [&](int x) { return neighbours[size_t(x)].size() >= 3; };
      const bool first = isBranch(e[0]), second = isBranch(e[1]);
      if (!first && !second) continue;
      const int big = first && (!second || s.radii[size_t(e[0])] >= s.radii[size_t(e[1])]) ? e[0] : e[1];
      const int small = big == e[0] ? e[1] : e[0];
      // Two branch nodes: merged once their spheres overlap by more than half the smaller radius.
      const double reach = first && second ? 0.5 * s.radii[size_t(small)] : 0.0;
      if ((s.nodes[size_t(big)] - s.nodes[size_t(small)]).norm() >= s.radii[size_t(big)] + reach) continue;
      const auto& around = neighbours[size_t(small)];
      if (std::any_of(around.begin(), around.end(),
                      [&](int n) { return neighbours[size_t(big)].count(n) > 0; }))
        continue;
      for (int n : around) {
        neighbours[size_t(n)].erase(small);
        if (n == big) continue;
        neighbours[size_t(n)].insert(big);
        neighbours[size_t(big)].insert(n);
      }
      neighbours[size_t(small)].clear();
      merged[size_t(small)] = true;
      s.radii[size_t(big)] = std::max(s.radii[size_t(big)], s.radii[size_t(small)]);  // the larger sphere
      if (s.root == small) s.root = big;
      changed = true;
      break;  // the edge list is rebuilt before the next search
    }
    if (changed) {
      s.edges.clear();
      for (int a = 0; a < s.nodeCount(); ++a)
        for (int b : neighbours[size_t(a)])
          if (a < b) s.edges.push_back({a, b});
    }
  }
}

std::string prepare(const Skeleton& input, const SqmParameters& p, PreparedSkeleton& out) {
  if (input.nodes.empty()) return "the skeleton has no nodes";
  if (input.radii.size() != input.nodes.size()) return "the skeleton has no Radius per node (SQM needs one)";
  for (const auto& problem : validateSkeleton(input, 1))
    if (problem.kind != SkeletonProblem::Kind::SelfLoopEdge) return problem.message;
  Skeleton& s = out.skeleton;
  s = input;
  s.edges.clear();
  std::set<std::pair<int, int>> seen;
  for (const auto& e : input.edges)
    if (e[0] != e[1] && seen.insert(std::minmax(e[0], e[1])).second) s.edges.push_back(e);
  out.origin.resize(s.nodes.size());
  std::iota(out.origin.begin(), out.origin.end(), 0);

  // Coincident nodes joined by an edge leave no direction to build a tube along.
  for (const auto& e : s.edges)
    if ((s.nodes[size_t(e[0])] - s.nodes[size_t(e[1])]).norm() <=
        1e-9 * std::max(s.radii[size_t(e[0])], s.radii[size_t(e[1])]))
      return "nodes " + std::to_string(e[0]) + " and " + std::to_string(e[1]) +
             " are joined by an edge but lie at the same place";
  if (p.mergeNodes) {
    mergeSwallowedNodes(s, out.merged);
  } else {  // the repair is off: a node it would merge leaves no mesh to build
    Skeleton probe = s;
    std::vector<bool> merged;
    mergeSwallowedNodes(probe, merged);
    const auto first = std::find(merged.begin(), merged.end(), true);
    if (first != merged.end())
      return "node " + std::to_string(first - merged.begin()) +
             " lies inside the sphere of a neighbouring branch node (or two neighbouring branch nodes' "
             "spheres "
             "overlap by more than half the smaller radius): the tube between them would run backwards out "
             "of "
             "the branch node's polyhedron and fold the surface. Let SQM merge such nodes (drop --no-merge) "
             "or "
             "move them apart";
    out.merged.assign(s.nodes.size(), false);
  }
  // Extension 5: every edge closing a cycle is cut; each end gets a pseudo child where the other end is.
  UnionFind sets(s.nodes.size());
  std::vector<std::array<int, 2>> treeEdges;
  for (const auto& e : s.edges) {
    if (sets.join(e[0], e[1])) {
      treeEdges.push_back(e);
      continue;
    }
    int pseudoIds[2];
    for (int end = 0; end < 2; ++end) {
      const int self = e[size_t(end)], other = e[size_t(1 - end)];
      s.nodes.push_back(s.nodes[size_t(other)]);
      s.radii.push_back(s.radii[size_t(other)]);
      if (!s.ellipsoidAxes.empty()) s.ellipsoidAxes.push_back(s.ellipsoidAxes[size_t(other)]);
      out.origin.push_back(self);
      pseudoIds[end] = int(s.nodes.size()) - 1;
      treeEdges.push_back({self, pseudoIds[end]});
    }
    out.cycleCuts.push_back({pseudoIds[0], pseudoIds[1]});
  }
  s.edges = treeEdges;
  out.pseudo.assign(s.nodes.size(), false);
  for (const auto& [a, b] : out.cycleCuts) out.pseudo[size_t(a)] = out.pseudo[size_t(b)] = true;

  if (p.capsules) {
    std::vector<int> degree(s.nodes.size(), 0);
    std::vector<int> neighbour(s.nodes.size(), -1);
    for (const auto& e : s.edges) {
      ++degree[size_t(e[0])];
      ++degree[size_t(e[1])];
      neighbour[size_t(e[0])] = e[1];
      neighbour[size_t(e[1])] = e[0];
    }
    const int inputCount = int(s.nodes.size());
    for (int leaf = 0; leaf < inputCount; ++leaf) {
      if (degree[size_t(leaf)] != 1 || out.pseudo[size_t(leaf)]) continue;
      const Eigen::Vector3d d =
          (s.nodes[size_t(leaf)] - s.nodes[size_t(neighbour[size_t(leaf)])]).normalized();
      const double r = s.radii[size_t(leaf)];
      int previous = leaf;
      const int steps = std::max(1, p.capsuleSteps);
      for (int k = 1; k <= steps; ++k) {
        // Extension 4: newRadius = sqrt(r^2 (1 - step^2)); the last node is the capsule's tip.
        const double step =
            double(k) / double(steps + 1) * (k == steps ? double(steps + 1) / double(steps) : 1.0);
        s.nodes.push_back(s.nodes[size_t(leaf)] + step * r * d);
        s.radii.push_back(std::max(r * std::sqrt(std::max(0.0, 1 - step * step)), 1e-3 * r));
        if (!s.ellipsoidAxes.empty()) s.ellipsoidAxes.push_back(s.ellipsoidAxes[size_t(leaf)]);
        out.origin.push_back(leaf);
        out.pseudo.push_back(false);
        s.edges.push_back({previous, int(s.nodes.size()) - 1});
        previous = int(s.nodes.size()) - 1;
      }
    }
  }
  return {};
}

// The mesh under construction, in the bind pose.
struct Builder {
  SqmMesh mesh;
  std::vector<int> owner;  // node (of the prepared skeleton) per vertex
  const std::vector<bool>* pseudo = nullptr;
  std::map<int, std::vector<int>> openRings;  // per pseudo leaf: the ring left open for the cycle closing
  std::vector<std::vector<size_t>> strips;    // each leaf fan's and cycle band's triangles (TrianglePairing)
  // Ends a tube at a leaf: a fan, or for a pseudo leaf the ring stays open.
  void endAtLeaf(const std::vector<int>& ring, int leaf, const Eigen::Vector3d& apex, bool reversed);
  int add(const Eigen::Vector3d& p, int node) {
    mesh.vertices.push_back(p);
    owner.push_back(node);
    return int(mesh.vertices.size()) - 1;
  }
};

// The ring of the next node along a straight path: translated onto the plane through `centre` across
// `direction`, projected onto the node's sphere, its angles untangled (untangleAngles).
std::vector<int> nextRing(Builder& b, const std::vector<int>& ring, const Eigen::Vector3d& centre,
                          const Eigen::Vector3d& direction, double radius, int node) {
  const Eigen::Vector3d u = perpendicular(direction), v = direction.cross(u);
  std::vector<double> angle;
  for (int id : ring) {
    const Eigen::Vector3d radial = b.mesh.vertices[size_t(id)] - centre;  // its part across the path counts
    angle.push_back(std::atan2(radial.dot(v), radial.dot(u)));
  }
  untangleAngles(angle);
  std::vector<int> next;
  for (double a : angle) next.push_back(b.add(centre + radius * (std::cos(a) * u + std::sin(a) * v), node));
  return next;
}

void bridge(Builder& b, const std::vector<int>& from, const std::vector<int>& to) {
  const size_t m = from.size();
  for (size_t i = 0; i < m; ++i) b.mesh.faces.push_back({from[i], from[(i + 1) % m], to[(i + 1) % m], to[i]});
}

// The faces around a Steiner point of a BNP touch no intersection vertex, so no tube replaces them: they
// stay, consecutive triangles joined into quads (of the two ways to pair them, the flatter); with an odd
// count one triangle is left.
void addSteinerCap(Builder& b, const BranchNodePolyhedron& bnp, BnpMesh::VertexHandle steiner,
                   const std::vector<int>& ids) {
  const BnpMesh& m = bnp.mesh;
  std::vector<BnpMesh::VertexHandle>
      ring;  // triangles (steiner, ring[k], ring[k + 1]), as oriented in the BNP
  const auto first = m.halfedge_handle(steiner);
  auto h = first;
  do {
    ring.push_back(m.to_vertex_handle(h));
    h = m.opposite_halfedge_handle(m.next_halfedge_handle(m.next_halfedge_handle(h)));
  } while (h != first && ring.size() <= m.valence(steiner));
  const size_t n = ring.size();
  const Eigen::Vector3d apex = toEigen(m.point(steiner));
  auto bend = [&](size_t k) {  // how far the quad's last corner lies off the plane of its first three
    const Eigen::Vector3d a = toEigen(m.point(ring[k % n])), c = toEigen(m.point(ring[(k + 1) % n])),
                          d = toEigen(m.point(ring[(k + 2) % n]));
    const Eigen::Vector3d normal = (a - apex).cross(c - apex);
    return normal.norm() > 0 ? std::abs(normal.normalized().dot(d - apex)) : 0.0;
  };
  double bends[2] = {0, 0};
  for (size_t offset = 0; offset < 2; ++offset)
    for (size_t k = offset; k + 1 < offset + n; k += 2) bends[offset] += bend(k);
  const size_t offset = bends[1] < bends[0] ? 1 : 0;
  auto id = [&](size_t k) { return ids[size_t(ring[k % n].idx())]; };
  const int centre = ids[size_t(steiner.idx())];
  size_t k = offset;
  for (; k + 1 < offset + n; k += 2) b.mesh.faces.push_back({centre, id(k), id(k + 1), id(k + 2)});
  if (k < offset + n) b.mesh.faces.push_back({centre, id(k), id(k + 1)});
}

// Pairs the last ring of a tube with the one-ring of the BNP vertex it reaches (both counter-clockwise
// about their own outward direction, so they run opposite ways) and adds the closing quads.
void closeOnRing(Builder& b, const std::vector<int>& ring, const std::vector<int>& target,
                 const Eigen::Vector3d& pathDirection, RingPairing pairing) {
  const int m = int(ring.size());
  auto paired = [&](int i, int offset) { return target[size_t(((offset - i) % m + m) % m)]; };
  auto position = [&](int v) { return b.mesh.vertices[size_t(v)]; };
  int best = 0;
  double bestCost = INFINITY;
  for (int offset = 0; offset < m; ++offset) {
    double cost = 0;
    switch (pairing) {
      case RingPairing::MinimalTotalDistance:
        for (int i = 0; i < m; ++i) cost += (position(ring[size_t(i)]) - position(paired(i, offset))).norm();
        break;
      case RingPairing::MinimalDistance:
        cost = (position(ring[0]) - position(paired(0, offset))).norm();
        break;
      case RingPairing::MinimalAngle: {
        const Eigen::Vector3d d = position(paired(0, offset)) - position(ring[0]);
        cost = std::acos(std::clamp(d.normalized().dot(pathDirection), -1.0, 1.0));
        break;
      }
    }
    if (cost < bestCost) {
      bestCost = cost;
      best = offset;
    }
  }
  for (int i = 0; i < m; ++i)
    b.mesh.faces.push_back(
        {ring[size_t(i)], ring[size_t((i + 1) % m)], paired(i + 1, best), paired(i, best)});
}

void fan(Builder& b, const std::vector<int>& ring, int apex, bool reversed) {
  const size_t m = ring.size();
  b.strips.emplace_back();
  for (size_t i = 0; i < m; ++i) {
    b.strips.back().push_back(b.mesh.faces.size());
    if (reversed)
      b.mesh.faces.push_back({ring[(i + 1) % m], ring[i], apex});
    else
      b.mesh.faces.push_back({ring[i], ring[(i + 1) % m], apex});
  }
}

void Builder::endAtLeaf(const std::vector<int>& ring, int leaf, const Eigen::Vector3d& apex, bool reversed) {
  if ((*pseudo)[size_t(leaf)]) {
    openRings[leaf] = ring;
    return;
  }
  fan(*this, ring, add(apex, leaf), reversed);
}

// A lone node: a cube projected on its sphere (six quads).
void meshLoneNode(Builder& b, const Eigen::Vector3d& c, double r, int node) {
  int v[8];
  for (int i = 0; i < 8; ++i)
    v[i] =
        b.add(c + r / std::sqrt(3.0) * Eigen::Vector3d(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1), node);
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) b.mesh.faces.push_back({v[q[0]], v[q[1]], v[q[2]], v[q[3]]});
}

// Follows the tree from `start` towards `next` through connection nodes; returns them and the end node.
std::vector<int> pathFrom(const SqmTree& tree, int start, int next, int& end) {
  std::vector<int> connections;
  int previous = start, current = next;
  while (tree.neighbourCount(current) == 2) {
    connections.push_back(current);
    const auto around = tree.neighbours(current);
    const int following = around[0] == previous ? around[1] : around[0];
    previous = current;
    current = following;
  }
  end = current;
  return connections;
}

// Carries `ring` (the former one-ring at `start`'s side) through the connection nodes of a path and
// returns the last ring.
std::vector<int> carryAlong(Builder& b, std::vector<int> ring, const std::vector<int>& connections, int start,
                            const Skeleton& s, const BindPose& pose) {
  Eigen::Vector3d from = pose.position[size_t(start)];
  for (int c : connections) {
    const Eigen::Vector3d direction = (pose.position[size_t(c)] - from).normalized();
    std::vector<int> next = nextRing(b, ring, pose.position[size_t(c)], direction, s.radii[size_t(c)], c);
    bridge(b, ring, next);
    ring = std::move(next);
    from = pose.position[size_t(c)];
  }
  return ring;
}

// A branch node polyhedron's triangles appended to `out` (recordStages), its vertices owned by its node.
void appendPolyhedron(SqmMesh& out, const BranchNodePolyhedron& bnp) {
  const int first = int(out.vertices.size());
  for (auto v : bnp.mesh.vertices()) {
    out.vertices.push_back(toEigen(bnp.mesh.point(v)));
    out.vertexNode.push_back(bnp.node);
  }
  for (auto f : bnp.mesh.faces()) {
    std::vector<int> face;
    for (auto v : bnp.mesh.fv_range(f)) face.push_back(first + v.idx());
    out.faces.push_back(face);
  }
}

// A linear skeleton (extension 2): an N-vertex ring at the first connection node, carried along the
// path and closed at both leaves; a lone node becomes a sphere.
void meshLinearSkeleton(const Skeleton& s, const SqmTree& tree, const BindPose& pose, const SqmParameters& p,
                        Builder& b) {
  const int root = tree.root;
  if (tree.children[size_t(root)].empty()) {
    meshLoneNode(b, pose.position[size_t(root)], s.radii[size_t(root)], root);
    return;
  }
  int end = -1;
  const std::vector<int> connections = pathFrom(tree, root, tree.children[size_t(root)][0], end);
  const Eigen::Vector3d d = (pose.position[size_t(end)] - pose.position[size_t(root)]).normalized();
  // Two nodes only: the ring goes half way, owned by the root.
  const bool midway = connections.empty();
  const int ringNode = midway ? root : connections[0];
  const Eigen::Vector3d centre =
      midway ? Eigen::Vector3d(0.5 * (pose.position[size_t(root)] + pose.position[size_t(end)]))
             : pose.position[size_t(ringNode)];
  const double radius =
      midway ? 0.5 * (s.radii[size_t(root)] + s.radii[size_t(end)]) : s.radii[size_t(ringNode)];
  const Eigen::Vector3d u = perpendicular(d), v = d.cross(u);
  std::vector<int> ring;
  const int n = std::max(3, p.linearRingVertices);
  for (int j = 0; j < n; ++j) {
    const double angle = 2 * M_PI * j / n;
    ring.push_back(b.add(centre + radius * (std::cos(angle) * u + std::sin(angle) * v), ringNode));
  }
  b.endAtLeaf(ring, root, pose.position[size_t(root)], true);
  ring = carryAlong(b, ring, std::vector<int>(connections.begin() + (midway ? 0 : 1), connections.end()),
                    ringNode, s, pose);
  b.endAtLeaf(ring, end, pose.position[size_t(end)], false);
}

// Step 2: every BNP refined, parent before child, so that the two ends of each path get rings that pair.
std::string refineBnps(const SqmTree& tree, const SqmParameters& p,
                       std::map<int, BranchNodePolyhedron>& bnps) {
  std::string error;
  // For each branch node and each of its intersection vertices: the path's end node, and which of the end
  // BNP's intersection vertices faces back (its parent side: index 0) when the end is a branch node.
  for (int k : tree.nodes) {
    if (!tree.isBranch(k)) continue;
    BranchNodePolyhedron& bnp = bnps[k];
    const int count = int(bnp.intersection.size());
    std::vector<int> target(static_cast<size_t>(count));
    std::vector<bool> exact(static_cast<size_t>(count), false);
    for (int i = 0; i < count; ++i) {
      target[size_t(i)] = bnp.valence(i);
      int end = -1;
      const std::vector<int> connections = pathFrom(tree, k, bnp.neighbourNodes[size_t(i)], end);
      if (!tree.isBranch(end)) continue;  // a leaf's fan closes any ring
      const bool towardsParent = tree.parent[size_t(k)] >= 0 && i == 0;
      if (towardsParent) {
        // The parent's BNP was refined first: match its vertex on this path exactly.
        const BranchNodePolyhedron& parentBnp = bnps[end];
        const int lastBefore = connections.empty() ? k : connections.back();
        const auto at =
            std::find(parentBnp.neighbourNodes.begin(), parentBnp.neighbourNodes.end(), lastBefore);
        exact[size_t(i)] = true;
        target[size_t(i)] = parentBnp.valence(int(at - parentBnp.neighbourNodes.begin()));
      } else {
        target[size_t(i)] = std::max(target[size_t(i)], bnps[end].valence(0));  // at least the child's
      }
    }
    if (!refineBnp(bnp, target, exact, p.smoothing, error)) return error;
  }
  return {};
}

std::string meshTree(const Skeleton& s, const SqmTree& tree, const BindPose& pose, const SqmParameters& p,
                     Builder& b, SqmResult& result) {
  if (!tree.hasBranchNode) {
    meshLinearSkeleton(s, tree, pose, p, b);
    return {};
  }

  // Steps 1-2: BNPs, generated for every branch node, refined parent before child.
  Stopwatch start;
  std::map<int, BranchNodePolyhedron> bnps;
  std::string error;
  for (int k : tree.nodes) {
    if (!tree.isBranch(k)) continue;
    std::vector<Eigen::Vector3d> directions;
    const std::vector<int> around = tree.neighbours(k);
    for (int m : around) directions.push_back(pose.position[size_t(m)]);
    if (!generateBnp(k, pose.position[size_t(k)], s.radii[size_t(k)], around, directions, bnps[k], error))
      return error;
  }
  result.generationSeconds += start.seconds();
  if (p.recordStages)
    for (const auto& [k, bnp] : bnps) appendPolyhedron(result.polyhedra, bnp);
  start.restart();
  if (std::string refined = refineBnps(tree, p, bnps); !refined.empty()) return refined;
  result.refinementSeconds += start.seconds();
  if (p.recordStages)
    for (const auto& [k, bnp] : bnps) appendPolyhedron(result.refinedPolyhedra, bnp);

  // Steps 3: joining. BNP vertices other than the intersection vertices go to the mesh; every BNP face
  // touches an intersection vertex, so none is kept: tubes take their place.
  start.restart();
  std::map<int, std::vector<int>> outputId;  // per branch node: output id per BNP vertex (-1 intersection)
  for (auto& [k, bnp] : bnps) {
    std::vector<int>& ids = outputId[k];
    ids.assign(bnp.mesh.n_vertices(), -1);
    std::set<int> intersections;
    for (auto v : bnp.intersection) intersections.insert(v.idx());
    for (auto v : bnp.mesh.vertices())
      if (!intersections.count(v.idx())) ids[size_t(v.idx())] = b.add(toEigen(bnp.mesh.point(v)), k);
  }
  for (const auto& [k, bnp] : bnps)
    for (auto steiner : bnp.steiner) addSteinerCap(b, bnp, steiner, outputId[k]);
  auto ringOf = [&](int k, int i) {
    std::vector<int> ring;
    for (auto v : bnps[k].orderedRing(i)) ring.push_back(outputId[k][size_t(v.idx())]);
    return ring;
  };
  for (int k : tree.nodes) {
    if (!tree.isBranch(k)) continue;
    const BranchNodePolyhedron& bnp = bnps[k];
    const size_t first = tree.parent[size_t(k)] >= 0 ? 1 : 0;  // the parent's side is joined by the parent
    for (size_t i = first; i < bnp.intersection.size(); ++i) {
      int end = -1;
      const std::vector<int> connections = pathFrom(tree, k, bnp.neighbourNodes[i], end);
      std::vector<int> ring = carryAlong(b, ringOf(k, int(i)), connections, k, s, pose);
      if (tree.isBranch(end)) {
        const Eigen::Vector3d direction =
            (pose.position[size_t(end)] - pose.position[size_t(k)]).normalized();
        closeOnRing(b, ring, ringOf(end, 0), direction, p.pairing);
      } else {
        b.endAtLeaf(ring, end, pose.position[size_t(end)], false);
      }
    }
  }
  result.joiningSeconds += start.seconds();
  return {};
}

// Step 4: back to the input pose by linear blend skinning with the straightening rotations.
void placeVertices(const Skeleton& s, const SqmTree& tree, const BindPose& pose, Builder& b,
                   size_t firstVertex) {
  for (size_t v = firstVertex; v < b.mesh.vertices.size(); ++v) {
    const int k = b.owner[v];
    const Eigen::Vector3d offset = b.mesh.vertices[v] - pose.position[size_t(k)];
    Eigen::Vector3d reference = pose.rotation[size_t(k)].conjugate() * offset;
    if (tree.neighbourCount(k) == 2 && tree.parent[size_t(k)] >= 0) {
      // A connection node: half its incoming, half its outgoing rotation; back onto its sphere.
      const Eigen::Vector3d outgoing =
          pose.rotation[size_t(tree.children[size_t(k)][0])].conjugate() * offset;
      const Eigen::Vector3d blended = 0.5 * (reference + outgoing);
      if (blended.squaredNorm() > 1e-24) reference = offset.norm() * blended.normalized();
    }
    b.mesh.vertices[v] = s.nodes[size_t(k)] + reference;
  }
}

}  // namespace

const char* ringPairingName(RingPairing pairing) {
  switch (pairing) {
    case RingPairing::MinimalTotalDistance:
      return "total-distance";
    case RingPairing::MinimalDistance:
      return "distance";
    case RingPairing::MinimalAngle:
      return "angle";
  }
  return "";
}

namespace {
const RingPairing kPairings[] = {RingPairing::MinimalTotalDistance, RingPairing::MinimalDistance,
                                 RingPairing::MinimalAngle};
}

bool parseRingPairing(const std::string& name, RingPairing& pairing) {
  for (RingPairing r : kPairings)
    if (name == ringPairingName(r)) {
      pairing = r;
      return true;
    }
  return false;
}

std::vector<std::string> ringPairingNames() {
  std::vector<std::string> names;
  for (RingPairing r : kPairings) names.push_back(ringPairingName(r));
  return names;
}

namespace {

// Vertices where other than four edges meet (the paper's Table 1 counts them: where quads are not a grid).
int countIrregularVertices(const SqmMesh& mesh) {
  // SQM's mesh is closed and manifold: around each vertex, faces and edges alternate, so its valence is
  // the number of its faces (sorting the edges to count them is a noticeable part of a refined mesh).
  std::vector<int> degree(mesh.vertices.size(), 0);
  for (const auto& f : mesh.faces)
    for (const int v : f) ++degree[size_t(v)];
  return int(std::count_if(degree.begin(), degree.end(), [](int d) { return d != 0 && d != 4; }));
}

}  // namespace

int SqmMesh::triangleCount() const {
  return int(
      std::count_if(faces.begin(), faces.end(), [](const std::vector<int>& f) { return f.size() == 3; }));
}

int SqmMesh::quadCount() const {
  return int(
      std::count_if(faces.begin(), faces.end(), [](const std::vector<int>& f) { return f.size() == 4; }));
}

int SqmMesh::faceNode(size_t f) const {
  // Faces have a handful of vertices: counting each one's node among them beats a map (a million faces).
  int best = 0, bestVotes = 0;
  for (const int v : faces[f]) {
    const int node = vertexNode[size_t(v)];
    int votes = 0;
    for (const int w : faces[f]) votes += vertexNode[size_t(w)] == node;
    if (votes > bestVotes || (votes == bestVotes && node < best)) {
      best = node;
      bestVotes = votes;
    }
  }
  return best;
}

SqmResult sqmMesh(const Skeleton& input, const SqmParameters& p,
                  const std::function<bool(double)>& progress) {
  SqmResult result;
  PreparedSkeleton prepared;
  result.error = prepare(input, p, prepared);
  if (!result.error.empty()) return result;
  const Skeleton& s = prepared.skeleton;
  result.mergedNodes = int(std::count(prepared.merged.begin(), prepared.merged.end(), true));

  Builder builder;
  builder.pseudo = &prepared.pseudo;
  std::vector<bool> done(s.nodes.size(), false);
  for (size_t k = 0; k < prepared.merged.size(); ++k) done[k] = prepared.merged[k];  // no tube of their own
  for (int start = 0; start < s.nodeCount(); ++start) {
    if (done[size_t(start)]) continue;
    Stopwatch clock;
    const SqmTree tree = buildSqmTree(s, start, s.root);
    const BindPose pose = straightenSkeleton(s, tree);
    result.straighteningSeconds += clock.seconds();
    for (int k : tree.nodes) {
      done[size_t(k)] = true;
      if (prepared.origin[size_t(k)] != k) continue;  // capsule nodes are not counted
      (tree.isBranch(k) ? result.branchNodes : tree.isLeaf(k) ? result.leafNodes : result.connectionNodes)++;
    }
    const size_t firstVertex = builder.mesh.vertices.size();
    result.error = meshTree(s, tree, pose, p, builder, result);
    if (!result.error.empty()) return result;
    clock.restart();
    placeVertices(s, tree, pose, builder, firstVertex);
    result.placementSeconds += clock.seconds();
    if (progress && !progress(double(start + 1) / double(s.nodeCount()))) {
      result.error = Error::cancelled();
      return result;
    }
  }
  // Extension 5: join the two open rings of every cut cycle edge, in the input pose.
  for (const auto& [a, b] : prepared.cycleCuts) {
    const int atA = prepared.origin[size_t(a)], atB = prepared.origin[size_t(b)];
    const auto band = closeCycleGap(builder.mesh.vertices, builder.openRings[a], s.nodes[size_t(atA)],
                                    builder.openRings[b], s.nodes[size_t(atB)]);
    builder.strips.emplace_back();
    for (const auto& t : band) {
      builder.strips.back().push_back(builder.mesh.faces.size());
      builder.mesh.faces.push_back({t[0], t[1], t[2]});
    }
  }
  // Extension 3: an ellipsoid node maps the unit sphere to its ellipsoid.
  if (!s.ellipsoidAxes.empty())
    for (size_t v = 0; v < builder.mesh.vertices.size(); ++v) {
      const int k = builder.owner[v];
      const Eigen::Vector3d unit = (builder.mesh.vertices[v] - s.nodes[size_t(k)]) / s.radii[size_t(k)];
      builder.mesh.vertices[v] = s.nodes[size_t(k)] + s.ellipsoidAxes[size_t(k)] * unit;
    }
  // Repair: where a lopsided pillow ring makes a tube twist (the pretzel), faces can come out turned
  // against their neighbours, and so can the cycle bands; the surface is orientable, so it gets one
  // consistent orientation, outward (OpenMesh's subdivision needs it).
  Stopwatch repairs;
  result.reorientedFaces = orientPolygonsOutward(builder.mesh.vertices, builder.mesh.faces);
  if (p.pairTriangles)
    result.pairedTriangles = pairStripTriangles(builder.mesh.vertices, builder.mesh.faces, builder.strips);
  result.repairSeconds += repairs.seconds();
  // Each vertex's node in the input's numbering, which the prepared skeleton (the refinement's) extends
  // by its capsule and cycle-cut nodes.
  result.mesh = std::move(builder.mesh);
  result.mesh.vertexNode.resize(builder.owner.size());
  for (size_t v = 0; v < builder.owner.size(); ++v)
    result.mesh.vertexNode[v] = prepared.origin[size_t(builder.owner[v])];
  if (p.recordStages) result.baseMesh = result.mesh;
  RefinementReport refinement;
  if (p.subdivisionLevels > 0) {
    // The cones of the skeleton the mesh was built on (capsule nodes included, pseudo nodes left out).
    Skeleton cones = s;
    cones.edges.clear();
    for (const auto& e : s.edges)
      if (!prepared.pseudo[size_t(e[0])] && !prepared.pseudo[size_t(e[1])]) cones.edges.push_back(e);
    for (const auto& [a, b] : prepared.cycleCuts)
      cones.edges.push_back({prepared.origin[size_t(a)], prepared.origin[size_t(b)]});
    Stopwatch clock;
    refineSqmMesh(result.mesh, cones, p.subdivisionLevels, p.sharpScaling, p.foldRepair, &refinement);
    result.foldRepairedVertices = refinement.repairedVertices;
    for (int& node : result.mesh.vertexNode) node = prepared.origin[size_t(node)];
    result.subdivisionSeconds += clock.seconds();
  }
  if (p.unite || p.countOverlaps) {
    Stopwatch clock;
    result.overlaps = sqmOverlaps(result.mesh);
    if (p.unite) {
      // Components smaller than a tenth of the smallest input node's ball are pockets between tubes (the
      // smallest part, a lone node, is a sphere of six quads: 0.37 of its ball).
      const double r = *std::min_element(input.radii.begin(), input.radii.end());
      result.unionResult = unionSqmMesh(result.mesh, 0.1 * 4.0 / 3.0 * M_PI * r * r * r, &result.overlaps);
      if (!result.unionResult.ok()) result.error = result.unionResult.error;
    }
    result.unionSeconds = clock.seconds();
    if (!result.error.empty()) return result;
  }
  result.irregularVertices = countIrregularVertices(result.mesh);
  return result;
}

}  // namespace medial
