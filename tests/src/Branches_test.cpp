// Branches: a branching tube cut into unbranched ones where its Manhattan layers fall apart.
#include "centerline/Branches.h"

#include <gtest/gtest.h>

#include <numeric>
#include <set>

namespace {

// A T of square tubes: a stem along z (x, y in 8..12, z in 0..40) and an arm along x (x in 13..30, y in
// 8..12, z in 18..22) leaving it halfway up.
medial::BinaryVolume tee() {
  medial::BinaryVolume v;
  v.size = {34, 20, 44};
  v.inside.assign(size_t(v.voxelCount()), 0);
  for (int k = 0; k < 44; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 34; ++i) {
        const bool stem = i >= 8 && i <= 12 && j >= 8 && j <= 12 && k >= 1 && k <= 40;
        const bool arm = i >= 13 && i <= 30 && j >= 8 && j <= 12 && k >= 18 && k <= 22;
        v.inside[size_t(v.index(i, j, k))] = stem || arm;
      }
  return v;
}

}  // namespace

TEST(Branches, TeeSplitsIntoAStemAndTwoBranchesThatPartitionIt) {
  const medial::BinaryVolume v = tee();
  const medial::BranchVolumes split = medial::splitBranches(v, -1, 4);
  ASSERT_TRUE(split.ok()) << split.error;
  ASSERT_EQ(split.voxels.size(), 3u);
  EXPECT_EQ(split.parent[0], -1);
  EXPECT_EQ(split.parent[1], 0);
  EXPECT_EQ(split.parent[2], 0);
  // The root starts at the bottom (the lowest voxel, no seed given).
  EXPECT_EQ(v.coordinates(split.start[0])[2], 1);
  // Every voxel of the structure is in exactly one branch.
  std::set<int64_t> seen;
  size_t total = 0;
  for (const auto& branch : split.voxels) {
    total += branch.size();
    for (int64_t voxel : branch) {
      EXPECT_TRUE(v.inside[size_t(voxel)]);
      seen.insert(voxel);
    }
  }
  EXPECT_EQ(seen.size(), total);
  EXPECT_EQ(int64_t(total), int64_t(std::accumulate(v.inside.begin(), v.inside.end(), 0)));
  // One child is the arm (it reaches x = 30), the other the stem's upper part (z = 40).
  bool arm = false, top = false;
  for (size_t b = 1; b < 3; ++b)
    for (int64_t voxel : split.voxels[b]) {
      arm |= v.coordinates(voxel)[0] == 30;
      top |= v.coordinates(voxel)[2] == 40;
    }
  EXPECT_TRUE(arm && top);
}

TEST(Branches, ShortSideBumpsStayPartOfTheirBranch) {
  medial::BinaryVolume v = tee();
  // Shorten the arm to 3 voxels: below a minimum length of 6 layers it is no branch.
  for (int64_t i = 0; i < v.voxelCount(); ++i)
    if (v.coordinates(i)[0] > 15) v.inside[size_t(i)] = 0;
  const medial::BranchVolumes split = medial::splitBranches(v, -1, 6);
  ASSERT_TRUE(split.ok()) << split.error;
  EXPECT_EQ(split.voxels.size(), 1u);
}

TEST(Branches, SeedOutsideTheStructureIsAnError) {
  const medial::BinaryVolume v = tee();
  const medial::BranchVolumes split = medial::splitBranches(v, v.index(0, 0, 0), 4);
  EXPECT_FALSE(split.ok());
}
