// ConnectivitySurgery (contraction paper §III.B) and NodeRadii on a capped cylinder contracted by hand onto
// its axis: the answer is a path along the axis whose nodes sit at the cylinder's radius from the surface.
#include "contraction/ConnectivitySurgery.h"
#include "contraction/NodeRadii.h"
#include "mesh/InsideTest.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

constexpr int kRings = 12, kAround = 8;

// A closed cylinder of radius 1 along z (rings at z = 0..11), capped by a centre vertex at each end.
medial::TriangleMesh cappedCylinder() {
  medial::TriangleMesh m;
  m.vertices.resize(kRings * kAround + 2, 3);
  for (int r = 0; r < kRings; ++r)
    for (int a = 0; a < kAround; ++a) {
      const double angle = 2 * M_PI * a / kAround;
      m.vertices.row(r * kAround + a) << std::cos(angle), std::sin(angle), r;
    }
  const int bottom = kRings * kAround, top = bottom + 1;
  m.vertices.row(bottom) << 0, 0, 0;
  m.vertices.row(top) << 0, 0, kRings - 1;
  std::vector<std::array<int, 3>> faces;
  for (int r = 0; r + 1 < kRings; ++r)
    for (int a = 0; a < kAround; ++a) {
      const int v = r * kAround + a, w = r * kAround + (a + 1) % kAround;
      faces.push_back({v, w, w + kAround});
      faces.push_back({v, w + kAround, v + kAround});
    }
  for (int a = 0; a < kAround; ++a) {
    faces.push_back({bottom, (a + 1) % kAround, a});
    faces.push_back({top, (kRings - 1) * kAround + a, (kRings - 1) * kAround + (a + 1) % kAround});
  }
  m.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
    m.faces.row(Eigen::Index(f)) << faces[f][0], faces[f][1], faces[f][2];
  return m;
}

// What a contraction leaves: every ring shrunk to a hundredth of its radius around the axis.
medial::Vertices contracted(const medial::TriangleMesh& m) {
  medial::Vertices v = m.vertices;
  v.col(0) *= 0.01;
  v.col(1) *= 0.01;
  return v;
}

}  // namespace

TEST(ConnectivitySurgery, ContractedCylinderCollapsesToAPathAlongItsAxis) {
  const medial::TriangleMesh mesh = cappedCylinder();
  const medial::CurveSkeleton s = medial::collapseToCurveSkeleton(contracted(mesh), mesh.faces);
  ASSERT_GE(s.nodes.rows(), 2);
  EXPECT_EQ(s.remainingFaces, 0);
  // A path: edges = nodes - 1, every node on the axis, between the caps.
  EXPECT_EQ(int(s.edges.size()), int(s.nodes.rows()) - 1);
  for (Eigen::Index n = 0; n < s.nodes.rows(); ++n) {
    EXPECT_LT(std::hypot(s.nodes(n, 0), s.nodes(n, 1)), 0.02) << n;
    EXPECT_GE(s.nodes(n, 2), -1e-9);
    EXPECT_LE(s.nodes(n, 2), kRings - 1 + 1e-9);
  }
  // Every vertex was absorbed by a node.
  ASSERT_EQ(s.vertexToNode.size(), size_t(mesh.vertices.rows()));
  for (int node : s.vertexToNode) EXPECT_TRUE(node >= 0 && node < s.nodes.rows());
}

TEST(NodeRadii, NodesInsideTheCylinderGetItsRadius) {
  const medial::TriangleMesh mesh = cappedCylinder();
  const medial::CurveSkeleton s = medial::collapseToCurveSkeleton(contracted(mesh), mesh.faces);
  const medial::InsideTest surface(mesh);
  const std::vector<double> radii = medial::nodeRadii(s, mesh.vertices, surface);
  ASSERT_EQ(radii.size(), size_t(s.nodes.rows()));
  int middle = 0;
  for (Eigen::Index n = 0; n < s.nodes.rows(); ++n) {
    EXPECT_GT(radii[size_t(n)], 0) << n;
    if (s.nodes(n, 2) < 2 || s.nodes(n, 2) > kRings - 3) continue;  // the caps pull the end nodes' medians
    EXPECT_NEAR(radii[size_t(n)], 1.0, 0.1) << "node " << n << " at z = " << s.nodes(n, 2);
    ++middle;
  }
  EXPECT_GT(middle, 0);
}
