// Tests of TrianglePairing: fans and bands of triangles joined in pairs into quads.
#include "sqm/TrianglePairing.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

struct Fan {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;
  std::vector<size_t> strip;
};

// A closed double cone: a fan of n triangles (the strip) from a ring of radius 1 to an apex at `height`
// (vertex 0), listed from its `first`, then n more below to an apex at z = -1 (vertex n + 1).
Fan cone(int n, double height, int first = 0) {
  Fan fan;
  fan.vertices.push_back({0, 0, height});
  for (int i = 0; i < n; ++i)
    fan.vertices.push_back({std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0});
  fan.vertices.push_back({0, 0, -1});
  for (int k = 0; k < n; ++k) {
    const int i = (first + k) % n;
    fan.strip.push_back(fan.faces.size());
    fan.faces.push_back({1 + i, 1 + (i + 1) % n, 0});
  }
  for (int i = 0; i < n; ++i) fan.faces.push_back({1 + (i + 1) % n, 1 + i, n + 1});
  return fan;
}

int countOfSize(const std::vector<std::vector<int>>& faces, size_t size) {
  return int(std::count_if(faces.begin(), faces.end(), [&](const auto& f) { return f.size() == size; }));
}

TEST(TrianglePairing, AFanOfEightBecomesFourQuadsThatSplitBackIntoItsTriangles) {
  Fan fan = cone(8, 1.0);
  const auto triangles = fan.faces;
  EXPECT_EQ(medial::pairStripTriangles(fan.vertices, fan.faces, {fan.strip}), 4);
  ASSERT_EQ(fan.faces.size(), 4u + 8);
  EXPECT_EQ(countOfSize(fan.faces, 4), 4);
  for (size_t f = 0; f < 4; ++f) {
    const auto& q = fan.faces[f];
    // Split along 0-2: two of the fan's triangles, same orientation (as rotations of them).
    auto isTriangle = [&](std::vector<int> t) {
      for (int r = 0; r < 3; ++r) {
        if (std::find(triangles.begin(), triangles.end(), t) != triangles.end()) return true;
        std::rotate(t.begin(), t.begin() + 1, t.end());
      }
      return false;
    };
    EXPECT_TRUE(isTriangle({q[0], q[1], q[2]}));
    EXPECT_TRUE(isTriangle({q[0], q[2], q[3]}));
  }
}

TEST(TrianglePairing, OddFansKeepOneTriangleAndNoVertexKeepsFewerThanThreeFaces) {
  Fan odd = cone(9, 1.0, 4);  // listed from the middle: the order must not matter
  EXPECT_EQ(medial::pairStripTriangles(odd.vertices, odd.faces, {odd.strip}), 4);
  EXPECT_EQ(countOfSize(odd.faces, 3), 1 + 9);
  // Four around an apex paired all round would leave the apex on two quads sharing two edges.
  Fan four = cone(4, 0.5);
  EXPECT_EQ(medial::pairStripTriangles(four.vertices, four.faces, {four.strip}), 1);
  EXPECT_EQ(countOfSize(four.faces, 3), 2 + 4);
}

TEST(TrianglePairing, AFlatOrFoldedPairIsLeftAlone) {
  Fan flat = cone(8, 0.0);  // a flat disc: the pairs are flat, and joined
  EXPECT_EQ(medial::pairStripTriangles(flat.vertices, flat.faces, {flat.strip}), 4);
  // A fan of six around an apex far below its ring's plane folds each pair by more than 75 degrees
  // about the shared edge.
  Fan folded = cone(6, 0.05);
  folded.vertices[0] = {0, 0, -0.05};
  for (auto& v : folded.vertices) v.z() *= 40;
  EXPECT_EQ(medial::pairStripTriangles(folded.vertices, folded.faces, {folded.strip}, 10.0), 0);
  EXPECT_EQ(folded.faces.size(), 12u);
}

TEST(TrianglePairing, ABandBetweenTwoRingsBecomesQuadsThatEachSpanBoth) {
  // Two rings of 6 (z = 0 and z = 1) zipped by 12 triangles, listed in a shuffled order; each ring
  // closed by a fan that is not part of the strip (its triangles share edges with the band's).
  std::vector<Eigen::Vector3d> vertices;
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 6; ++i)
      vertices.push_back({std::cos(M_PI * i / 3), std::sin(M_PI * i / 3), double(z)});
  vertices.push_back({0, 0, -1});
  vertices.push_back({0, 0, 2});
  std::vector<std::vector<int>> faces;
  for (int i = 0; i < 6; ++i) {
    const int a = i, b = (i + 1) % 6;
    faces.push_back({a, b, 6 + a});
    faces.push_back({b, 6 + b, 6 + a});
  }
  for (int i = 0; i < 6; ++i) {
    faces.push_back({(i + 1) % 6, i, 12});
    faces.push_back({6 + i, 6 + (i + 1) % 6, 13});
  }
  const std::vector<size_t> band{5, 0, 11, 3, 1, 7, 2, 9, 4, 10, 6, 8};
  EXPECT_EQ(medial::pairStripTriangles(vertices, faces, {band}), 6);
  EXPECT_EQ(faces.size(), 6u + 12);
  EXPECT_EQ(countOfSize(faces, 4), 6);
  for (size_t f = 0; f < 6; ++f) {
    int low = 0;
    for (int v : faces[f]) low += v < 6;
    EXPECT_EQ(low, 2);
  }
}

TEST(TrianglePairing, TrianglesThatAreNotOneStripAreLeftAlone) {
  Fan fan = cone(8, 1.0);
  std::vector<size_t> broken(fan.strip.begin(), fan.strip.end());
  broken.erase(broken.begin() + 2);
  broken.erase(broken.begin() + 5);  // two pieces: not one path or cycle
  EXPECT_EQ(medial::pairStripTriangles(fan.vertices, fan.faces, {broken}), 0);
  std::vector<size_t> path(fan.strip.begin(), fan.strip.begin() + 5);  // a path of five: two pairs
  EXPECT_EQ(medial::pairStripTriangles(fan.vertices, fan.faces, {path}), 2);
  EXPECT_EQ(fan.faces.size(), 6u + 8);
}

}  // namespace
