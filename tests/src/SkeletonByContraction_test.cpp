#include "ContractionTestMeshes.h"
#include "contraction/EmbeddingRefinement.h"
#include "contraction/NodeSelection.h"
#include "contraction/SkeletonByContraction.h"
#include "mesh/InsideTest.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <numeric>

using medial::testing::appendMesh;
using medial::testing::torusMesh;
using medial::testing::tubeMesh;

namespace {

struct GraphCounts {
  int components = 0, cycles = 0;
};

GraphCounts countGraph(const medial::Skeleton& s) {
  std::vector<int> parent(s.nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int x) {
    return parent[size_t(x)] == x ? x : parent[size_t(x)] = find(parent[size_t(x)]);
  };
  for (const auto& e : s.edges) parent[size_t(find(e[0]))] = find(e[1]);
  GraphCounts c;
  for (int i = 0; i < s.nodeCount(); ++i) c.components += find(i) == i;
  c.cycles = s.edgeCount() - s.nodeCount() + c.components;
  return c;
}

double distanceToSkeleton(const Eigen::Vector3d& p, const medial::Skeleton& s) {
  double best = INFINITY;
  for (const auto& e : s.edges) {
    const Eigen::Vector3d a = s.nodes[size_t(e[0])], b = s.nodes[size_t(e[1])];
    const double t = std::clamp((p - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - p).norm());
  }
  return best;
}

}  // namespace

TEST(SkeletonByContraction, TorusGivesOneCycleInsideTheMesh) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  const auto r = medial::skeletonByContraction(torus);
  ASSERT_TRUE(r.ok()) << r.error;
  const GraphCounts c = countGraph(r.skeleton);
  EXPECT_EQ(c.components, 1);
  EXPECT_EQ(c.cycles, 1);
  EXPECT_LE(r.skeleton.nodeCount(), 30);
  EXPECT_GE(r.skeleton.nodeCount(), 3);
  const medial::InsideTest inside(torus);
  for (const auto& node : r.skeleton.nodes) {
    EXPECT_TRUE(inside.contains(node)) << node.transpose();
    EXPECT_NEAR(std::hypot(node.x(), node.y()), 2.0, 0.25);  // on the core circle
  }
  for (const auto& e : r.skeleton.edges)
    EXPECT_TRUE(inside.contains(0.5 * (r.skeleton.nodes[size_t(e[0])] + r.skeleton.nodes[size_t(e[1])])));
  for (double radius : r.skeleton.radii) EXPECT_NEAR(radius, 0.5, 0.2);
  EXPECT_TRUE(medial::validateSkeleton(r.skeleton).empty());
}

TEST(SkeletonByContraction, EveryVertexMapsToANode) {
  const auto r = medial::skeletonByContraction(tubeMesh(10, 1));
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.vertexToNode.size(), size_t(tubeMesh(10, 1).vertices.rows()));
  for (int node : r.vertexToNode) {
    EXPECT_GE(node, 0);
    EXPECT_LT(node, r.skeleton.nodeCount());
  }
  const GraphCounts c = countGraph(r.skeleton);
  EXPECT_EQ(c.components, 1);
  EXPECT_EQ(c.cycles, 0);
}

TEST(SkeletonByContraction, OneSkeletonPerComponent) {
  const auto mesh = appendMesh(torusMesh(2, 0.5), tubeMesh(6, 0.8), Eigen::RowVector3d(10, 0, 0));
  const auto r = medial::skeletonByContraction(mesh);
  ASSERT_TRUE(r.ok()) << r.error;
  const GraphCounts c = countGraph(r.skeleton);
  EXPECT_EQ(c.components, 2);
  EXPECT_EQ(c.cycles, 1);
}

TEST(SkeletonByContraction, ScaleDoesNotChangeTheSkeleton) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  const auto reference = medial::skeletonByContraction(torus);
  for (double scale : {1e-3, 1e3}) {
    medial::TriangleMesh scaled = torus;
    scaled.vertices *= scale;
    const auto r = medial::skeletonByContraction(scaled);
    ASSERT_TRUE(r.ok());
    // Collapse ties on a symmetric torus may break differently after rounding, so compare shapes: same
    // cycle count, and every node lies on the reference skeleton (within 2% of the torus size, 5).
    EXPECT_EQ(countGraph(r.skeleton).cycles, countGraph(reference.skeleton).cycles);
    for (const auto& node : r.skeleton.nodes)
      EXPECT_LT(distanceToSkeleton(node / scale, reference.skeleton), 0.1) << node.transpose() / scale;
  }
}

// A fine torus whose vertices are moved a little at random (fixed seed): no two collapses tie, so results
// at different scales can be compared node by node.
medial::TriangleMesh jitteredTorus() {
  medial::TriangleMesh torus = torusMesh(2, 0.5, 96, 32);  // 3072 vertices
  std::srand(7);
  for (Eigen::Index v = 0; v < torus.vertices.rows(); ++v)
    for (int c = 0; c < 3; ++c) torus.vertices(v, c) += 0.01 * (std::rand() / double(RAND_MAX) - 0.5);
  return torus;
}

TEST(SkeletonByContraction, ADecimatedMeshGivesTheSameSkeletonForEveryVertex) {
  // 3072 vertices over a budget of 600: the coarse mesh is contracted, the input's vertices come back.
  const medial::TriangleMesh torus = jitteredTorus();
  medial::SkeletonByContractionParameters p;
  p.contractionVertices = 600;
  p.computeWeights = true;
  const auto r = medial::skeletonByContraction(torus, p);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_LE(r.contractedVertices, 610);
  EXPECT_EQ(countGraph(r.skeleton).cycles, 1);
  const medial::InsideTest inside(torus);
  for (const auto& node : r.skeleton.nodes) {
    EXPECT_TRUE(inside.contains(node)) << node.transpose();
    EXPECT_NEAR(std::hypot(node.x(), node.y()), 2.0, 0.25);
  }
  for (double radius : r.skeleton.radii) EXPECT_NEAR(radius, 0.5, 0.2);
  ASSERT_EQ(r.vertexToNode.size(), size_t(torus.vertices.rows()));
  ASSERT_EQ(r.weights.rows(), torus.vertices.rows());
  for (Eigen::Index v = 0; v < torus.vertices.rows(); ++v) {
    const int node = r.vertexToNode[size_t(v)];
    ASSERT_GE(node, 0);
    // A vertex belongs to a node on its own side of the torus (within a quarter turn).
    const Eigen::Vector3d n = r.skeleton.nodes[size_t(node)];
    EXPECT_GT(n.head<2>().normalized().dot(torus.vertices.row(v).head<2>().normalized()), 0.7);
    EXPECT_NEAR(r.weights.row(v).sum(), 1.0, 1e-9);
  }

  // Without the budget the whole mesh is contracted; the skeleton lies on the same circle.
  p.contractionVertices = 0;
  const auto full = medial::skeletonByContraction(torus, p);
  ASSERT_TRUE(full.ok()) << full.error;
  EXPECT_EQ(full.contractedVertices, torus.vertices.rows());
  for (const auto& node : r.skeleton.nodes) EXPECT_LT(distanceToSkeleton(node, full.skeleton), 0.15);
}

TEST(SkeletonByContraction, DecimationDoesNotDependOnTheScale) {
  const medial::TriangleMesh torus = jitteredTorus();
  medial::SkeletonByContractionParameters p;
  p.contractionVertices = 600;
  const auto reference = medial::skeletonByContraction(torus, p);
  ASSERT_TRUE(reference.ok());
  for (double scale : {1e-3, 1e3}) {
    medial::TriangleMesh scaled = torus;
    scaled.vertices *= scale;
    const auto r = medial::skeletonByContraction(scaled, p);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(countGraph(r.skeleton).cycles, 1);
    for (const auto& node : r.skeleton.nodes)
      EXPECT_LT(distanceToSkeleton(node / scale, reference.skeleton), 0.1) << node.transpose() / scale;
  }
}

TEST(SkeletonByContraction, DegenerateFacesAreTolerated) {
  medial::TriangleMesh torus = torusMesh(2, 0.5);
  torus.faces.conservativeResize(torus.faces.rows() + 1, 3);
  torus.faces.row(torus.faces.rows() - 1) << 0, 1, 1;  // zero area
  const auto r = medial::skeletonByContraction(torus);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(countGraph(r.skeleton).cycles, 1);
}

TEST(SkeletonByContraction, NonManifoldFinIsTolerated) {
  // A fin: a triangle on an edge of the torus that two torus faces already share (3 faces on one edge).
  medial::TriangleMesh torus = torusMesh(2, 0.5);
  const int a = torus.faces(0, 0), b = torus.faces(0, 1);
  torus.vertices.conservativeResize(torus.vertices.rows() + 1, 3);
  torus.vertices.row(torus.vertices.rows() - 1) =
      0.5 * (torus.vertices.row(a) + torus.vertices.row(b)) + Eigen::RowVector3d(0, 0, 0.3);
  torus.faces.conservativeResize(torus.faces.rows() + 1, 3);
  torus.faces.row(torus.faces.rows() - 1) << a, b, int(torus.vertices.rows() - 1);
  medial::SkeletonByContractionParameters p;
  p.computeWeights = true;
  const auto r = medial::skeletonByContraction(torus, p);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(countGraph(r.skeleton).components, 1);
  EXPECT_EQ(countGraph(r.skeleton).cycles, 1);
  for (Eigen::Index j = 0; j < torus.vertices.rows(); ++j) EXPECT_NEAR(r.weights.row(j).sum(), 1.0, 1e-9);
}

TEST(SkeletonByContraction, BadInputIsRefusedWithAMessage) {
  medial::TriangleMesh empty;
  EXPECT_EQ(medial::skeletonByContraction(empty).error.message(), "the mesh has no triangles");

  medial::TriangleMesh nan = torusMesh(2, 0.5);
  nan.vertices(7, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(medial::skeletonByContraction(nan).error.message(),
            "vertex 7 has a non-finite coordinate (NaN or infinity)");

  medial::TriangleMesh outOfRange = torusMesh(2, 0.5);
  outOfRange.faces(3, 2) = 100000;
  EXPECT_EQ(medial::skeletonByContraction(outOfRange).error.message(),
            "triangle 3 refers to vertex 100000, which does not exist");
}

// Two nodes joined by one edge; no mesh vertex belongs to either yet.
medial::CurveSkeleton twoNodeCurve(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   Eigen::Index vertexCount) {
  medial::CurveSkeleton curve;
  curve.nodes.resize(2, 3);
  curve.nodes.row(0) = a.transpose();
  curve.nodes.row(1) = b.transpose();
  curve.edges = {{0, 1}};
  curve.vertexToNode.assign(size_t(vertexCount), -1);
  return curve;
}

TEST(EmbeddingRefinement, AnEdgeAcrossTheHoleIsSplitAlongTheMesh) {
  // Two nodes on opposite sides of a torus, each holding its quarter of the upper half ring: their edge
  // crosses the hole. Split, the path follows the half ring inside the tube.
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  const medial::InsideTest inside(torus);
  medial::CurveSkeleton curve = twoNodeCurve({2, 0, 0}, {-2, 0, 0}, torus.vertices.rows());
  for (Eigen::Index v = 0; v < torus.vertices.rows(); ++v)
    if (torus.vertices(v, 1) >= 0) curve.vertexToNode[size_t(v)] = torus.vertices(v, 0) >= 0 ? 0 : 1;
  const int added = medial::splitEdgesLeavingTheMesh(curve, torus.vertices, inside);
  EXPECT_GE(added, 3);
  ASSERT_EQ(curve.nodes.rows(), 2 + added);
  EXPECT_EQ(int(curve.edges.size()), 1 + added);  // still one path from node 0 to node 1
  for (const auto& [a, b] : curve.edges)
    EXPECT_TRUE(inside.segmentIsClear(curve.nodes.row(a).transpose(), curve.nodes.row(b).transpose()));
  for (Eigen::Index k = 2; k < curve.nodes.rows(); ++k) {
    EXPECT_TRUE(inside.contains(curve.nodes.row(k).transpose()));
    EXPECT_GT(curve.nodes(k, 1), 0);  // on the half ring the vertices came from
  }
  for (Eigen::Index v = 0; v < torus.vertices.rows(); ++v)  // vertices keep a node iff they had one
    EXPECT_EQ(curve.vertexToNode[size_t(v)] >= 0, torus.vertices(v, 1) >= 0);
}

TEST(EmbeddingRefinement, AnEdgeWithoutAbsorbedVerticesIsSplitInsideToo) {
  // Two nodes on the core circle of a torus, 120 degrees apart, with no absorbed vertices: their chord
  // passes 1 from the centre, through the hole. The split node comes from the search across the chord.
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  const medial::InsideTest inside(torus);
  medial::CurveSkeleton curve =
      twoNodeCurve({1, std::sqrt(3.0), 0}, {1, -std::sqrt(3.0), 0}, torus.vertices.rows());
  const int added = medial::splitEdgesLeavingTheMesh(curve, torus.vertices, inside);
  EXPECT_GE(added, 1);
  for (const auto& [a, b] : curve.edges)
    EXPECT_TRUE(inside.segmentIsClear(curve.nodes.row(a).transpose(), curve.nodes.row(b).transpose()));
  for (Eigen::Index k = 2; k < curve.nodes.rows(); ++k)
    EXPECT_TRUE(inside.contains(curve.nodes.row(k).transpose()));
}

TEST(EmbeddingRefinement, ANodeOutsideIsPushedToTheMiddleOfThePart) {
  // A node 0.5 outside the torus's tube (R 2, r 0.5) at x = 3 moves through the nearest surface point
  // (2.5, 0, 0) to the tube's axis; the node inside stays where it is.
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  const medial::InsideTest inside(torus);
  medial::CurveSkeleton curve = twoNodeCurve({3, 0, 0}, {-2, 0, 0}, torus.vertices.rows());
  EXPECT_EQ(medial::pushNodesInside(curve, inside), 1);
  EXPECT_TRUE(inside.contains(curve.nodes.row(0).transpose()));
  EXPECT_NEAR(curve.nodes(0, 0), 2.0, 0.1);
  EXPECT_NEAR(curve.nodes(0, 1), 0.0, 1e-9);
  EXPECT_NEAR(curve.nodes(0, 2), 0.0, 1e-9);
  EXPECT_EQ(curve.nodes(1, 0), -2.0);
}

TEST(NodeSelection, KeepsCyclesAndTips) {
  // A square cycle with a long tail of 10 nodes: selection down to 4 keeps the cycle and the tip.
  medial::CurveSkeleton s;
  s.nodes.resize(14, 3);
  s.nodes.row(0) << 0, 0, 0;
  s.nodes.row(1) << 1, 0, 0;
  s.nodes.row(2) << 1, 1, 0;
  s.nodes.row(3) << 0, 1, 0;
  s.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  for (int k = 0; k < 10; ++k) {
    s.nodes.row(4 + k) << 1 + 0.3 * (k + 1), 0, 0;
    s.edges.emplace_back(k == 0 ? 1 : 3 + k, 4 + k);
  }
  s.vertexToNode = {13, 0};
  std::vector<int> cameFrom;
  medial::selectNodes(s, 4, nullptr, &cameFrom);
  const medial::Skeleton out = medial::skeletonOf(s);
  ASSERT_EQ(cameFrom.size(), out.nodes.size());
  EXPECT_EQ(cameFrom[size_t(s.vertexToNode[0])], 13);  // the tip is the tail's last node
  const GraphCounts c = countGraph(out);
  EXPECT_EQ(c.cycles, 1);
  EXPECT_EQ(c.components, 1);
  EXPECT_EQ(out.nodeCount(), 4);  // a cycle needs three nodes, the tail its tip
  EXPECT_NEAR(out.nodes[size_t(s.vertexToNode[0])].x(), 4.0, 1e-12);  // the tip did not move
}

TEST(NodeSelection, ShortSideBranchesGoFirst) {
  // A straight limb of 5 nodes along x with a short twig (0.2) and a long branch (3 edges of 1) off its
  // middle node: down to 6 nodes the twig goes, the branch keeps its tip.
  medial::CurveSkeleton s;
  s.nodes.resize(9, 3);
  for (int k = 0; k < 5; ++k) s.nodes.row(k) << k, 0, 0;
  s.nodes.row(5) << 2, 0.2, 0;
  for (int k = 0; k < 3; ++k) s.nodes.row(6 + k) << 2, -(k + 1.0), 0;
  s.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {2, 5}, {2, 6}, {6, 7}, {7, 8}};
  s.vertexToNode = {5, 8};
  medial::selectNodes(s, 6);
  const medial::Skeleton out = medial::skeletonOf(s);
  EXPECT_EQ(out.nodeCount(), 6);
  EXPECT_EQ(countGraph(out).components, 1);
  EXPECT_NEAR(out.nodes[size_t(s.vertexToNode[0])].y(), 0.0, 1e-12);   // the twig's vertex went to the limb
  EXPECT_NEAR(out.nodes[size_t(s.vertexToNode[1])].y(), -3.0, 1e-12);  // the branch tip stayed
}

TEST(NodeSelection, RefusesCollapsesThatLeaveTheMesh) {
  // The core circle of a torus (R 2, r 0.5) as 24 nodes. Down to 3 nodes without a mesh: a triangle,
  // whose edge midpoints (1 from the axis) lie outside the tube. With the mesh, selection stops while
  // every edge stays inside (a hexagon's midpoints are at 1.73).
  auto circle = [] {
    medial::CurveSkeleton s;
    s.nodes.resize(24, 3);
    for (int k = 0; k < 24; ++k) {
      s.nodes.row(k) << 2 * std::cos(k * M_PI / 12), 2 * std::sin(k * M_PI / 12), 0;
      s.edges.emplace_back(k, (k + 1) % 24);
    }
    return s;
  };
  medial::CurveSkeleton free = circle();
  medial::selectNodes(free, 3);
  EXPECT_EQ(free.nodes.rows(), 3);

  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  const medial::InsideTest inside(torus);
  medial::CurveSkeleton constrained = circle();
  medial::selectNodes(constrained, 3, &inside);
  EXPECT_GE(constrained.nodes.rows(), 6);
  EXPECT_EQ(countGraph(medial::skeletonOf(constrained)).cycles, 1);
  for (const auto& [a, b] : constrained.edges)
    EXPECT_TRUE(
        inside.segmentIsClear(constrained.nodes.row(a).transpose(), constrained.nodes.row(b).transpose()));
}

TEST(NodeSelection, ShortensACurledTipRatherThanStopAboveTheTarget) {
  // A curled finger: 12 nodes 30 degrees apart on an open arc inside a thin torus (R 2, r 0.1), where
  // every chord over two steps leaves the tube. Merging at the preferred place (the tip, or the middle)
  // stops at 12; the second pass keeps the inner end and so reaches the 4 nodes asked for, inside.
  medial::CurveSkeleton s;
  s.nodes.resize(12, 3);
  for (int k = 0; k < 12; ++k) {
    s.nodes.row(k) << 2 * std::cos(k * M_PI / 6), 2 * std::sin(k * M_PI / 6), 0;
    if (k > 0) s.edges.emplace_back(k - 1, k);
  }
  const medial::TriangleMesh torus = torusMesh(2, 0.1, 96, 12);
  const medial::InsideTest inside(torus);
  medial::selectNodes(s, 4, &inside);
  ASSERT_EQ(s.nodes.rows(), 4);
  EXPECT_EQ(countGraph(medial::skeletonOf(s)).components, 1);
  for (const auto& [a, b] : s.edges)
    EXPECT_TRUE(inside.segmentIsClear(s.nodes.row(a).transpose(), s.nodes.row(b).transpose()));
}

// The preconditioned conjugate gradients reach the skeleton the direct solver does (it failed on real
// meshes without a preconditioner).
TEST(SkeletonByContraction, ConjugateGradientsGiveTheSameSkeletonAsCholmod) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5, 32, 12);
  medial::SkeletonByContractionParameters p;
  const auto direct = medial::skeletonByContraction(torus, p);
  p.contraction.solver = medial::SparseSolverKind::ConjugateGradient;
  const auto iterative = medial::skeletonByContraction(torus, p);
  ASSERT_TRUE(direct.ok()) << direct.error;
  ASSERT_TRUE(iterative.ok()) << iterative.error;
  ASSERT_EQ(direct.skeleton.nodeCount(), iterative.skeleton.nodeCount());
  EXPECT_EQ(direct.contractionIterations, iterative.contractionIterations);
  for (size_t k = 0; k < direct.skeleton.nodes.size(); ++k)
    EXPECT_LT((direct.skeleton.nodes[k] - iterative.skeleton.nodes[k]).norm(), 1e-3) << k;
}
