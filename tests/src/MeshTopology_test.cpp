#include "mesh/MeshTopology.h"

#include <gtest/gtest.h>

#include <cmath>

using Faces = std::vector<std::vector<int64_t>>;

namespace {

const Faces kTetrahedron = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

// A torus as a rings x sides grid of quads (closed, genus 1).
Faces torusQuads(int rings, int sides) {
  Faces faces;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j)
      faces.push_back({i * sides + j, ((i + 1) % rings) * sides + j,
                       ((i + 1) % rings) * sides + (j + 1) % sides, i * sides + (j + 1) % sides});
  return faces;
}

}  // namespace

TEST(MeshTopology, TetrahedronIsClosedGenusZero) {
  const auto t = medial::computeMeshTopology(4, kTetrahedron);
  EXPECT_EQ(t.faces, 4);
  EXPECT_EQ(t.edges, 6);
  EXPECT_EQ(t.eulerCharacteristic, 2);
  EXPECT_EQ(t.genus, 0);
  EXPECT_EQ(t.components, 1);
  EXPECT_TRUE(t.isClosedManifold());
}

TEST(MeshTopology, TorusHasGenusOne) {
  const auto t = medial::computeMeshTopology(8 * 5, torusQuads(8, 5));
  EXPECT_EQ(t.eulerCharacteristic, 0);
  EXPECT_EQ(t.genus, 1);
  EXPECT_TRUE(t.isClosedManifold());
}

TEST(MeshTopology, OpenMeshCountsBorderEdgesAndLoops) {
  Faces open = kTetrahedron;
  open.pop_back();  // a hole of three border edges
  const auto t = medial::computeMeshTopology(4, open);
  EXPECT_EQ(t.borderEdges, 3);
  EXPECT_EQ(t.boundaryLoops, 1);
  EXPECT_EQ(t.genus, 0);  // a disk
  EXPECT_FALSE(t.isClosed());
}

TEST(MeshTopology, NonManifoldEdgeIsCounted) {
  Faces fan = kTetrahedron;
  fan.push_back({0, 1, 4});  // a third face on edge 0-1
  const auto t = medial::computeMeshTopology(5, fan);
  EXPECT_EQ(t.nonManifoldEdges, 1);
  EXPECT_FALSE(t.isEdgeManifold());
}

TEST(MeshTopology, ComponentsAndUnusedVerticesAreCounted) {
  Faces two = kTetrahedron;
  for (const auto& f : kTetrahedron) two.push_back({f[0] + 4, f[1] + 4, f[2] + 4});
  const auto t = medial::computeMeshTopology(10, two);  // vertices 8 and 9 unused
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.unusedVertices, 2);
  EXPECT_EQ(t.eulerCharacteristic, 4);
  EXPECT_EQ(t.genus, 0);
}

TEST(MeshTopology, DegenerateFacesAreSetAside) {
  Faces faces = kTetrahedron;
  faces.push_back({0, 0, 1});
  const auto t = medial::computeMeshTopology(4, faces);
  EXPECT_EQ(t.degenerateFaces, 1);
  EXPECT_EQ(t.faces, 4);
  EXPECT_TRUE(t.isClosedManifold());
}

TEST(MeshTopology, EmptyMeshIsNotClosedManifold) {
  const auto t = medial::computeMeshTopology(0, {});
  EXPECT_EQ(t.components, 0);
  EXPECT_FALSE(t.isClosedManifold());
}
