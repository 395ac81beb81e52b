// RigRoot: a rig hangs from the body's centre - the hips of a figure - never from a hand whose fingers make
// it the node where most branches meet.
#include "ContractionTestMeshes.h"
#include "rig/RigRoot.h"

#include <gtest/gtest.h>

namespace {

// A figure standing along z with a human's proportions (metres): pelvis 0 (legs to the feet 3, 4), spine
// 0-1-2, chest 2 (arms to the hands 5, 6, neck to the head 7), and on the right hand (node 6) five fingers:
// the hand has degree six, the pelvis and the chest three.
medial::Skeleton figureWithFingers() {
  medial::Skeleton figure;
  figure.nodes = {{0, 0, 0},       {0, 0, 0.25},    {0, 0, 0.5},    {-0.15, 0, -0.9},
                  {0.15, 0, -0.9}, {-0.75, 0, 0.4}, {0.75, 0, 0.4}, {0, 0, 0.8}};
  figure.edges = {{0, 1}, {1, 2}, {0, 3}, {0, 4}, {2, 5}, {2, 6}, {2, 7}};
  for (int finger = 0; finger < 5; ++finger) {
    figure.nodes.emplace_back(0.85, 0, 0.36 + 0.02 * finger);
    figure.edges.push_back({6, figure.nodeCount() - 1});
  }
  return figure;
}

// A closed box mesh around `centre` (its volume centroid).
medial::TriangleMesh boxAround(const Eigen::Vector3d& centre) {
  medial::TriangleMesh box = medial::testing::torusMesh(1, 0.3, 12, 6);
  box.vertices.rowwise() += centre.transpose();
  return box;
}

}  // namespace

TEST(RigRoot, AFigureHangsFromItsHipsOrChestNotItsHand) {
  const medial::Skeleton figure = figureWithFingers();
  // The mesh's middle near the pelvis: the pelvis; near the chest: the chest. Never the hand (node 6).
  EXPECT_EQ(medial::bodyCentreNode(figure, boxAround({0, 0, 0.05})), 0);
  EXPECT_EQ(medial::bodyCentreNode(figure, boxAround({0, 0, 0.45})), 2);
  EXPECT_EQ(medial::bodyCentreNode(figure, boxAround({0.75, 0, 0.4})), 2) << "the hand is not central";
  const int withoutMesh = medial::bodyCentreNode(figure, medial::TriangleMesh{});
  EXPECT_TRUE(withoutMesh == 0 || withoutMesh == 2) << withoutMesh;
}

TEST(RigRoot, EccentricityIsTheDistanceToTheFarthestNode) {
  const medial::Skeleton figure = figureWithFingers();
  double longest = 0;
  const std::vector<double> eccentricity = medial::nodeEccentricities(figure, longest);
  const auto length = [&](int a, int b) {
    return (figure.nodes[size_t(a)] - figure.nodes[size_t(b)]).norm();
  };
  const double leg = length(0, 3), spine = 0.5, arm = length(2, 6), finger = length(6, 8);
  // The longest path runs from a foot over the spine to the right hand's outer finger.
  EXPECT_NEAR(longest, leg + spine + arm + finger, 1e-9);
  EXPECT_NEAR(eccentricity[0], spine + arm + finger, 1e-9);  // pelvis: to that finger
  EXPECT_NEAR(eccentricity[2], spine + leg, 1e-9);           // chest: to a foot
  EXPECT_NEAR(eccentricity[6], arm + spine + leg, 1e-9);     // hand: to a foot
  EXPECT_LE(eccentricity[0], medial::kCentralShare * longest);
  EXPECT_LE(eccentricity[2], medial::kCentralShare * longest);
  EXPECT_GT(eccentricity[6], medial::kCentralShare * longest);
}

TEST(RigRoot, APathWithoutBranchesHangsFromItsMiddle) {
  medial::Skeleton path;
  for (double x : {0.0, 1.0, 2.0, 5.0, 10.0}) path.nodes.emplace_back(x, 0, 0);
  for (int i = 0; i < 4; ++i) path.edges.push_back({i, i + 1});
  // Central nodes (at most 6.5 from every end): x = 5 only (x = 2: 8 from the end). The mesh cannot pull the
  // root out of the middle.
  EXPECT_EQ(medial::bodyCentreNode(path, boxAround({0, 0, 0})), 3);
  EXPECT_EQ(medial::bodyCentreNode(medial::Skeleton{}, medial::TriangleMesh{}), -1);
}
