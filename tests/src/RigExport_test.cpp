// RigExport: a skinned tube with a three-bone skeleton written as glTF and FBX, read back with Assimp.
#include "ContractionTestMeshes.h"
#include "rig/HeatWeights.h"
#include "rig/RigExport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

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
  // The root joint at node 0, then breadth-first from node 0: edge 0 (0 -> 1), then the two bones leaving
  // node 1.
  EXPECT_EQ(medial::rigBoneNames(rig.skeleton),
            (std::vector<std::string>{"Root", "Bone_0_0_1", "Bone_1_1_2", "Bone_2_1_3"}));
}

// (format, file extension)
class RigRoundTrip : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(RigRoundTrip, BonesAndWeightSumsSurvive) {
  // glTF through TinyGLTF, FBX through Medial's writer; both read back with Assimp's importers.
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
                                           std::make_pair("fbx", "fbx")));

TEST(RigExport, BinaryFbxHasTheHeaderVersionAndFooterReadersCheck) {
  const std::string path = scratch("tube.fbx");
  ASSERT_EQ(medial::exportRig(tubeRig(), path, medial::rigFormatForFile(path)), "");
  std::ifstream file(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 10000u);
  EXPECT_EQ(bytes.substr(0, 23), std::string("Kaydara FBX Binary  \0\x1a\0", 23));
  EXPECT_EQ(bytes.substr(23, 4), std::string("\xe8\x1c\0\0", 4));  // 7400
  EXPECT_EQ(bytes.substr(bytes.size() - 16),
            std::string("\xf8\x5a\x8c\x6a\xde\xf5\xd9\x7e\xec\xe9\x0c\xe3\x75\x8f\x29\x0b", 16));
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
  EXPECT_NE(medial::exportRig(nan, scratch("bad.glb"), "glb2").find("vertex 5 for bone 1"),
            std::string::npos);
  medial::Rig negative = tubeRig();
  negative.weights(0, 0) = -0.5;
  EXPECT_NE(medial::exportRig(negative, scratch("bad.glb"), "glb2"), "");
  medial::Rig unweighted = tubeRig();
  unweighted.weights.setZero();
  EXPECT_EQ(medial::exportRig(unweighted, scratch("unweighted.glb"), "glb2"), "");
}
