// intersectingFaces against CGAL's self_intersections (selfIntersectingFaces) on closed quad meshes with
// folds, overlaps, coplanar neighbours and untouched parts: the same pairs, and with a limit the first
// pairs of its fixed order, marked incomplete, the same every run.
#include "mesh/FaceIntersections.h"
#include "mesh/SelfIntersections.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace {

struct QuadMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;
};

// A torus of rows x columns quads (closed, manifold) centred at `centre`, its vertices moved by up to
// `noise` of the tube's radius in random directions: large noise folds it and makes it cut itself.
void addTorus(QuadMesh& mesh, const Eigen::Vector3d& centre, int rows, int columns, double noise,
              unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  const double pi = std::acos(-1.0), major = 1.0, minor = 0.35;
  const int first = int(mesh.vertices.size());
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < columns; ++j) {
      const double u = 2 * pi * i / rows, v = 2 * pi * j / columns;
      const Eigen::Vector3d p((major + minor * std::cos(v)) * std::cos(u),
                              (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v));
      mesh.vertices.push_back(centre + p +
                              noise * minor * Eigen::Vector3d(unit(random), unit(random), unit(random)));
    }
  const auto at = [&](int i, int j) { return first + (i % rows) * columns + (j % columns); };
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < columns; ++j)
      mesh.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
}

std::vector<std::pair<int, int>> cgalPairs(const QuadMesh& mesh) {
  return medial::selfIntersectingFaces(mesh.vertices, mesh.faces);
}

}  // namespace

TEST(FaceIntersections, SmoothTorusHasNone) {
  QuadMesh mesh;
  addTorus(mesh, {0, 0, 0}, 48, 16, 0.0, 1);
  const medial::FaceIntersections found = medial::intersectingFaces(mesh.vertices, mesh.faces);
  EXPECT_TRUE(found.facePairs.empty());
  EXPECT_TRUE(found.complete);
  EXPECT_TRUE(cgalPairs(mesh).empty());
}

// Noisy tori (folds between neighbours) and two tori through each other (overlaps between distant faces).
TEST(FaceIntersections, SamePairsAsCgalOnFoldedAndOverlappingMeshes) {
  for (const double noise : {0.3, 0.8, 1.5}) {
    QuadMesh mesh;
    addTorus(mesh, {0, 0, 0}, 40, 12, noise, 7);
    addTorus(mesh, {0.9, 0.2, 0.1}, 40, 12, noise / 3, 8);
    const auto expected = cgalPairs(mesh);
    ASSERT_FALSE(expected.empty()) << "noise " << noise;
    const medial::FaceIntersections found = medial::intersectingFaces(mesh.vertices, mesh.faces);
    EXPECT_EQ(found.facePairs, expected) << "noise " << noise;
    EXPECT_TRUE(found.complete);
  }
}

// Two quads sharing an edge and folded flat onto each other cut each other; laid out flat they do not.
TEST(FaceIntersections, CoplanarNeighboursCutOnlyWhenFolded) {
  QuadMesh flat{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}},
                {{0, 1, 2, 3}, {1, 4, 5, 2}}};
  EXPECT_TRUE(medial::intersectingFaces(flat.vertices, flat.faces).facePairs.empty());
  QuadMesh folded = flat;
  folded.vertices[4] = {0.5, 0, 0};
  folded.vertices[5] = {0.5, 1, 0};
  EXPECT_EQ(medial::intersectingFaces(folded.vertices, folded.faces).facePairs,
            (std::vector<std::pair<int, int>>{{0, 1}}));
}

TEST(FaceIntersections, LimitKeepsSomeOfThePairsAndSaysSo) {
  QuadMesh mesh;
  addTorus(mesh, {0, 0, 0}, 40, 12, 1.5, 3);
  const medial::FaceIntersections all = medial::intersectingFaces(mesh.vertices, mesh.faces);
  ASSERT_GT(all.facePairs.size(), 20u);
  const medial::FaceIntersections first = medial::intersectingFaces(mesh.vertices, mesh.faces, 10);
  EXPECT_FALSE(first.complete);
  ASSERT_EQ(first.facePairs.size(), 10u);
  EXPECT_TRUE(std::is_sorted(first.facePairs.begin(), first.facePairs.end()));
  EXPECT_TRUE(std::includes(all.facePairs.begin(), all.facePairs.end(), first.facePairs.begin(),
                            first.facePairs.end()));
  EXPECT_EQ(medial::intersectingFaces(mesh.vertices, mesh.faces, 10).facePairs, first.facePairs)
      << "the same again";
  EXPECT_TRUE(medial::intersectingFaces(mesh.vertices, mesh.faces, all.facePairs.size()).complete);
}

// A triangle twice, the second turned round (a pillow the union's cleanup once left): CGAL counts it, so do
// we.
TEST(FaceIntersections, ATriangleTwiceCutsItself) {
  const std::vector<Eigen::Vector3d> vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::vector<int>> faces{{0, 1, 2}, {2, 1, 0}};
  EXPECT_EQ(medial::intersectingFaces(vertices, faces).facePairs, (std::vector<std::pair<int, int>>{{0, 1}}));
  EXPECT_EQ(medial::selfIntersectingFaces(vertices, faces), (std::vector<std::pair<int, int>>{{0, 1}}));
}
