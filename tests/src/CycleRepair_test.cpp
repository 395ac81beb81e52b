// CycleRepair and the pieces it stands on: linking numbers, the homology basis of a closed mesh.
#include "ContractionTestMeshes.h"
#include "contraction/CycleRepair.h"
#include "mesh/HomologyLoops.h"
#include "mesh/InsideTest.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <set>

using medial::testing::appendMesh;
using medial::testing::torusMesh;
using medial::testing::tubeMesh;

namespace {

using Polygon = std::vector<Eigen::Vector3d>;

Polygon circle(const Eigen::Vector3d& centre, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
               int points = 64) {
  Polygon p;
  for (int k = 0; k < points; ++k) {
    const double t = 2 * M_PI * k / points;
    p.push_back(centre + std::cos(t) * u + std::sin(t) * v);
  }
  return p;
}

// A closed curve through the torus's hole along the z axis, closed far away.
const Polygon kAxis = {{0, 0, -10}, {0, 0, 10}, {100, 0, 10}, {100, 0, -10}};

int cycleCount(const medial::CurveSkeleton& s) {
  std::vector<int> parent(size_t(s.nodes.rows()));
  for (size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
  std::function<int(int)> find = [&](int x) {
    return parent[size_t(x)] == x ? x : parent[size_t(x)] = find(parent[size_t(x)]);
  };
  int components = int(parent.size());
  for (const auto& [a, b] : s.edges)
    if (find(a) != find(b)) {
      parent[size_t(find(a))] = find(b);
      --components;
    }
  return int(s.edges.size()) - int(s.nodes.rows()) + components;
}

// The skeleton of a torus (R 2) without its cycle: 5 nodes on the upper half of the core circle.
medial::CurveSkeleton halfCircle(const Eigen::Vector3d& shift = Eigen::Vector3d::Zero()) {
  medial::CurveSkeleton s;
  s.nodes.resize(5, 3);
  for (int k = 0; k < 5; ++k) {
    s.nodes.row(k) =
        (Eigen::Vector3d(2 * std::cos(M_PI * k / 4), 2 * std::sin(M_PI * k / 4), 0) + shift).transpose();
    if (k > 0) s.edges.emplace_back(k - 1, k);
  }
  return s;
}

}  // namespace

// Gauss's linking integral from the exact solid angle of each pair of segments (Klenin & Langowski 2000):
// the reference that medial::linkingNumber's crossing count must agree with.
double gaussLinkingIntegral(const Polygon& a, const Polygon& b) {
  double total = 0;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j) {
      const Eigen::Vector3d &p1 = a[i], &p2 = a[(i + 1) % a.size()], &p3 = b[j], &p4 = b[(j + 1) % b.size()];
      const Eigen::Vector3d r13 = p3 - p1, r14 = p4 - p1, r23 = p3 - p2, r24 = p4 - p2;
      Eigen::Vector3d n[4] = {r13.cross(r14), r14.cross(r24), r24.cross(r23), r23.cross(r13)};
      bool degenerate = false;
      for (auto& v : n) degenerate = degenerate || v.norm() == 0 || (v.normalize(), false);
      if (degenerate) continue;
      double omega = 0;
      for (int k = 0; k < 4; ++k) omega += std::asin(std::clamp(n[k].dot(n[(k + 1) % 4]), -1.0, 1.0));
      const double sign = (p4 - p3).cross(p2 - p1).dot(r13);
      total += sign > 0 ? omega : sign < 0 ? -omega : 0.0;
    }
  return total / (4 * M_PI);
}

// A closed random walk: `steps` points around `centre`, closed by its last step.
Polygon randomLoop(std::mt19937& random, const Eigen::Vector3d& centre, int steps) {
  std::normal_distribution<double> step(0.0, 1.0);
  Polygon p{centre};
  for (int k = 1; k < steps; ++k)
    p.push_back(p.back() + Eigen::Vector3d(step(random), step(random), step(random)));
  return p;
}

TEST(LinkingNumber, CrossingsAgreeWithGaussIntegralOnTangledRandomLoops) {
  std::mt19937 random(7);
  int linked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Polygon a = randomLoop(random, {0, 0, 0}, 40), b = randomLoop(random, {1, 0, 0}, 40);
    const double gauss = gaussLinkingIntegral(a, b);
    if (std::abs(gauss - std::round(gauss)) > 0.01) continue;  // the walks touch: not a link
    EXPECT_EQ(medial::linkingNumber(a, b), std::round(gauss)) << "trial " << trial;
    EXPECT_EQ(medial::linkingNumber(b, a), std::round(gauss)) << "trial " << trial;
    linked += std::round(gauss) != 0;
  }
  EXPECT_GT(linked, 30) << "the walks tangle often enough for the test to mean something";
}

TEST(LinkingNumber, HopfLinkIsOneUnlinkedIsZero) {
  const Polygon a = circle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const Polygon hopf = circle({1, 0, 0}, {1, 0, 0}, {0, 0, 1});  // through a's disc once
  EXPECT_NEAR(std::abs(medial::linkingNumber(a, hopf)), 1.0, 1e-6);
  EXPECT_NEAR(medial::linkingNumber(a, hopf), medial::linkingNumber(hopf, a), 1e-6);
  const Polygon apart = circle({5, 0, 0}, {1, 0, 0}, {0, 0, 1});
  EXPECT_NEAR(medial::linkingNumber(a, apart), 0.0, 1e-6);
  const Polygon coaxial = circle({0, 0, 0.1}, {2, 0, 0}, {0, 2, 0});  // a larger circle above: unlinked
  EXPECT_NEAR(medial::linkingNumber(a, coaxial), 0.0, 1e-6);
  // The torus's core circle goes once around the axis through its hole.
  EXPECT_NEAR(std::abs(medial::linkingNumber(circle({0, 0, 0}, {2, 0, 0}, {0, 2, 0}), kAxis)), 1.0, 1e-6);
}

TEST(HomologyLoops, TwoLoopsPerHandleOfEachClosedComponent) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  const auto loops = medial::homologyBasisLoops(torus);
  ASSERT_EQ(loops.size(), 2u);
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < torus.faces.rows(); ++f)
    for (int c = 0; c < 3; ++c) edges.insert(std::minmax(torus.faces(f, c), torus.faces(f, (c + 1) % 3)));
  for (const auto& loop : loops) {
    EXPECT_GE(loop.size(), 3u);
    for (size_t i = 0; i < loop.size(); ++i)  // a closed path of mesh edges
      EXPECT_TRUE(edges.count(std::minmax(loop[i], loop[(i + 1) % loop.size()])));
  }
  EXPECT_EQ(medial::closedGenus(torus), 1);
  EXPECT_TRUE(medial::homologyBasisLoops(tubeMesh(4, 0.5)).empty());  // a sphere
  EXPECT_EQ(medial::closedGenus(tubeMesh(4, 0.5)), 0);
  const medial::TriangleMesh twoTori = appendMesh(torus, torus, {10, 0, 0});
  EXPECT_EQ(medial::homologyBasisLoops(twoTori).size(), 4u);
  EXPECT_EQ(medial::closedGenus(twoTori), 2);
  EXPECT_EQ(medial::closedGenus(appendMesh(twoTori, tubeMesh(4, 0.5), {0, 10, 0})), 2);
  medial::TriangleMesh open = torus;  // a border: left out
  open.faces.conservativeResize(open.faces.rows() - 1, 3);
  EXPECT_TRUE(medial::homologyBasisLoops(open).empty());
  EXPECT_EQ(medial::closedGenus(open), 0);
}

TEST(CycleRepair, PutsTheLostCycleOfATorusBackAroundItsHole) {
  const medial::TriangleMesh torus = torusMesh(2, 0.5);
  const medial::InsideTest inside(torus);
  medial::CurveSkeleton s = halfCircle();
  const medial::CycleRepairResult r = medial::restoreMissingCycles(s, torus, inside);
  EXPECT_EQ(r.genus, 1);
  EXPECT_EQ(r.cyclesBefore, 0);
  EXPECT_EQ(r.cyclesAdded, 1);
  EXPECT_EQ(cycleCount(s), 1);
  ASSERT_GT(s.nodes.rows(), 5);
  Polygon added;
  for (Eigen::Index k = 5; k < s.nodes.rows(); ++k) {
    added.push_back(s.nodes.row(k).transpose());
    EXPECT_TRUE(inside.contains(added.back()));
  }
  // The new cycle goes around the hole (the tunnel's class), not around the tube (a meridian).
  EXPECT_NEAR(std::abs(medial::linkingNumber(added, kAxis)), 1.0, 1e-6);
  // Tied to the old skeleton: one component.
  EXPECT_EQ(int(s.edges.size()), 4 + int(added.size()) + 1);
}

TEST(CycleRepair, LeavesAKeptCycleAndMendsOnlyTheTorusThatLostIt) {
  // Two tori 10 apart: the first keeps its core circle as a skeleton cycle, the second lost its cycle.
  const medial::TriangleMesh tori = appendMesh(torusMesh(2, 0.5), torusMesh(2, 0.5), {10, 0, 0});
  const medial::InsideTest inside(tori);
  medial::CurveSkeleton s = halfCircle({10, 0, 0});
  const Polygon core = circle({0, 0, 0}, {2, 0, 0}, {0, 2, 0}, 12);
  const int first = int(s.nodes.rows());
  s.nodes.conservativeResize(first + 12, 3);
  for (int k = 0; k < 12; ++k) {
    s.nodes.row(first + k) = core[size_t(k)].transpose();
    s.edges.emplace_back(first + k, first + (k + 1) % 12);
  }
  const medial::CycleRepairResult r = medial::restoreMissingCycles(s, tori, inside);
  EXPECT_EQ(r.genus, 2);
  EXPECT_EQ(r.cyclesBefore, 1);
  EXPECT_EQ(r.cyclesAdded, 1);
  EXPECT_EQ(cycleCount(s), 2);
  for (Eigen::Index k = first + 12; k < s.nodes.rows(); ++k)
    EXPECT_GT(s.nodes(k, 0), 5);  // in the second torus

  medial::CurveSkeleton whole = halfCircle();  // a skeleton with all its cycles is left alone
  whole.edges.emplace_back(4, 0);
  const auto before = whole.nodes;
  EXPECT_EQ(medial::restoreMissingCycles(whole, torusMesh(2, 0.5), medial::InsideTest(torusMesh(2, 0.5)))
                .cyclesAdded,
            0);
  EXPECT_EQ(whole.nodes, before);
}

TEST(CycleRepair, GenusZeroAndOpenMeshesAreLeftAlone) {
  const medial::TriangleMesh tube = tubeMesh(4, 0.5);
  medial::CurveSkeleton s;
  s.nodes.resize(2, 3);
  s.nodes << -1, 0, 0, 1, 0, 0;
  s.edges = {{0, 1}};
  EXPECT_EQ(medial::restoreMissingCycles(s, tube, medial::InsideTest(tube)).cyclesAdded, 0);
  medial::TriangleMesh open = torusMesh(2, 0.5);
  open.faces.conservativeResize(open.faces.rows() - 1, 3);
  medial::CurveSkeleton half = halfCircle();
  EXPECT_EQ(medial::restoreMissingCycles(half, open, medial::InsideTest(open)).cyclesAdded, 0);
  EXPECT_EQ(half.nodes.rows(), 5);
}
