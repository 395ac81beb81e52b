// StructureRuns: the part to follow from runs and union-find, against the full-volume clean-up it replaces.
#include "centerline/BinaryVolume.h"
#include "centerline/StructureRuns.h"

#include <gtest/gtest.h>

#include <random>

namespace {

medial::BinaryVolume emptyVolume(int nx, int ny, int nz) {
  medial::BinaryVolume v;
  v.size = {nx, ny, nz};
  v.origin = {10, 20, 30};
  v.spacing = {0.5, 0.7, 1.0};
  v.inside.assign(size_t(v.voxelCount()), 0);
  return v;
}

std::vector<medial::VoxelRun> runsOf(const medial::BinaryVolume& v) {
  return medial::selectedRuns(v.size, [&](int64_t i) { return v.inside[size_t(i)] != 0; });
}

}  // namespace

TEST(StructureRuns, BorderPartsDiagonalNeighboursAndTheBox) {
  medial::BinaryVolume v = emptyVolume(10, 10, 10);
  for (int x = 0; x < 3; ++x) v.inside[size_t(v.index(x, 5, 5))] = 1;  // touches the border (x = 0)
  v.inside[size_t(v.index(4, 4, 4))] = 1;                              // two voxels joined by a corner
  v.inside[size_t(v.index(5, 5, 5))] = 1;
  v.inside[size_t(v.index(8, 8, 2))] = 1;  // alone
  const auto runs = runsOf(v);
  EXPECT_EQ(runs.size(), 4u);

  const medial::ChosenPart dropped = medial::largestPart(v, runs, true, 1);
  EXPECT_EQ(dropped.parts, 3);
  EXPECT_EQ(dropped.borderVoxels, 3);
  EXPECT_EQ(dropped.voxels, 2);
  EXPECT_EQ(dropped.first, (std::array<int, 3>{3, 3, 3}));
  EXPECT_EQ(dropped.volume.size, (std::array<int, 3>{4, 4, 4}));
  EXPECT_TRUE(dropped.volume.physical(int64_t(0)).isApprox(v.physical(v.index(3, 3, 3))));
  EXPECT_EQ(dropped.volume.inside[size_t(dropped.volume.index(1, 1, 1))], 1);
  EXPECT_EQ(dropped.volume.inside[size_t(dropped.volume.index(2, 2, 2))], 1);

  const medial::ChosenPart kept = medial::largestPart(v, runs, false, 1);
  EXPECT_EQ(kept.voxels, 3);
  EXPECT_EQ(kept.first, (std::array<int, 3>{0, 4, 4}));
  EXPECT_EQ(kept.volume.size, (std::array<int, 3>{4, 3, 3}));

  v.inside.assign(v.inside.size(), 0);
  v.inside[0] = 1;  // only a border part
  EXPECT_EQ(medial::largestPart(v, runsOf(v), true, 1).voxels, 0);
}

// On random volumes the runs give the voxels, frame and box that dropBorderTouchingParts,
// keepLargestComponent and cropToStructure give.
TEST(StructureRuns, SameAsTheFullVolumeCleanUpOnRandomVolumes) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 40; ++trial) {
    medial::BinaryVolume v = emptyVolume(12 + trial % 5, 9 + trial % 3, 10 + trial % 4);
    std::bernoulli_distribution on(0.08 + 0.005 * trial);
    for (auto& voxel : v.inside) voxel = on(random);
    for (const bool dropBorder : {true, false}) {
      medial::BinaryVolume old = v;
      if (dropBorder) medial::dropBorderTouchingParts(old);
      medial::keepLargestComponent(old);
      const int64_t voxels = std::count(old.inside.begin(), old.inside.end(), 1);
      const medial::ChosenPart chosen = medial::largestPart(v, runsOf(v), dropBorder, 1);
      ASSERT_EQ(chosen.voxels, voxels) << "trial " << trial << " dropBorder " << dropBorder;
      if (voxels == 0) continue;
      const auto first = medial::cropToStructure(old, 1);
      EXPECT_EQ(chosen.first, first) << "trial " << trial;
      EXPECT_EQ(chosen.volume.size, old.size) << "trial " << trial;
      EXPECT_TRUE(chosen.volume.origin.isApprox(old.origin)) << "trial " << trial;
      EXPECT_EQ(chosen.volume.inside, old.inside) << "trial " << trial;
    }
  }
}
