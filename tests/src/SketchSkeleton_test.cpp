// Sketch skeletonization (Ma et al. 2021) on the strokes of data/sketches (made by data/make-sketches.py):
// the invariants (inside the polygon, a tree, the star's joints, refinement never adds joints),
// BoundedDP, the inflated mesh, and bad input.
#include "TestPaths.h"

#include "mesh/InsideTest.h"
#include "mesh/MeshTopology.h"
#include "mesh/SelfIntersections.h"
#include "sketch/BoundedDP.h"
#include "sketch/SketchInflation.h"
#include "sketch/SketchSkeleton.h"
#include "sketch/StraightSkeletonGraph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace {

using medial::Polygon2;
using medial::SketchPart;

// The sketch text format (see data/make-sketches.py): parts of `x y` lines, optional 4x4 placement rows.
std::vector<SketchPart> loadSketch(const std::string& name) {
  std::ifstream file(medial::test::dataPath("sketches/" + name));
  std::vector<SketchPart> parts(1);
  std::vector<Eigen::RowVector4d> rows;
  std::string line;
  auto finish = [&] {
    if (rows.size() == 4)
      for (int r = 0; r < 4; ++r) parts.back().placement.row(r) = rows[r];
    rows.clear();
  };
  while (std::getline(file, line)) {
    if (!line.empty() && line[0] == '#') continue;
    std::istringstream in(line);
    std::vector<double> v;
    for (double x; in >> x;) v.push_back(x);
    if (v.empty()) {
      finish();
      if (!parts.back().stroke.empty()) parts.emplace_back();
    } else if (v.size() == 2) {
      parts.back().stroke.emplace_back(v[0], v[1]);
    } else if (v.size() == 4) {
      rows.emplace_back(v[0], v[1], v[2], v[3]);
    }
  }
  finish();
  return parts;
}

std::vector<std::vector<int64_t>> faceLists(const medial::TriangleMesh& mesh) {
  std::vector<std::vector<int64_t>> faces;
  for (int f = 0; f < mesh.faces.rows(); ++f)
    faces.push_back({mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2)});
  return faces;
}

std::vector<int> degrees(const medial::Skeleton& s) { return medial::nodeDegrees(s); }

int countDegree(const medial::Skeleton& s, int wanted) {
  int count = 0;
  for (int d : degrees(s)) count += wanted >= 3 ? d >= 3 : d == wanted;
  return count;
}

// A forest with one tree: connected and edges = nodes - 1.
bool isTree(const medial::Skeleton& s) {
  if (s.edgeCount() != s.nodeCount() - 1) return false;
  std::vector<std::vector<int>> adjacent(s.nodeCount());
  for (const auto& e : s.edges) adjacent[e[0]].push_back(e[1]), adjacent[e[1]].push_back(e[0]);
  std::vector<char> seen(s.nodeCount(), 0);
  std::vector<int> stack{0};
  seen[0] = 1;
  int reached = 1;
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    for (int w : adjacent[v])
      if (!seen[w]) seen[w] = 1, ++reached, stack.push_back(w);
  }
  return reached == s.nodeCount();
}

// Every node and every bone (sampled) of a one-part, unplaced sketch lies inside its stroke.
void expectInside(const medial::SketchResult& r, const Polygon2& stroke) {
  const auto& s = r.graph.skeleton;
  for (const auto& e : s.edges)
    for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const Eigen::Vector3d p = (1 - t) * s.nodes[e[0]] + t * s.nodes[e[1]];
      EXPECT_TRUE(medial::isInside(stroke, p.head<2>())) << "bone point " << p.transpose() << " outside";
    }
  for (int v = 0; v < s.nodeCount(); ++v) {
    EXPECT_TRUE(medial::isInside(stroke, s.nodes[v].head<2>()));
    EXPECT_GT(s.radii[v], 0);
  }
}

TEST(SketchSkeleton, RectangleIsOneBone) {
  const auto parts = loadSketch("rectangle.txt");
  const auto r = medial::sketchSkeleton(parts);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.graph.skeleton.nodeCount(), 2);
  EXPECT_EQ(r.graph.skeleton.edgeCount(), 1);
  expectInside(r, parts[0].stroke);
  // Along the long axis, centred, with the half-height as radius (50).
  for (int v = 0; v < 2; ++v) {
    EXPECT_NEAR(r.graph.skeleton.nodes[v].y(), 50, 1.0);
    EXPECT_NEAR(r.graph.skeleton.radii[v], 50, 2.0);
  }
}

TEST(SketchSkeleton, StarHasOneJunctionAndFiveTerminals) {
  const auto parts = loadSketch("star.txt");
  const auto r = medial::sketchSkeleton(parts);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(isTree(r.graph.skeleton));
  EXPECT_EQ(countDegree(r.graph.skeleton, 3), 1);
  EXPECT_EQ(countDegree(r.graph.skeleton, 1), 5);
  expectInside(r, parts[0].stroke);
  // The terminals reach into the points: beyond the inner radius 120.
  const auto d = degrees(r.graph.skeleton);
  for (int v = 0; v < r.graph.skeleton.nodeCount(); ++v) {
    if (d[v] == 1) {
      EXPECT_GT(r.graph.skeleton.nodes[v].norm(), 150);
    }
  }
}

TEST(SketchSkeleton, HandHasSixTerminalsAndStaysInside) {
  const auto parts = loadSketch("hand.txt");
  const auto r = medial::sketchSkeleton(parts);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(isTree(r.graph.skeleton));
  EXPECT_EQ(countDegree(r.graph.skeleton, 1), 6);  // five fingers and the wrist
  expectInside(r, parts[0].stroke);
}

TEST(SketchSkeleton, UnsteadyStrokeGivesOnePath) {
  const auto parts = loadSketch("unsteady.txt");
  const auto r = medial::sketchSkeleton(parts);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(isTree(r.graph.skeleton));
  EXPECT_EQ(countDegree(r.graph.skeleton, 1), 2);
  EXPECT_EQ(countDegree(r.graph.skeleton, 3), 0);
  expectInside(r, parts[0].stroke);
  // The 2000 jittered points became a polygon of a few dozen vertices.
  EXPECT_LT(r.parts[0].stroke.polygon.size(), 80u);
}

TEST(SketchSkeleton, BirdWingsAttachToTheBody) {
  const auto parts = loadSketch("bird.txt");
  ASSERT_EQ(parts.size(), 3u);
  const auto r = medial::sketchSkeleton(parts);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(isTree(r.graph.skeleton));  // three parts, one tree
  EXPECT_EQ(r.parts[0].attachment.parent, -1);
  EXPECT_EQ(r.parts[1].attachment.parent, 0);
  EXPECT_EQ(r.parts[2].attachment.parent, 0);
  // Wings lie in the horizontal plane through the body: their tips far out in +z and -z.
  double zMin = 0, zMax = 0;
  for (const auto& p : r.graph.skeleton.nodes) zMin = std::min(zMin, p.z()), zMax = std::max(zMax, p.z());
  EXPECT_GT(zMax, 300);
  EXPECT_LT(zMin, -300);
  EXPECT_EQ(r.graph.nodePart[r.graph.skeleton.root], 0);
}

TEST(SketchSkeleton, LargerThresholdsNeverAddJoints) {
  for (const char* name : {"hand.txt", "bird.txt", "star.txt", "unsteady.txt"}) {
    const auto parts = loadSketch(name);
    for (double medial::RefinementThresholds::*which :
         {&medial::RefinementThresholds::simplification, &medial::RefinementThresholds::merging,
          &medial::RefinementThresholds::pruning, &medial::RefinementThresholds::collapsing}) {
      int previous = std::numeric_limits<int>::max();
      for (double factor : {0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 8.0}) {
        medial::SketchParameters p;
        p.inflate = false;
        p.thresholds.*which *= factor;
        const auto r = medial::sketchSkeleton(parts, p);
        ASSERT_TRUE(r.ok()) << r.error;
        EXPECT_TRUE(isTree(r.graph.skeleton)) << name;
        EXPECT_LE(r.graph.skeleton.nodeCount(), previous)
            << name << " factor " << factor << " threshold "
            << (p.thresholds.merging != 30      ? "merging"
                : p.thresholds.pruning != 30    ? "pruning"
                : p.thresholds.collapsing != 10 ? "collapsing"
                                                : "simplification");
        previous = r.graph.skeleton.nodeCount();
      }
    }
  }
}

TEST(SketchSkeleton, PartThresholdsApplyToTheirPartOnly) {
  auto parts = loadSketch("bird.txt");
  medial::SketchParameters p;
  p.inflate = false;
  const auto plain = medial::sketchSkeleton(parts, p);
  parts[1].thresholds = medial::RefinementThresholds{200, 30, 30, 10};  // one wing much simpler
  const auto coarse = medial::sketchSkeleton(parts, p);
  ASSERT_TRUE(plain.ok() && coarse.ok());
  auto count = [](const medial::SketchResult& r, int part) {
    int n = 0;
    for (int q : r.graph.nodePart) n += q == part;
    return n;
  };
  EXPECT_LT(count(coarse, 1), count(plain, 1));
  EXPECT_EQ(count(coarse, 2), count(plain, 2));
  EXPECT_EQ(count(coarse, 0), count(plain, 0));
}

TEST(SketchSkeleton, ScaleDoesNotChangeTheSkeleton) {
  auto parts = loadSketch("hand.txt");
  const auto r1 = medial::sketchSkeleton(parts);
  for (auto& q : parts[0].stroke) q *= 0.001;  // the same drawing in metres
  const auto r2 = medial::sketchSkeleton(parts);
  ASSERT_TRUE(r1.ok() && r2.ok());
  EXPECT_EQ(r1.graph.skeleton.nodeCount(), r2.graph.skeleton.nodeCount());
  EXPECT_EQ(r1.graph.skeleton.edgeCount(), r2.graph.skeleton.edgeCount());
}

// The invariant: each sample sketch gives one closed manifold mesh (a sphere's topology), no face
// cutting another, every skeleton node inside; its vertices are labelled with every part.
TEST(SketchSkeleton, InflatedPartsJoinIntoOneWatertightMeshAroundTheSkeleton) {
  for (const char* name : {"bird.txt", "hand.txt", "star.txt"}) {
    SCOPED_TRACE(name);
    const auto parts = loadSketch(name);
    const auto r = medial::sketchSkeleton(parts);
    ASSERT_TRUE(r.ok()) << r.error;
    const auto faces = faceLists(r.mesh);
    const auto t = medial::computeMeshTopology(r.mesh.vertices.rows(), faces);
    EXPECT_EQ(t.borderEdges, 0);
    EXPECT_EQ(t.nonManifoldEdges, 0);
    EXPECT_EQ(t.components, 1);
    EXPECT_EQ(t.eulerCharacteristic, 2);
    std::vector<Eigen::Vector3d> points(size_t(r.mesh.vertices.rows()));
    for (size_t v = 0; v < points.size(); ++v) points[v] = r.mesh.vertices.row(Eigen::Index(v)).transpose();
    EXPECT_TRUE(medial::selfIntersectingFaces(points, faces).empty());
    const medial::InsideTest inside(r.mesh);
    for (const Eigen::Vector3d& node : r.graph.skeleton.nodes)
      EXPECT_TRUE(inside.contains(node)) << node.transpose();
    ASSERT_EQ(r.meshVertexPart.size(), points.size());
    for (int k = 0; k < int(parts.size()); ++k)
      EXPECT_NE(std::find(r.meshVertexPart.begin(), r.meshVertexPart.end(), k), r.meshVertexPart.end()) << k;
  }
  // --separate-parts: the bird's three closed parts as they are.
  medial::SketchParameters separate;
  separate.mergeParts = false;
  const auto r = medial::sketchSkeleton(loadSketch("bird.txt"), separate);
  ASSERT_TRUE(r.ok()) << r.error;
  const auto t = medial::computeMeshTopology(r.mesh.vertices.rows(), faceLists(r.mesh));
  EXPECT_EQ(t.borderEdges, 0);
  EXPECT_EQ(t.components, 3);
  EXPECT_EQ(t.eulerCharacteristic, 6);  // three spheres
}

TEST(SketchInflation, StripCrossSectionIsRoundWithThicknessTwo) {
  // A long 1000 x 100 strip: in its middle the height is the half-width (50) for c = 2.
  const Polygon2 strip{{0, 0}, {1000, 0}, {1000, 100}, {0, 100}};
  medial::TriangleMesh mesh;
  std::string error;
  ASSERT_TRUE(medial::inflatePolygon(strip, {2.0, 8.0}, mesh, error)) << error;
  double top = 0;
  for (int v = 0; v < mesh.vertices.rows(); ++v)
    if (std::abs(mesh.vertices(v, 0) - 500) < 100) top = std::max(top, mesh.vertices(v, 2));
  EXPECT_NEAR(top, 50, 3);
}

TEST(BoundedDP, StraightBranchKeepsOnlyItsEnds) {
  const Polygon2 strip{{-10, -20}, {210, -20}, {210, 20}, {-10, 20}};
  const std::vector<Eigen::Vector2d> branch{{0, 0}, {50, 0.5}, {100, -0.5}, {150, 0.3}, {200, 0}};
  const auto r = medial::boundedDP(branch, strip, {});
  EXPECT_EQ(r.points.size(), 2u);
  EXPECT_TRUE(r.inside);
}

TEST(BoundedDP, BentBranchStaysInsideItsRegion) {
  // An L-shaped corridor 20 wide: the simplified axis must keep the corner to stay inside.
  const Polygon2 corridor{{-10, -10}, {210, -10}, {210, 200}, {190, 200}, {190, 10}, {-10, 10}};
  std::vector<Eigen::Vector2d> branch;
  for (int x = 0; x <= 200; x += 20) branch.emplace_back(x, 0);
  for (int y = 20; y <= 190; y += 20) branch.emplace_back(200, y);
  medial::BoundedDPParameters p;
  p.threshold = 500;  // far too coarse: Algorithm 2 must lower it
  const auto r = medial::boundedDP(branch, corridor, p);
  EXPECT_GE(r.points.size(), 3u);
  EXPECT_TRUE(r.inside);
  EXPECT_LT(r.threshold, 500);
}

// The fast path (CGAL in double arithmetic, checked) must give the skeleton of the exact predicates.
TEST(StraightSkeletonGraph, DoubleArithmeticMatchesExactPredicates) {
  for (const char* name : {"rectangle.txt", "star.txt", "hand.txt", "bird.txt", "unsteady.txt"}) {
    for (const auto& part : loadSketch(name)) {
      Eigen::AlignedBox2d box;
      for (const auto& q : part.stroke) box.extend(q);
      const double unit = box.diagonal().norm() / 1000;
      const auto stroke = medial::prepareStroke(part.stroke, {10 * unit, 2 * unit});
      ASSERT_TRUE(stroke.ok()) << name;
      medial::SkeletonGraph2 fast, exact;
      std::string error;
      ASSERT_TRUE(medial::straightSkeletonGraph(stroke.polygon, 0.5, fast, error)) << name << ": " << error;
      ASSERT_TRUE(medial::straightSkeletonGraph(stroke.polygon, 0.5, exact, error,
                                                medial::SkeletonArithmetic::exactPredicates))
          << name;
      ASSERT_EQ(fast.nodeCount(), exact.nodeCount()) << name;
      EXPECT_EQ(fast.edges, exact.edges) << name;
      for (int v = 0; v < fast.nodeCount(); ++v)
        EXPECT_LT((fast.nodes[v] - exact.nodes[v]).norm(), 1e-6 * unit) << name;
    }
  }
}

TEST(StraightSkeletonGraph, NearlyDegenerateOutlineGivesATreeInside) {
  // A comb: parallel teeth of equal width (many simultaneous events) whose sides carry points off the line
  // by 1e-13 (nearly collinear triples).
  Polygon2 comb{{0, 0}, {100, 0}};
  for (int tooth = 4; tooth >= 0; --tooth) {
    const double x = 20 * tooth;
    comb.insert(comb.end(), {{x + 15, 30},
                             {x + 15, 60},
                             {x + 15 + 1e-13, 90},
                             {x + 15, 120},
                             {x + 5, 120},
                             {x + 5, 90},
                             {x + 5 - 1e-13, 60},
                             {x + 5, 30}});
  }
  comb.emplace_back(0, 30);
  for (auto arithmetic :
       {medial::SkeletonArithmetic::automatic, medial::SkeletonArithmetic::exactPredicates}) {
    medial::SkeletonGraph2 graph;
    std::string error;
    ASSERT_TRUE(medial::straightSkeletonGraph(comb, 0.5, graph, error, arithmetic)) << error;
    EXPECT_EQ(int(graph.edges.size()), graph.nodeCount() - 1);
    for (const auto& node : graph.nodes) EXPECT_TRUE(medial::isInside(comb, node)) << node.transpose();
  }
}

// Bad input: a clear error naming the stroke, never a crash.
SketchPart partOf(const Polygon2& stroke) {
  SketchPart part;
  part.stroke = stroke;
  return part;
}

medial::SketchResult runOne(const Polygon2& stroke) { return medial::sketchSkeleton({partOf(stroke)}); }

TEST(SketchSkeleton, FewerThanThreePointsIsAnError) {
  const auto r = runOne({{0, 0}, {10, 0}});
  EXPECT_NE(r.error.message().find("stroke 1"), std::string::npos) << r.error;
  EXPECT_NE(r.error.message().find("at least 3"), std::string::npos) << r.error;
  EXPECT_FALSE(runOne({}).ok());
}

TEST(SketchSkeleton, ZeroAreaStrokeIsAnError) {
  const auto r = runOne({{0, 0}, {10, 0}, {20, 0}, {5, 0}});
  EXPECT_NE(r.error.message().find("no area"), std::string::npos) << r.error;
}

TEST(SketchSkeleton, SelfIntersectingStrokeIsAnError) {
  const auto r = runOne({{0, 0}, {100, 100}, {100, 0}, {0, 60}});  // an uneven bow tie
  EXPECT_NE(r.error.message().find("crosses itself"), std::string::npos) << r.error;
}

TEST(SketchSkeleton, NanIsAnError) {
  const auto r = runOne({{0, 0}, {100, 0}, {std::nan(""), 50}, {0, 100}});
  EXPECT_NE(r.error.message().find("non-finite"), std::string::npos) << r.error;
}

TEST(SketchSkeleton, RepeatedConsecutivePointsAreDropped) {
  const Polygon2 clean{{0, 0}, {400, 0}, {400, 100}, {0, 100}};
  const Polygon2 repeated{{0, 0}, {0, 0}, {400, 0}, {400, 0}, {400, 0}, {400, 100}, {0, 100}, {0, 0}};
  const auto a = runOne(clean), b = runOne(repeated);
  ASSERT_TRUE(a.ok() && b.ok()) << a.error << b.error;
  EXPECT_EQ(a.graph.skeleton.nodeCount(), b.graph.skeleton.nodeCount());
  EXPECT_FALSE(runOne({{0, 0}, {0, 0}, {5, 5}, {5, 5}}).ok());  // two distinct points only
}

TEST(SketchSkeleton, DegeneratePlacementIsAnError) {
  SketchPart part = partOf({{0, 0}, {100, 0}, {100, 50}, {0, 50}});
  part.placement.setZero();
  const auto r = medial::sketchSkeleton({part});
  EXPECT_NE(r.error.message().find("placement"), std::string::npos) << r.error;
}

TEST(SketchSkeleton, AbortStopsWithAnError) {
  const auto r = medial::sketchSkeleton(loadSketch("bird.txt"), {}, [](double) { return false; });
  EXPECT_TRUE(r.error.isCancelled());
}

}  // namespace
