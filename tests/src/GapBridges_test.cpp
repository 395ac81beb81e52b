// GapBridges: least-cost paths through a cost box, the order in which parts are chained, and the joined
// centerline with its bridges.
#include "centerline/GapBridges.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using Eigen::Vector3d;
using medial::Centerline;

// A straight centerline from a to b, a point every mm, radius r.
Centerline segment(const Vector3d& a, const Vector3d& b, double r = 2.0) {
  Centerline line;
  const int n = std::max(2, int(std::lround((b - a).norm())) + 1);
  for (int k = 0; k < n; ++k) {
    line.points.push_back(a + (b - a) * double(k) / (n - 1));
    line.radius.push_back(r);
    line.arcLength.push_back((b - a).norm() * k / (n - 1));
  }
  return line;
}

medial::CostBox uniformBox(std::array<int, 3> size, float cost) {
  medial::CostBox box;
  box.size = size;
  box.cost.assign(size_t(size[0]) * size[1] * size[2], cost);
  return box;
}

double pathLength(const std::vector<std::array<int, 3>>& path, const Vector3d& spacing) {
  double length = 0;
  for (size_t k = 1; k < path.size(); ++k)
    length += Vector3d(path[k][0] - path[k - 1][0], path[k][1] - path[k - 1][1], path[k][2] - path[k - 1][2])
                  .cwiseProduct(spacing)
                  .norm();
  return length;
}

}  // namespace

TEST(GapBridges, LeastCostPathIsStraightThroughUniformCost) {
  const medial::CostBox box = uniformBox({30, 20, 10}, 1.0f);
  const Vector3d spacing(0.7, 0.7, 1.0);
  const auto path = medial::leastCostPath(box, spacing, {2, 3, 4}, {25, 15, 6});
  ASSERT_GE(path.size(), 2u);
  EXPECT_EQ(path.front(), (std::array<int, 3>{2, 3, 4}));
  EXPECT_EQ(path.back(), (std::array<int, 3>{25, 15, 6}));
  const double straight = Vector3d(23 * 0.7, 12 * 0.7, 2.0).norm();
  // A 26-connected path on anisotropic voxels is at most about 13 % longer than the straight line (here
  // 12 %); the bridge smooths it afterwards.
  EXPECT_LE(pathLength(path, spacing), 1.14 * straight);
}

TEST(GapBridges, LeastCostPathGoesThroughTheCheapHoleOfAWall) {
  // A wall of cost 50 across x = 10 with a hole of cost 1 at y 15..17: the path from one side to the other
  // passes the hole rather than the wall, though the hole is off the straight line.
  medial::CostBox box = uniformBox({21, 21, 3}, 1.0f);
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 21; ++y)
      if (y < 15 || y > 17) box.cost[size_t(10 + 21 * (y + 21 * z))] = 50.0f;
  const auto path = medial::leastCostPath(box, Vector3d::Ones(), {0, 5, 1}, {20, 5, 1});
  ASSERT_FALSE(path.empty());
  bool throughHole = false;
  for (const auto& v : path)
    if (v[0] == 10) throughHole = v[1] >= 15 && v[1] <= 17;
  EXPECT_TRUE(throughHole);
  // Outside the box: no path.
  EXPECT_TRUE(medial::leastCostPath(box, Vector3d::Ones(), {0, 5, 1}, {30, 5, 1}).empty());
}

TEST(GapBridges, PartsChainFromTheLowestEndToTheNearestEnds) {
  // Three pieces of one tube along z, split by gaps of 10 and 12 mm, given out of order and two of them
  // backwards; a far fourth piece (60 mm off) starts a chain of its own.
  const std::vector<Centerline> parts = {segment({0, 0, 90}, {0, 0, 60}),  // the middle, backwards
                                         segment({0, 0, 0}, {0, 0, 50}),  // the lowest: the rectum end at z 0
                                         segment({0, 0, 140}, {0, 0, 102}),  // the top, backwards
                                         segment({60, 0, 300}, {60, 0, 340})};
  int bridges = 0;
  const medial::PartChains chains = medial::chainParts(parts, -1, 40.0, [&](const medial::BridgeEnds& ends) {
    const Vector3d &from = ends.from, &to = ends.to;
    // Up the tube at both ends: the chain leaves upwards and arrives upwards at the next part's end.
    EXPECT_GT(ends.fromDirection.z(), 0.99);
    EXPECT_GT(ends.toDirection.z(), 0.99);
    ++bridges;
    medial::Bridge b;
    b.gap = (to - from).norm();  // the whole distance is outside the structure here
    b.points = medial::bridgePoints(from, to, {from, to}, 1.0);
    return b;
  });
  ASSERT_EQ(chains.chains.size(), 2u);
  const auto& first = chains.chains[0];
  ASSERT_EQ(first.size(), 3u);
  EXPECT_EQ(first[0].part, 1);
  EXPECT_FALSE(first[0].reversed);
  EXPECT_EQ(first[1].part, 0);
  EXPECT_TRUE(first[1].reversed);
  EXPECT_EQ(first[2].part, 2);
  EXPECT_TRUE(first[2].reversed);
  EXPECT_NEAR(first[1].bridge.gap, 10.0, 1e-9);
  EXPECT_NEAR(first[2].bridge.gap, 12.0, 1e-9);
  ASSERT_EQ(chains.brokenGaps.size(), 1u);
  EXPECT_GT(chains.brokenGaps[0], 40.0);
  EXPECT_EQ(bridges, 2) << "the far piece is out of reach: no path is searched for it";

  // The joined line: from z 0 to 140 in one polyline, its bridges marked, arc length continuous.
  const Centerline line = medial::joinChain(parts, first);
  ASSERT_EQ(line.points.size(), line.bridged.size());
  EXPECT_NEAR(line.points.front().z(), 0.0, 1e-9);
  EXPECT_NEAR(line.points.back().z(), 140.0, 1e-9);
  EXPECT_NEAR(line.length(), 140.0, 1e-6);
  int bridged = 0;
  for (size_t k = 0; k < line.points.size(); ++k) {
    if (!line.bridged[k]) continue;
    ++bridged;
    const double z = line.points[k].z();
    EXPECT_TRUE((z > 50 && z < 60) || (z > 90 && z < 102)) << z;
    EXPECT_EQ(line.radius[k], 0.0);
  }
  EXPECT_EQ(bridged, 9 + 11) << "a point every mm inside each gap";

  // The seed's part first: the chain starts there and goes on from its last point.
  const medial::PartChains seeded = medial::chainParts(parts, 2, 40.0, [](const medial::BridgeEnds& ends) {
    medial::Bridge bridge;
    bridge.gap = (ends.to - ends.from).norm();
    return bridge;
  });
  ASSERT_FALSE(seeded.chains.empty());
  EXPECT_EQ(seeded.chains[0][0].part, 2);
  EXPECT_EQ(seeded.chains[0].size(), 3u);
}

TEST(GapBridges, AGapLongerThanTheMaximumEndsTheChain) {
  const std::vector<Centerline> parts = {segment({0, 0, 0}, {0, 0, 50}), segment({0, 0, 70}, {0, 0, 120})};
  const auto across = [](const medial::BridgeEnds& ends) {
    medial::Bridge bridge;
    bridge.gap = (ends.to - ends.from).norm();
    return bridge;
  };
  EXPECT_EQ(medial::chainParts(parts, -1, 25.0, across).chains.size(), 1u);
  const medial::PartChains split = medial::chainParts(parts, -1, 15.0, across);
  ASSERT_EQ(split.chains.size(), 2u);
  ASSERT_EQ(split.brokenGaps.size(), 1u);
  EXPECT_NEAR(split.brokenGaps[0], 20.0, 1e-9);
}
