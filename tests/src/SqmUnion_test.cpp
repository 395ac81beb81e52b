// unionSqmMesh on meshes whose answer is known exactly: two overlapping boxes (the union's volume and
// its quads away from the cut), and the inputs it must refuse with a clear error and leave unchanged
// (boxes touching along an edge, whose union is not a manifold; open sheets crossing, which bound nothing).
#include "mesh/MeshGeometry.h"
#include "mesh/MeshTopology.h"
#include "mesh/SelfIntersections.h"
#include "sqm/SqmUnion.h"

#include <gtest/gtest.h>

#include <array>

namespace {

// An axis-aligned box of six outward quads, appended to `mesh`; its vertices belong to `node`.
void addBox(medial::SqmMesh& mesh, const Eigen::Vector3d& low, const Eigen::Vector3d& high, int node) {
  const int first = int(mesh.vertices.size());
  for (int k = 0; k < 8; ++k)
    mesh.vertices.emplace_back(k & 1 ? high.x() : low.x(), k & 2 ? high.y() : low.y(),
                               k & 4 ? high.z() : low.z());
  mesh.vertexNode.insert(mesh.vertexNode.end(), 8, node);
  const std::array<std::array<int, 4>, 6> quads = {
      {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
  for (const auto& q : quads) mesh.faces.push_back({first + q[0], first + q[1], first + q[2], first + q[3]});
}

medial::MeshTopology topologyOf(const medial::SqmMesh& mesh) {
  std::vector<std::vector<int64_t>> faces;
  for (const auto& f : mesh.faces) faces.emplace_back(f.begin(), f.end());
  return medial::computeMeshTopology(int64_t(mesh.vertices.size()), faces);
}

double volumeOf(const medial::SqmMesh& mesh) {
  medial::Vertices vertices(Eigen::Index(mesh.vertices.size()), 3);
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    vertices.row(Eigen::Index(v)) = mesh.vertices[v].transpose();
  std::vector<std::array<int, 3>> triangles;
  for (const auto& f : mesh.faces)
    for (size_t k = 1; k + 1 < f.size(); ++k) triangles.push_back({f[0], f[k], f[k + 1]});
  medial::Faces faces(Eigen::Index(triangles.size()), 3);
  for (size_t t = 0; t < triangles.size(); ++t)
    faces.row(Eigen::Index(t)) << triangles[t][0], triangles[t][1], triangles[t][2];
  return medial::enclosedVolume(vertices, faces);
}

}  // namespace

// Two unit cubes overlapping in a cube of side 0.5: the union encloses 1 + 1 - 0.125 exactly, is one closed
// manifold without self-intersection, and the faces no curve crosses stay whole quads.
TEST(SqmUnionAlgorithm, OverlappingBoxesBecomeTheirUnion) {
  medial::SqmMesh mesh;
  addBox(mesh, {0, 0, 0}, {1, 1, 1}, 0);
  addBox(mesh, {0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}, 1);
  const medial::SqmUnionResult result = medial::unionSqmMesh(mesh);
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_GT(result.before.facePairs, 0);
  EXPECT_EQ(result.before.nodePairs, 1);
  const medial::MeshTopology topology = topologyOf(mesh);
  EXPECT_TRUE(topology.isClosedManifold());
  EXPECT_EQ(topology.components, 1);
  EXPECT_EQ(topology.genus, 0);
  EXPECT_NEAR(volumeOf(mesh), 1.875, 1e-9);
  EXPECT_TRUE(medial::selfIntersectingFaces(mesh.vertices, mesh.faces).empty());
  EXPECT_EQ(result.intersectingAfter, 0);
  // Each cube keeps its three faces away from the other whole: 6 quads.
  EXPECT_EQ(mesh.quadCount(), 6);
  ASSERT_EQ(mesh.vertexNode.size(), mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3d& p = mesh.vertices[v];
    if ((p.array() < 0.5).any()) {
      EXPECT_EQ(mesh.vertexNode[v], 0) << "vertex " << v;  // only cube 0 there
    }
    if ((p.array() > 1.0).any()) {
      EXPECT_EQ(mesh.vertexNode[v], 1) << "vertex " << v;
    }
  }
}

// Boxes that only touch along an edge have a non-manifold union: a clear error, the mesh as it was.
TEST(SqmUnionAlgorithm, BoxesTouchingAlongAnEdgeAreRefused) {
  medial::SqmMesh mesh;
  addBox(mesh, {0, 0, 0}, {1, 1, 1}, 0);
  addBox(mesh, {1, 1, 0}, {2, 2, 1}, 1);
  const medial::SqmMesh before = mesh;
  const medial::SqmUnionResult result = medial::unionSqmMesh(mesh);
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error.find("manifold"), std::string::npos) << result.error;
  EXPECT_EQ(mesh.vertices, before.vertices);
  EXPECT_EQ(mesh.faces, before.faces);
}

// Two open squares crossing each other bound no volume: refused, unchanged.
TEST(SqmUnionAlgorithm, OpenSheetsAreRefused) {
  medial::SqmMesh mesh;
  mesh.vertices = {{0, 0, 0},        {1, 0, 0},       {1, 1, 0},        {0, 1, 0},
                   {0.5, 0.5, -0.5}, {0.5, 0.5, 0.5}, {0.5, -0.5, 0.5}, {0.5, -0.5, -0.5}};
  mesh.faces = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  mesh.vertexNode = {0, 0, 0, 0, 1, 1, 1, 1};
  const medial::SqmMesh before = mesh;
  const medial::SqmUnionResult result = medial::unionSqmMesh(mesh);
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error.find("open edges"), std::string::npos) << result.error;
  EXPECT_EQ(mesh.faces, before.faces);
}
