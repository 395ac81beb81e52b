// RigExport: a skinned tube with a three-bone skeleton written as glTF and FBX, read back with Assimp.
#include "ContractionTestMeshes.h"
#include "contraction/HeatWeights.h"
#include "rig/RigExport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using medial::testing::tubeMesh;

namespace {

// tubeMesh(10, 1) along x, a skeleton that branches at the middle: 3 bones, root at the left end.
medial::Rig tubeRig() {
  medial::Rig rig;
  rig.mesh = tubeMesh(10, 1);
  rig.skeleton.nodes = {{-5, 0, 0}, {0, 0, 0}, {5, 0, 0}, {0, 0.5, 0}};
  rig.skeleton.edges = {{1, 0}, {1, 2}, {1, 3}};
  rig.skeleton.root = 0;
  const medial::InsideTest inside(rig.mesh);
  const auto weights = medial::heatWeights(rig.mesh, rig.skeleton, inside);
  EXPECT_TRUE(weights.ok()) << weights.error;
  rig.weights = weights.weights;
  return rig;
}

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "medial-rig-test";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

}  // namespace

TEST(RigExport, FormatFromFileName) {
  EXPECT_EQ(medial::rigFormatForFile("a/b.glb"), "glb2");
  EXPECT_EQ(medial::rigFormatForFile("B.GLTF"), "gltf2");
  EXPECT_EQ(medial::rigFormatForFile("c.fbx"), "fbx");
  EXPECT_EQ(medial::rigFormatForFile("d.obj"), "");
}

TEST(RigExport, BonesFollowTheHierarchyFromTheRoot) {
  const medial::Rig rig = tubeRig();
  // Breadth-first from node 0: edge 0 (0 -> 1) first, then the two bones leaving node 1.
  EXPECT_EQ(medial::rigBoneNames(rig.skeleton),
            (std::vector<std::string>{"Bone_0_0_1", "Bone_1_1_2", "Bone_2_1_3"}));
}

// (Assimp exporter id, file extension)
class RigRoundTrip : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(RigRoundTrip, BonesAndWeightSumsSurvive) {
  // Assimp cannot read back its own binary FBX (docs/ARCHITECTURE.md §9), so FBX is checked through its ASCII
  // flavour (the same exporter code writes both), the binary file by its header below.
  const std::string format = GetParam().first;
  const std::string path = scratch(std::string("tube.") + GetParam().second);
  const medial::Rig rig = tubeRig();
  ASSERT_EQ(medial::exportRig(rig, path, format), "");
  const medial::RigSummary summary = medial::readRigSummary(path);
  ASSERT_EQ(summary.error, "");
  EXPECT_EQ(summary.bones, 3);
  EXPECT_EQ(summary.faces, rig.mesh.faces.rows());
  // Assimp's FBX importer splits vertices per face corner; glTF keeps them shared.
  EXPECT_GE(summary.vertices, rig.mesh.vertices.rows());
  EXPECT_EQ(summary.unweightedVertices, 0);
  EXPECT_LT(summary.maxWeightSumError, 1e-5);  // float weights
  std::remove(path.c_str());
}

INSTANTIATE_TEST_SUITE_P(Formats, RigRoundTrip,
                         ::testing::Values(std::make_pair("glb2", "glb"), std::make_pair("gltf2", "gltf"),
                                           std::make_pair("fbxa", "fbx")));

TEST(RigExport, BinaryFbxIsWritten) {
  const std::string path = scratch("tube.fbx");
  ASSERT_EQ(medial::exportRig(tubeRig(), path, medial::rigFormatForFile(path)), "");
  std::ifstream file(path, std::ios::binary);
  std::string magic(20, '\0');
  file.read(magic.data(), 20);
  EXPECT_EQ(magic, std::string("Kaydara FBX Binary  "));
  EXPECT_GT(std::filesystem::file_size(path), 10000u);
  std::remove(path.c_str());
}

TEST(RigExport, BadRigsAreRefused) {
  medial::Rig rig = tubeRig();
  rig.weights.conservativeResize(rig.weights.rows(), 2);
  EXPECT_EQ(medial::exportRig(rig, scratch("bad.glb"), "glb2"),
            "the weights are 642 x 2, expected vertices x bones = 642 x 3");
  medial::Rig boneless = tubeRig();
  boneless.skeleton.edges.clear();
  EXPECT_EQ(medial::exportRig(boneless, scratch("bad.glb"), "glb2"), "the skeleton has no bones (edges)");
  EXPECT_NE(medial::exportRig(tubeRig(), "/nonexistent-dir/rig.glb", "glb2"), "");
  EXPECT_NE(medial::exportRig(tubeRig(), scratch("rig.xyz"), "no-such-format"), "");
  // Found by fuzzing: NaN and negative weights are refused; weights all zero give a rig without bones
  // (its empty bone list once leaked).
  medial::Rig nan = tubeRig();
  nan.weights(5, 1) = std::nan("");
  EXPECT_NE(medial::exportRig(nan, scratch("bad.glb"), "glb2").find("vertex 5 for bone 1"), std::string::npos);
  medial::Rig negative = tubeRig();
  negative.weights(0, 0) = -0.5;
  EXPECT_NE(medial::exportRig(negative, scratch("bad.glb"), "glb2"), "");
  medial::Rig unweighted = tubeRig();
  unweighted.weights.setZero();
  EXPECT_EQ(medial::exportRig(unweighted, scratch("unweighted.glb"), "glb2"), "");
}
