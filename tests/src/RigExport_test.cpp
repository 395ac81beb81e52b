// RigExport: a skinned tube with a three-bone skeleton written as glTF and FBX, read back with Assimp.
#include "ContractionTestMeshes.h"
#include "rig/HeatWeights.h"
#include "rig/RigBones.h"
#include "rig/RigExport.h"
#include "rig/RigImport.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

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
  // node 1, the end joints of the two leaf bones, and Root_end.
  EXPECT_EQ(medial::rigBoneNames(rig.skeleton),
            (std::vector<std::string>{"Root", "Bone_0_0_1", "Bone_1_1_2", "Bone_2_1_3", "Bone_1_1_2_end",
                                      "Bone_2_1_3_end", "Root_end"}));
}

TEST(RigExport, EndJointsSitAtTheLeavesAndRootStandsBelowTheMesh) {
  const medial::Rig rig = tubeRig();
  const std::vector<medial::RigBone> bones = medial::buildRigBones(rig.skeleton, &rig.mesh.vertices);
  ASSERT_EQ(bones.size(), 7u);
  for (const medial::RigBone& bone : bones) {
    const Eigen::Vector3d at = bone.global.topRightCorner<3, 1>();
    if (bone.name.size() > 4 && bone.name.substr(bone.name.size() - 4) == "_end" && bone.name != "Root_end") {
      EXPECT_EQ(bone.edge, -1) << bone.name;
      EXPECT_EQ(bones[size_t(bone.parent)].name + "_end", bone.name);
      EXPECT_LT((at - rig.skeleton.nodes[size_t(bone.head)]).norm(), 1e-12) << bone.name;
    }
  }
  // The tube is 2 high (y in [-1, 1]) and no vertex lies farther than 1 from the skeleton (its radius, its
  // caps' tips 1 beyond the end nodes): Root stands below y = -1 by twice that.
  const Eigen::Vector3d root = bones[0].global.topRightCorner<3, 1>();
  EXPECT_NEAR(root.x(), -5, 1e-12);
  EXPECT_LT(root.y(), -1 - 2 * 1.0 + 1e-9);
  EXPECT_LT(bones[0].global(1, 1), 0) << "Root's Y axis points down";
  EXPECT_LT(bones.back().global(1, 3), root.y()) << "Root_end below Root";
}

TEST(RigExport, UpAxisRotationsTakeTheAxisUp) {
  const std::vector<std::pair<std::string, Eigen::Vector3d>> axes = {
      {"x", Eigen::Vector3d::UnitX()},   {"y", Eigen::Vector3d::UnitY()},
      {"z", Eigen::Vector3d::UnitZ()},   {"-x", -Eigen::Vector3d::UnitX()},
      {"-y", -Eigen::Vector3d::UnitY()}, {"-z", -Eigen::Vector3d::UnitZ()}};
  for (const auto& [name, axis] : axes) {
    Eigen::Matrix3d rotation;
    ASSERT_TRUE(medial::upAxisRotation(name, rotation)) << name;
    EXPECT_NEAR(rotation.determinant(), 1, 1e-12) << name;
    EXPECT_LT((rotation * axis - Eigen::Vector3d::UnitY()).norm(), 1e-12) << name;
  }
  Eigen::Matrix3d rotation;
  EXPECT_FALSE(medial::upAxisRotation("up", rotation));
  EXPECT_NE(medial::exportRig(tubeRig(), scratch("bad.glb"), "glb2", {4, "Mesh", "w", 1.0}), "");
  EXPECT_NE(medial::exportRig(tubeRig(), scratch("bad.glb"), "glb2", {4, "Mesh", "y", 0.0}), "");
}

TEST(RigExport, AnXUpMeshIsTurnedAndScaled) {
  // The tube along x, turned as if x were up and scaled by 2: read back (Assimp, no axis conversion of its
  // own for glTF) it stands along y, 2 x 12 tall (the tube with its caps is 12 long), 2 x 2 wide.
  const std::string path = scratch("turned.glb");
  ASSERT_EQ(medial::exportRig(tubeRig(), path, "glb2", {4, "Mesh", "x", 2.0}), "");
  const medial::ImportedRig back = medial::importRig(path);
  ASSERT_EQ(back.error, "");
  const Eigen::Vector3d extent =
      back.mesh.vertices.colwise().maxCoeff() - back.mesh.vertices.colwise().minCoeff();
  EXPECT_NEAR(extent.x(), 2 * 2, 1e-4);
  EXPECT_NEAR(extent.y(), 2 * 12, 1e-4);
  EXPECT_NEAR(extent.z(), 2 * 2, 1e-4);
  EXPECT_EQ(back.skeleton.nodeCount(), 4) << "the same skeleton, Root and end joints folded in";
  std::remove(path.c_str());
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
