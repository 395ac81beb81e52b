// SqmRefinement: the refined mesh keeps its skeleton inside and stays on the swept spheres (issue 27's
// invariants) on frames, ladders, a cube's edges and a zig-zag, whose corners Catmull-Clark used to pull
// inward.
#include "mesh/InsideTest.h"
#include "mesh/MeshTopology.h"
#include "mesh/SelfIntersections.h"
#include "sqm/SqmMesher.h"
#include "sqm/SweptSpheres.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

struct NamedSkeleton {
  std::string name;
  medial::Skeleton skeleton;
};

medial::Skeleton withRadius(std::vector<Eigen::Vector3d> nodes, std::vector<std::array<int, 2>> edges,
                            double radius) {
  medial::Skeleton s;
  s.nodes = std::move(nodes);
  s.edges = std::move(edges);
  s.radii.assign(s.nodes.size(), radius);
  return s;
}

// The test skeletons: no nodes between the corners, so each edge is one long quad strip.
std::vector<NamedSkeleton> cornerSkeletons() {
  std::vector<NamedSkeleton> all;
  const std::vector<Eigen::Vector3d> square = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
  const std::vector<std::array<int, 2>> frame = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  all.push_back({"square frame", withRadius(square, frame, 0.25)});
  auto tableNodes = square;
  auto tableEdges = frame;
  for (int corner = 0; corner < 4; ++corner) {
    tableNodes.push_back(square[size_t(corner)] + Eigen::Vector3d(0, 0, -4));
    tableEdges.push_back({corner, int(tableNodes.size()) - 1});
  }
  all.push_back({"frame with a leg", withRadius({square[0], square[1], square[2], square[3], {0, 0, -4}},
                                                {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}}, 0.25)});
  all.push_back({"table", withRadius(tableNodes, tableEdges, 0.25)});
  all.push_back({"ladder", withRadius({{0, 0, 0}, {4, 0, 0}, {8, 0, 0}, {0, 4, 0}, {4, 4, 0}, {8, 4, 0}},
                                      {{0, 1}, {1, 2}, {3, 4}, {4, 5}, {0, 3}, {1, 4}, {2, 5}}, 0.6)});
  std::vector<Eigen::Vector3d> cube;
  std::vector<std::array<int, 2>> cubeEdges;
  for (int k = 0; k < 8; ++k) cube.push_back(4 * Eigen::Vector3d(k & 1, (k >> 1) & 1, (k >> 2) & 1));
  for (int a = 0; a < 8; ++a)
    for (int bit : {1, 2, 4})
      if (!(a & bit)) cubeEdges.push_back({a, a | bit});
  all.push_back({"cube's edges", withRadius(cube, cubeEdges, 0.5)});
  // A zig-zag turning by 60, 90 and 120 degrees in its plane.
  std::vector<Eigen::Vector3d> zigzag = {{0, 0, 0}};
  double heading = 0;
  for (double turn : {0.0, 60.0, -90.0, 120.0, 0.0}) {
    heading += turn * M_PI / 180;
    zigzag.push_back(zigzag.back() + 3 * Eigen::Vector3d(std::cos(heading), std::sin(heading), 0));
  }
  std::vector<std::array<int, 2>> chain;
  for (int k = 0; k + 1 < int(zigzag.size()); ++k) chain.push_back({k, k + 1});
  all.push_back({"zig-zag", withRadius(zigzag, chain, 0.4)});
  return all;
}

medial::TriangleMesh triangles(const medial::SqmMesh& mesh) {
  medial::TriangleMesh t;
  t.vertices.resize(Eigen::Index(mesh.vertices.size()), 3);
  for (size_t v = 0; v < mesh.vertices.size(); ++v) t.vertices.row(Eigen::Index(v)) = mesh.vertices[v];
  std::vector<Eigen::Vector3i> fan;
  for (const auto& f : mesh.faces)
    for (size_t k = 1; k + 1 < f.size(); ++k) fan.emplace_back(f[0], f[k], f[k + 1]);
  t.faces.resize(Eigen::Index(fan.size()), 3);
  for (size_t k = 0; k < fan.size(); ++k) t.faces.row(Eigen::Index(k)) = fan[k];
  return t;
}

// Signed depth of a point under the surface (negative: outside).
double depth(const medial::InsideTest& inside, const Eigen::Vector3d& p) {
  const double d = std::sqrt(inside.squaredDistanceToSurface(p));
  return inside.contains(p) ? d : -d;
}

double percentile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return values[size_t(q * double(values.size() - 1))];
}

}  // namespace

TEST(SqmRefinement, CornersKeepTheirNodesInsideAndTheSurfaceOnTheSweptSpheres) {
  for (const auto& [name, s] : cornerSkeletons()) {
    const auto degree = medial::nodeDegrees(s);
    const medial::SweptSpheres swept(s);
    for (int levels = 1; levels <= 3; ++levels) {
      SCOPED_TRACE(name + ", " + std::to_string(levels) + " levels");
      medial::SqmParameters p;
      p.subdivisionLevels = levels;
      const auto result = medial::sqmMesh(s, p);
      ASSERT_TRUE(result.ok()) << result.error;
      const auto& mesh = result.mesh;
      std::vector<std::vector<int>> faces = mesh.faces;
      EXPECT_TRUE(medial::selfIntersectingFaces(mesh.vertices, faces).empty());
      std::vector<std::vector<int64_t>> wideFaces;
      for (const auto& f : faces) wideFaces.emplace_back(f.begin(), f.end());
      const auto topology = medial::computeMeshTopology(int64_t(mesh.vertices.size()), wideFaces);
      EXPECT_TRUE(topology.isClosedManifold());
      const medial::InsideTest inside(triangles(mesh));
      double worstNode = INFINITY, worstMiddle = INFINITY, worstLeafMiddle = INFINITY;
      for (int n = 0; n < s.nodeCount(); ++n)
        if (degree[size_t(n)] >= 2)
          worstNode = std::min(worstNode, depth(inside, s.nodes[size_t(n)]) / s.radii[size_t(n)]);
      for (const auto& [a, b] : s.edges) {
        const Eigen::Vector3d middle = 0.5 * (s.nodes[size_t(a)] + s.nodes[size_t(b)]);
        if (degree[size_t(a)] >= 2 && degree[size_t(b)] >= 2)
          worstMiddle =
              std::min(worstMiddle, depth(inside, middle) / std::min(s.radii[size_t(a)], s.radii[size_t(b)]));
        else
          worstLeafMiddle = std::min(worstLeafMiddle,
                                     depth(inside, middle) / s.radii[size_t(degree[size_t(a)] >= 2 ? a : b)]);
      }
      std::vector<double> off;  // |distance to the swept-sphere surface| / the vertex's node radius
      for (size_t v = 0; v < mesh.vertices.size(); ++v)
        off.push_back(std::abs(swept.signedDistance(mesh.vertices[v])) / s.radii[size_t(mesh.vertexNode[v])]);
      std::printf(
          "%s, K=%d: node margin %.2f r, edge middle %.2f r, leaf edge middle %.2f r, off the "
          "swept spheres median %.3f r, 95th percentile %.3f r\n",
          name.c_str(), levels, worstNode, worstMiddle, worstLeafMiddle, percentile(off, 0.5),
          percentile(off, 0.95));
      EXPECT_GE(worstNode, 0.5);
      EXPECT_GE(worstMiddle, 0.5);
      if (worstLeafMiddle < INFINITY) {
        EXPECT_GE(worstLeafMiddle, 0.3);
      }
      EXPECT_LE(percentile(off, 0.5), 0.05);
      EXPECT_LE(percentile(off, 0.95), 0.20);
    }
  }
}
