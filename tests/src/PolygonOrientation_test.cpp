// PolygonOrientation and SelfIntersections: the mesh checks SQM relies on, on meshes whose answer is known.
#include "mesh/PolygonOrientation.h"
#include "mesh/SelfIntersections.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace {

std::vector<Eigen::Vector3d> cubeVertices(const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < 8; ++i) v.push_back(offset + Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  return v;
}

// Outward quads of the unit cube (vertex i at (i&1, i>>1&1, i>>2&1)).
std::vector<std::vector<int>> cubeFaces() {
  return {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
}

double signedVolume(const std::vector<Eigen::Vector3d>& v, const std::vector<std::vector<int>>& faces) {
  double volume = 0;
  for (const auto& f : faces)
    for (size_t k = 1; k + 1 < f.size(); ++k)
      volume += v[size_t(f[0])].dot(v[size_t(f[k])].cross(v[size_t(f[k + 1])])) / 6;
  return volume;
}

}  // namespace

TEST(PolygonOrientation, OutwardCubeIsLeftAsItIs) {
  auto faces = cubeFaces();
  EXPECT_EQ(medial::orientPolygonsOutward(cubeVertices(), faces), 0);
  EXPECT_EQ(faces, cubeFaces());
}

TEST(PolygonOrientation, FlippedFacesAndAnInsideOutCubeTurnOutward) {
  const auto v = cubeVertices();
  auto faces = cubeFaces();
  std::reverse(faces[1].begin(), faces[1].end());
  std::reverse(faces[4].begin(), faces[4].end());
  EXPECT_EQ(medial::orientPolygonsOutward(v, faces), 2);
  EXPECT_NEAR(signedVolume(v, faces), 1.0, 1e-12);
  for (auto& f : faces) std::reverse(f.begin(), f.end());  // all inward
  EXPECT_EQ(medial::orientPolygonsOutward(v, faces), 6);
  EXPECT_NEAR(signedVolume(v, faces), 1.0, 1e-12);
}

TEST(PolygonOrientation, NonManifoldMeshIsRefusedAndLeftAlone) {
  // Three quads on one edge (0-1): no consistent orientation without duplicating vertices.
  std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},  {1, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {0, -1, 0}, {1, -1, 0}};
  std::vector<std::vector<int>> faces = {{0, 1, 3, 2}, {0, 1, 5, 4}, {0, 1, 7, 6}};
  const auto before = faces;
  EXPECT_EQ(medial::orientPolygonsOutward(v, faces), -1);
  EXPECT_EQ(faces, before);
}

TEST(SelfIntersections, SeparateCubesDoNotIntersectOverlappingOnesDo) {
  auto v = cubeVertices();
  const auto second = cubeVertices(Eigen::Vector3d(2, 0, 0));
  v.insert(v.end(), second.begin(), second.end());
  auto faces = cubeFaces();
  for (auto f : cubeFaces()) {
    for (int& i : f) i += 8;
    faces.push_back(f);
  }
  EXPECT_TRUE(medial::selfIntersectingFaces(v, faces).empty());
  // Move the second cube half into the first: its faces cut the first's.
  for (size_t i = 8; i < v.size(); ++i) v[i].x() -= 1.5;
  const auto pairs = medial::selfIntersectingFaces(v, faces);
  EXPECT_FALSE(pairs.empty());
  for (const auto& [a, b] : pairs) {
    EXPECT_LT(a, b);
    EXPECT_TRUE(a < 6 && b >= 6) << "only faces of different cubes cut each other: " << a << " " << b;
  }
  // The same answer for 64-bit indices (meshes from VTK).
  std::vector<std::vector<int64_t>> wide;
  for (const auto& f : faces) wide.emplace_back(f.begin(), f.end());
  EXPECT_EQ(medial::selfIntersectingFaces(v, wide), pairs);
}
