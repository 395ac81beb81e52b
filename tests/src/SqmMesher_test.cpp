// SqmMesher: closed quad-dominant manifolds from skeletons, the extensions, and bad input.
#include "mesh/MeshTopology.h"
#include "sqm/BranchNodePolyhedron.h"
#include "sqm/CycleClosing.h"
#include "sqm/RingAngles.h"
#include "sqm/SkeletonStraightening.h"
#include "sqm/SqmMesher.h"
#include "sqm/SqmRefinement.h"
#include "sqm/SweptSpheres.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

medial::Skeleton ySkeleton() {  // a planar Y: three arms of two edges around a root branch node
  medial::Skeleton s;
  s.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {-0.5, 1, 0}, {-1, 2, 0}, {-0.5, -1, 0}, {-1, -2, 0}};
  s.radii = {0.4, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3};
  s.edges = {{0, 1}, {1, 2}, {0, 3}, {3, 4}, {0, 5}, {5, 6}};
  s.root = 0;
  return s;
}

medial::Skeleton starSkeleton() {  // six arms along the axes, a second branch node at the end of one
  medial::Skeleton s;
  s.nodes = {{0, 0, 0}};
  s.radii = {0.5};
  const Eigen::Vector3d directions[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const auto& d : directions)
    for (int k = 1; k <= 3; ++k) {
      s.nodes.push_back(d * k * 0.7);
      s.radii.push_back(0.25);
      s.edges.push_back({k == 1 ? 0 : s.nodeCount() - 2, s.nodeCount() - 1});
    }
  for (const Eigen::Vector3d& side : {Eigen::Vector3d(0, 0.8, 0), Eigen::Vector3d(0, 0, 0.8)}) {
    s.nodes.push_back(s.nodes[3] + side + Eigen::Vector3d(0.3, 0, 0));
    s.radii.push_back(0.2);
    s.edges.push_back({3, s.nodeCount() - 1});
  }
  s.root = 0;
  return s;
}

medial::Skeleton wormSkeleton() {
  medial::Skeleton s;
  for (int i = 0; i < 23; ++i) {
    s.nodes.push_back({i * 0.5, std::sin(i * 0.4), 0});
    s.radii.push_back(0.3);
    if (i > 0) s.edges.push_back({i - 1, i});
  }
  return s;
}

medial::MeshTopology topologyOf(const medial::SqmMesh& mesh) {
  std::vector<std::vector<int64_t>> faces;
  for (const auto& f : mesh.faces) faces.emplace_back(f.begin(), f.end());
  return medial::computeMeshTopology(int64_t(mesh.vertices.size()), faces);
}

// The invariants of the issue that hold for every skeleton: a closed 2-manifold per component with
// Euler characteristic 2 (trees), finite coordinates, triangles only in leaf fans, vertices on their
// node's sphere except the fan apexes at the leaves' centres.
void expectClosedQuadDominant(const medial::Skeleton& s, const medial::SqmResult& r, int components = 1,
                              int cycles = 0) {
  ASSERT_TRUE(r.ok()) << r.error;
  const medial::MeshTopology t = topologyOf(r.mesh);
  EXPECT_EQ(t.borderEdges, 0);
  EXPECT_EQ(t.nonManifoldEdges, 0);
  EXPECT_EQ(t.degenerateFaces, 0);
  EXPECT_EQ(t.unusedVertices, 0);
  EXPECT_EQ(t.components, components);
  EXPECT_EQ(t.eulerCharacteristic, 2 * components - 2 * cycles);
  std::vector<int> degree(s.nodes.size(), 0);
  for (const auto& e : s.edges) {
    ++degree[size_t(e[0])];
    ++degree[size_t(e[1])];
  }
  for (size_t v = 0; v < r.mesh.vertices.size(); ++v) {
    ASSERT_TRUE(r.mesh.vertices[v].allFinite()) << v;
    const int node = r.mesh.vertexNode[v];
    const double distance = (r.mesh.vertices[v] - s.nodes[size_t(node)]).norm();
    if (distance > 1e-9) {
      EXPECT_NEAR(distance, s.radii[size_t(node)], 1e-9) << "vertex " << v << " node " << node;
    }
  }
  for (const auto& f : r.mesh.faces) {
    if (f.size() == 4 || cycles > 0) continue;  // cycle closures are triangles too
    ASSERT_EQ(f.size(), 3u);
    bool hasLeafApex = false;
    for (int v : f)
      hasLeafApex |=
          degree[size_t(r.mesh.vertexNode[size_t(v)])] <= 1 &&
          (r.mesh.vertices[size_t(v)] - s.nodes[size_t(r.mesh.vertexNode[size_t(v)])]).norm() < 1e-9;
    EXPECT_TRUE(hasLeafApex) << "a triangle away from the leaves";
  }
}

}  // namespace

TEST(SqmMesher, PlanarYIsClosedAndQuadDominant) {
  const auto s = ySkeleton();
  const auto r = medial::sqmMesh(s);
  expectClosedQuadDominant(s, r);
  EXPECT_EQ(r.branchNodes, 1);
  EXPECT_EQ(r.leafNodes, 3);
  EXPECT_GE(r.mesh.quadCount(), 0.9 * double(r.mesh.faces.size())) << "the paper's 90 % quads";
}

// A branch node whose neighbours all lie in one plane through it (every joint of a sketch's skeleton):
// the hull is a flat polygon covered from both sides, each side a cap of a hemisphere, so a Steiner point
// goes at each pole: a closed bipyramid of 2n triangles, each split in six.
TEST(BranchNodePolyhedron, CoplanarNeighboursGiveAClosedPolyhedron) {
  for (int arms = 3; arms <= 6; ++arms) {
    std::vector<int> neighbours;
    std::vector<Eigen::Vector3d> positions;
    for (int k = 0; k < arms; ++k) {
      const double angle = 2 * M_PI * k / arms + 0.3 * std::sin(k);  // uneven spacing
      neighbours.push_back(k + 1);
      positions.emplace_back(std::cos(angle), std::sin(angle), 0);
    }
    medial::BranchNodePolyhedron bnp;
    std::string error;
    ASSERT_TRUE(medial::generateBnp(0, Eigen::Vector3d::Zero(), 0.5, neighbours, positions, bnp, error))
        << error;
    EXPECT_EQ(bnp.steiner.size(), 2u) << arms << " arms";
    EXPECT_EQ(int(bnp.mesh.n_faces()), 6 * 2 * arms) << arms << " arms: a face was refused";
    for (auto pole : bnp.steiner) EXPECT_NEAR(std::abs(bnp.mesh.point(pole)[2]), 0.5, 1e-12);
    for (auto e : bnp.mesh.edges()) EXPECT_FALSE(bnp.mesh.is_boundary(e)) << arms << " arms";
  }
  const medial::Skeleton plus = [] {
    medial::Skeleton s;
    s.nodes = {{0, 0, 0}};
    s.radii = {0.4};
    for (const Eigen::Vector3d& d : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                     Eigen::Vector3d(-1, 0.2, 0), Eigen::Vector3d(0.1, -1, 0)})
      for (int k = 1; k <= 2; ++k) {
        s.nodes.push_back(k * d);
        s.radii.push_back(0.25);
        s.edges.push_back({k == 1 ? 0 : s.nodeCount() - 2, s.nodeCount() - 1});
      }
    s.root = 0;
    return s;
  }();
  expectClosedQuadDominant(plus, medial::sqmMesh(plus));
}

// Steiner points go only into caps wider than 75 degrees: none for arms spread like a tetrahedron's or
// along the six axes; one on the far side of three orthogonal arms (their triangle's back covers 7/8 of
// the sphere).
TEST(BranchNodePolyhedron, SteinerPointsCoverOnlyWideCaps) {
  auto steinerPoints = [](const std::vector<Eigen::Vector3d>& directions) {
    std::vector<int> neighbours;
    for (size_t k = 0; k < directions.size(); ++k) neighbours.push_back(int(k) + 1);
    medial::BranchNodePolyhedron bnp;
    std::string error;
    EXPECT_TRUE(medial::generateBnp(0, Eigen::Vector3d::Zero(), 1.0, neighbours, directions, bnp, error))
        << error;
    for (auto e : bnp.mesh.edges()) EXPECT_FALSE(bnp.mesh.is_boundary(e));
    std::vector<Eigen::Vector3d> points;
    for (auto v : bnp.steiner)
      points.emplace_back(bnp.mesh.point(v)[0], bnp.mesh.point(v)[1], bnp.mesh.point(v)[2]);
    return points;
  };
  EXPECT_TRUE(steinerPoints({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}).empty());
  EXPECT_TRUE(steinerPoints({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}).empty());
  const auto corner = steinerPoints({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  ASSERT_EQ(corner.size(), 1u);
  EXPECT_LT((corner[0] + Eigen::Vector3d(1, 1, 1).normalized()).norm(), 1e-9);
}

TEST(SqmMesher, EverySmoothingAndPairingGivesAClosedManifold) {
  const auto s = starSkeleton();
  for (auto smoothing : {medial::LieSmoothing::Quaternion, medial::LieSmoothing::Averaging,
                         medial::LieSmoothing::AreaLaplacian, medial::LieSmoothing::ValencyLaplacian})
    for (auto pairing : {medial::RingPairing::MinimalTotalDistance, medial::RingPairing::MinimalDistance,
                         medial::RingPairing::MinimalAngle}) {
      medial::SqmParameters p;
      p.smoothing = smoothing;
      p.pairing = pairing;
      SCOPED_TRACE(std::string(medial::lieSmoothingName(smoothing)) + " / " +
                   medial::ringPairingName(pairing));
      expectClosedQuadDominant(s, medial::sqmMesh(s, p));
    }
}

TEST(SqmMesher, LinearSkeletonGetsNVertexRings) {
  const auto s = wormSkeleton();
  medial::SqmParameters p;
  p.linearRingVertices = 6;
  const auto r = medial::sqmMesh(s, p);
  expectClosedQuadDominant(s, r);
  // 21 connection nodes, 6 vertices each, two apexes; 20 rings of quads and two fans of 6 triangles,
  // joined in pairs into 3 quads each.
  EXPECT_EQ(r.mesh.vertices.size(), 21u * 6 + 2);
  EXPECT_EQ(r.mesh.quadCount(), 20 * 6 + 2 * 3);
  EXPECT_EQ(r.mesh.faces.size(), 20u * 6 + 2 * 3);
  EXPECT_EQ(r.pairedTriangles, 6);
  p.pairTriangles = false;  // the paper's fans
  const auto fans = medial::sqmMesh(s, p);
  expectClosedQuadDominant(s, fans);
  EXPECT_EQ(fans.mesh.quadCount(), 20 * 6);
  EXPECT_EQ(fans.mesh.faces.size(), 20u * 6 + 12);
}

TEST(SqmMesher, LongChainsAreWalkedWithoutRecursion) {
  // A 50,000-node centerline with one side branch half way: deep recursion would overflow the stack.
  medial::Skeleton s;
  for (int i = 0; i < 50000; ++i) {
    s.nodes.push_back({0.1 * i, 0.2 * std::sin(0.01 * i), 0});
    s.radii.push_back(0.04);
    if (i > 0) s.edges.push_back({i - 1, i});
  }
  s.nodes.push_back({2500, 1, 0});
  s.radii.push_back(0.04);
  s.edges.push_back({25000, 50000});
  s.root = 0;
  const auto r = medial::sqmMesh(s);
  ASSERT_TRUE(r.ok()) << r.error;
  const medial::MeshTopology t = topologyOf(r.mesh);
  EXPECT_EQ(t.borderEdges + t.nonManifoldEdges, 0);
  EXPECT_EQ(t.eulerCharacteristic, 2);
}

TEST(SqmMesher, RootThatIsALeafIsMovedToABranchNode) {
  auto s = ySkeleton();
  s.root = 2;  // a leaf
  EXPECT_EQ(medial::buildSqmTree(s, s.root, s.root).root, 0) << "the tree is rooted at the branch node";
  const auto r = medial::sqmMesh(s);
  expectClosedQuadDominant(s, r);
  // The same mesh as when the branch node is asked for.
  s.root = 0;
  const auto rooted = medial::sqmMesh(s);
  ASSERT_EQ(r.mesh.vertices.size(), rooted.mesh.vertices.size());
  double largest = 0;
  for (size_t v = 0; v < r.mesh.vertices.size(); ++v)
    largest = std::max(largest, (r.mesh.vertices[v] - rooted.mesh.vertices[v]).norm());
  EXPECT_LT(largest, 1e-12);
}

TEST(SqmMesher, LoneNodesTwoNodeSegmentsAndComponents) {
  medial::Skeleton s = ySkeleton();
  s.nodes.push_back({10, 0, 0});  // a lone node
  s.radii.push_back(1);
  s.nodes.push_back({0, 10, 0});  // a two-node segment
  s.nodes.push_back({0, 12, 0});
  s.radii.push_back(0.5);
  s.radii.push_back(0.5);
  s.edges.push_back({8, 9});
  const auto r = medial::sqmMesh(s);
  ASSERT_TRUE(r.ok()) << r.error;
  const medial::MeshTopology t = topologyOf(r.mesh);
  EXPECT_EQ(t.components, 3);
  EXPECT_EQ(t.eulerCharacteristic, 6);
  EXPECT_EQ(t.borderEdges, 0);
  EXPECT_EQ(t.nonManifoldEdges, 0);
}

TEST(SqmMesher, CapsulesRoundTheLeaves) {
  const auto s = ySkeleton();
  medial::SqmParameters p;
  p.capsules = true;
  const auto r = medial::sqmMesh(s, p);
  ASSERT_TRUE(r.ok()) << r.error;
  const medial::MeshTopology t = topologyOf(r.mesh);
  EXPECT_EQ(t.borderEdges + t.nonManifoldEdges, 0);
  EXPECT_EQ(t.eulerCharacteristic, 2);
  // Each tip lies one radius beyond its leaf, along the arm: (2 + 0.3, 0, 0) for the first arm.
  double farthest = 0;
  for (const auto& v : r.mesh.vertices) farthest = std::max(farthest, v.x());
  EXPECT_NEAR(farthest, 2.3, 1e-9);
}

TEST(SqmMesher, EllipsoidNodesScaleTheirVertices) {
  auto s = wormSkeleton();
  for (size_t k = 0; k < s.nodes.size(); ++k)
    s.ellipsoidAxes.push_back(Eigen::Vector3d(0.3, 0.3, 0.9).asDiagonal());
  const auto r = medial::sqmMesh(s);
  ASSERT_TRUE(r.ok()) << r.error;
  double zExtent = 0, yExtentAtMiddle = 0;
  for (size_t v = 0; v < r.mesh.vertices.size(); ++v) {
    zExtent = std::max(zExtent, std::abs(r.mesh.vertices[v].z()));
    if (r.mesh.vertexNode[v] == 11)
      yExtentAtMiddle = std::max(yExtentAtMiddle, std::abs(r.mesh.vertices[v].y() - s.nodes[11].y()));
  }
  EXPECT_GT(zExtent, 0.8);  // three times the radius across z
  EXPECT_LT(yExtentAtMiddle, 0.3 + 1e-9);
}

TEST(SqmMesher, CyclesAreCutAndClosed) {
  // A ring of 12 (one cycle, no branch node), a Y whose two arm tips are joined (a cycle through the root),
  // and a triangle of three nodes.
  medial::Skeleton ring;
  for (int i = 0; i < 12; ++i) {
    ring.nodes.push_back({2 * std::cos(2 * M_PI * i / 12), 2 * std::sin(2 * M_PI * i / 12), 0});
    ring.radii.push_back(0.4);
    ring.edges.push_back({i, (i + 1) % 12});
  }
  expectClosedQuadDominant(ring, medial::sqmMesh(ring), 1, 1);
  auto joined = ySkeleton();
  joined.edges.push_back({2, 4});
  expectClosedQuadDominant(joined, medial::sqmMesh(joined), 1, 1);
  medial::Skeleton triangle;
  triangle.nodes = {{0, 0, 0}, {2, 0, 0}, {1, 1.7, 0}};
  triangle.radii = {0.3, 0.3, 0.3};
  triangle.edges = {{0, 1}, {1, 2}, {2, 0}};
  const auto r = medial::sqmMesh(triangle);
  expectClosedQuadDominant(triangle, r, 1, 1);
}

TEST(SqmMesher, RefinementStaysClosedOnTheSweptSpheres) {
  for (const auto& s : {starSkeleton(), ySkeleton()}) {
    medial::SqmParameters p;
    p.subdivisionLevels = 2;
    const auto coarse = medial::sqmMesh(s), fine = medial::sqmMesh(s, p);
    ASSERT_TRUE(fine.ok()) << fine.error;
    const medial::MeshTopology t = topologyOf(fine.mesh);
    EXPECT_EQ(t.borderEdges + t.nonManifoldEdges, 0);
    EXPECT_EQ(t.eulerCharacteristic, 2);
    EXPECT_EQ(fine.mesh.quadCount(), int(fine.mesh.faces.size()));  // the tessellation makes quads only
    // Two levels: each n-gon becomes n quads, each quad four.
    size_t expected = 0;
    for (const auto& f : coarse.mesh.faces) expected += f.size() * 4;
    EXPECT_EQ(fine.mesh.faces.size(), expected);
    // Every vertex lies on the swept surface of some edge (end spheres joined by their tangent cone), or in
    // a crease where two tubes meet, inside one: never outside all. Most lie on a surface (96 % on the
    // star, 99 % on the Y; the rest in the creases between arms; 74 % and 56 % with Catmull-Clark).
    int onACone = 0;
    const medial::SweptSpheres swept(s);
    for (const auto& v : fine.mesh.vertices) {
      double gap = INFINITY, deepest = INFINITY;
      for (int e = 0; e < s.edgeCount(); ++e) {
        const double d = swept.project(v, e).signedDistance();
        gap = std::min(gap, std::abs(d));
        deepest = std::min(deepest, d);
      }
      EXPECT_LT(deepest, 1e-9);
      onACone += gap < 1e-9;
    }
    std::printf("%.0f %% of the refined vertices on a swept surface\n",
                100.0 * onACone / double(fine.mesh.vertices.size()));
    EXPECT_GT(onACone, 0.9 * double(fine.mesh.vertices.size()));
  }
}

TEST(SqmRefinement, SharpScalingShrinksTheConesOnlyNearSharpVertices) {
  EXPECT_DOUBLE_EQ(medial::sharpScaleFactor(0, 0.8), 0.8);
  EXPECT_DOUBLE_EQ(medial::sharpScaleFactor(1, 0.8), 1.0);
  EXPECT_DOUBLE_EQ(medial::sharpScaleFactor(3, 0.8), 1.0);  // clamped beyond one radius
  for (double t = 0; t < 1; t += 0.05)
    EXPECT_LE(medial::sharpScaleFactor(t, 0.8), medial::sharpScaleFactor(t + 0.05, 0.8));
  // A narrow Y: two arms leave the branch node 20 degrees apart, so the mesh folds between them.
  medial::Skeleton s;
  s.nodes = {{0, 0, 0}, {0, -1, 0}, {0, -2, 0}};
  s.radii = {0.5, 0.4, 0.4};
  s.edges = {{0, 1}, {1, 2}};
  for (double side : {-1.0, 1.0}) {
    const Eigen::Vector3d d(side * std::sin(10 * M_PI / 180), std::cos(10 * M_PI / 180), 0);
    for (int k = 1; k <= 3; ++k) {
      s.nodes.push_back(d * k * 0.9);
      s.radii.push_back(0.3);
      s.edges.push_back({k == 1 ? 0 : s.nodeCount() - 2, s.nodeCount() - 1});
    }
  }
  s.root = 0;
  const auto base = medial::sqmMesh(s);
  ASSERT_TRUE(base.ok()) << base.error;
  int insideWith[2] = {0, 0};
  for (const bool on : {false, true}) {
    medial::SqmMesh mesh = base.mesh;
    medial::SharpScaling scaling;
    scaling.enabled = on;
    scaling.minimumScale = 0.6;
    const int sharp = medial::refineSqmMesh(mesh, s, 2, scaling);
    EXPECT_TRUE(topologyOf(mesh).isClosedManifold());
    if (on) {
      EXPECT_GT(sharp, 0);
    }
    int& inside = insideWith[on];
    for (const auto& v :
         mesh.vertices) {  // on a cone, or (scaled, or in a crease) inside one, never outside all
      double nearest = INFINITY, deepest = INFINITY;  // |distance| to the nearest cone; signed, deepest
      for (int e = 0; e < s.edgeCount(); ++e) {
        const double d = medial::SweptSpheres(s).project(v, e).signedDistance();
        nearest = std::min(nearest, std::abs(d));
        deepest = std::min(deepest, d);
      }
      EXPECT_LT(deepest, 1e-9);
      inside += nearest > 1e-6;
    }
  }
  // Both ways some vertices lie inside: without scaling those of the crease between the two arms, with
  // it the shrunk neighbourhood of the sharp vertices (scaling works on the nearest cone, unblended).
  EXPECT_GT(insideWith[0], 0);
  EXPECT_GT(insideWith[1], 0);
}

TEST(RingAngles, AFoldedRingTurnsForwardAgainAndAMonotoneOneStays) {
  std::vector<double> monotone{0.0, 1.0, 2.5, 4.0, 5.5};
  const auto kept = monotone;
  EXPECT_FALSE(medial::untangleAngles(monotone));
  EXPECT_EQ(monotone, kept);
  // 0.8 -> 0.6 turns back (a fold); the ring still winds once around.
  std::vector<double> folded{0.0, 0.8, 0.6, 2.0, 4.0};
  EXPECT_TRUE(medial::untangleAngles(folded));
  EXPECT_DOUBLE_EQ(folded[0], 0.0);
  const double equal = 2 * M_PI / 5;
  for (size_t k = 0; k < folded.size(); ++k)
    EXPECT_GE(std::remainder(folded[(k + 1) % 5] - folded[k], 2 * M_PI), 0.2 * equal - 1e-12) << k;
  // Winding zero (goes out and comes back): equal spacing in the wanted sense.
  std::vector<double> backAndForth{0.0, 1.0, 2.0, 1.0};
  EXPECT_TRUE(medial::untangleAngles(backAndForth, -1));
  for (size_t k = 1; k < 4; ++k) EXPECT_NEAR(backAndForth[k] - backAndForth[k - 1], -M_PI / 2, 1e-12);
}

TEST(CycleClosing, LopsidedRingsStillCloseTheBand) {
  // Ring A around (0,0,0) facing +z, ring B around (0,0,1) facing -z; B's four vertices crowd one side.
  std::vector<Eigen::Vector3d> positions;
  std::vector<int> a, b;
  for (int k = 0; k < 6; ++k) {
    positions.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0});
    a.push_back(int(positions.size()) - 1);
  }
  for (double angle : {0.3, 0.1, -0.1, -0.3}) {  // clockwise seen from +z: counter-clockwise about -z
    positions.push_back({std::cos(angle), std::sin(angle), 1});
    b.push_back(int(positions.size()) - 1);
  }
  const auto band =
      medial::closeCycleGap(positions, a, Eigen::Vector3d(0, 0, 0), b, Eigen::Vector3d(0, 0, 1));
  ASSERT_EQ(band.size(), a.size() + b.size());
  // Every ring edge is used once, in the direction that continues the tubes: A forwards, B forwards.
  std::vector<std::vector<int64_t>> faces;
  for (const auto& t : band) faces.push_back({t[0], t[1], t[2]});
  const medial::MeshTopology t = medial::computeMeshTopology(int64_t(positions.size()), faces);
  EXPECT_EQ(t.borderEdges, int64_t(a.size() + b.size()));  // the band's two rims
  EXPECT_EQ(t.nonManifoldEdges, 0);
  EXPECT_EQ(t.boundaryLoops, 2);
  for (const auto& tri : band)
    for (int c = 0; c < 3; ++c) {
      const int from = tri[size_t(c)], to = tri[size_t((c + 1) % 3)];
      if (from < 6 && to < 6) {
        EXPECT_EQ(to, (from + 1) % 6);
      }
      if (from >= 6 && to >= 6) {
        EXPECT_EQ(to - 6, (from - 6 + 1) % 4);
      }
    }
}

TEST(SqmMesher, NodesInsideANeighboursSphereAreMergedIntoIt) {
  // A thick root with three arms; the first node of one arm lies inside the root's sphere, and so does
  // the next one once the first is merged (a thin part joining a thick one, like a finger at a palm).
  auto s = ySkeleton();
  s.radii[0] = 1.05;
  s.nodes.insert(s.nodes.begin() + 1, Eigen::Vector3d(0.5, 0, 0));  // becomes node 1; the old 1.. shift
  s.radii.insert(s.radii.begin() + 1, 0.35);
  for (auto& e : s.edges)
    for (int& v : e) v += v >= 1 ? 1 : 0;
  for (auto& e : s.edges)
    if (e == std::array<int, 2>{0, 2}) e = {1, 2};
  s.edges.push_back({0, 1});
  const auto r = medial::sqmMesh(s);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.mergedNodes,
            2);  // (0.5, 0, 0) and (1, 0, 0), closer to the root than its radius; not (-0.5, 1, 0)
  const medial::MeshTopology t = topologyOf(r.mesh);
  EXPECT_EQ(t.borderEdges, 0);
  EXPECT_EQ(t.nonManifoldEdges, 0);
  EXPECT_EQ(t.eulerCharacteristic, 2);
  for (int node : r.mesh.vertexNode) EXPECT_TRUE(node != 1 && node != 2) << "a merged node owns a vertex";

  // A neighbour exactly as large as the branch node is swallowed too, whichever way round the edge is
  // listed (a spine of equal spheres through a shoulder).
  auto equal = ySkeleton();
  equal.nodes.push_back(Eigen::Vector3d(0, 0, 0.3));
  equal.radii.push_back(equal.radii[0]);
  equal.edges.push_back({int(equal.nodes.size()) - 1, 0});
  const auto spine = medial::sqmMesh(equal);
  ASSERT_TRUE(spine.ok()) << spine.error;
  EXPECT_EQ(spine.mergedNodes, 1);

  // A larger neighbour inside the branch node's sphere is swallowed too; the branch node takes its radius.
  auto larger = ySkeleton();
  larger.nodes.push_back(Eigen::Vector3d(0, 0, 0.3));
  larger.radii.push_back(0.5);
  larger.edges.push_back({0, int(larger.nodes.size()) - 1});
  const auto grown = medial::sqmMesh(larger);
  ASSERT_TRUE(grown.ok()) << grown.error;
  EXPECT_EQ(grown.mergedNodes, 1);
  double farthest = 0;
  for (size_t v = 0; v < grown.mesh.vertices.size(); ++v)
    if (grown.mesh.vertexNode[v] == 0) farthest = std::max(farthest, grown.mesh.vertices[v].norm());
  EXPECT_NEAR(farthest, 0.5, 1e-9);

  // Two branch nodes whose spheres overlap by more than half the smaller radius merge; by less, not.
  auto twoBranches = [](double distance) {
    medial::Skeleton s;
    s.nodes = {{0, 0, 0},     {distance, 0, 0},       {-1, 0.5, 0},
               {-1, -0.5, 0}, {distance + 1, 0.5, 0}, {distance + 1, -0.5, 0}};
    s.radii = {0.4, 0.3, 0.2, 0.2, 0.2, 0.2};
    s.edges = {{0, 1}, {0, 2}, {0, 3}, {1, 4}, {1, 5}};
    return medial::sqmMesh(s);
  };
  EXPECT_EQ(twoBranches(0.5).mergedNodes, 1);  // overlap 0.2 > 0.15
  EXPECT_EQ(twoBranches(0.6).mergedNodes, 0);  // overlap 0.1 < 0.15
  EXPECT_TRUE(twoBranches(0.5).ok());

  // In a cycle of three, merging would close the cycle onto one edge: the nodes stay.
  medial::Skeleton triangle;
  triangle.nodes = {{0, 0, 0}, {0.5, 0, 0}, {0.25, 2, 0}};
  triangle.radii = {0.8, 0.2, 0.2};
  triangle.edges = {{0, 1}, {1, 2}, {2, 0}};
  const auto kept = medial::sqmMesh(triangle);
  EXPECT_EQ(kept.mergedNodes, 0);
}

TEST(SqmMesher, BadInputIsRefusedOrRepaired) {
  EXPECT_EQ(medial::sqmMesh(medial::Skeleton()).error.message(), "the skeleton has no nodes");
  auto noRadius = ySkeleton();
  noRadius.radii.clear();
  EXPECT_EQ(medial::sqmMesh(noRadius).error.message(), "the skeleton has no Radius per node (SQM needs one)");
  auto zeroRadius = ySkeleton();
  zeroRadius.radii[3] = 0;
  EXPECT_NE(medial::sqmMesh(zeroRadius).error.message().find("node 3"), std::string::npos);
  auto nan = ySkeleton();
  nan.nodes[2].x() = NAN;
  EXPECT_NE(medial::sqmMesh(nan).error.message().find("node 2"), std::string::npos);
  auto coincident = ySkeleton();
  coincident.nodes[2] = coincident.nodes[1];
  EXPECT_EQ(medial::sqmMesh(coincident).error.message(),
            "nodes 1 and 2 are joined by an edge but lie at the same place");
  auto sameDirection = ySkeleton();
  sameDirection.nodes.push_back({2, 0, 0});  // a second edge from node 0 along +x
  sameDirection.radii.push_back(0.3);
  sameDirection.edges.push_back({0, 7});
  sameDirection.nodes[1] = {1, 0, 0};
  sameDirection.edges[1] = {1, 2};
  EXPECT_NE(medial::sqmMesh(sameDirection).error.message().find("same direction"), std::string::npos);

  // Repairs: a self-loop is dropped, a repeated edge merged.
  auto repaired = ySkeleton();
  repaired.edges.push_back({3, 3});
  repaired.edges.push_back({1, 0});
  expectClosedQuadDominant(ySkeleton(), medial::sqmMesh(repaired));
}
