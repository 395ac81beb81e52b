// vtkMedialSkinBinding: an SQM mesh bound to the skeleton it was made from, written as a rig; bad inputs.
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "rig/RigExport.h"
#include "vtkMedialReader.h"
#include "vtkMedialRigWriter.h"
#include "vtkMedialSQM.h"
#include "vtkMedialSkinBinding.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

namespace {

vtkSmartPointer<vtkMedialReader> readerOf(const std::string& path) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

}  // namespace

// A procedural character: the humanoid skeleton's SQM mesh, skinned to that skeleton and exported.
TEST(SkinBinding, SqmMeshBindsToItsSkeletonAndWritesARig) {
  auto skeleton = readerOf(medial::test::dataPath("skeletons/sqm/humanoid.vtp"));
  auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
  sqm->SetInputConnection(skeleton->GetOutputPort());
  sqm->SetSubdivisionLevels(1);
  auto binding = vtkSmartPointer<vtkMedialSkinBinding>::New();
  auto errors = medial::ErrorCollector::Watch(binding);
  binding->SetInputConnection(0, sqm->GetOutputPort());
  binding->SetSkeletonConnection(skeleton->GetOutputPort());
  binding->Update();
  ASSERT_FALSE(errors->HasErrors()) << errors->Joined();

  vtkPolyData* mesh = binding->GetOutput(0);
  vtkPolyData* bound = sqm->GetOutput();
  EXPECT_EQ(mesh->GetNumberOfPolys(), bound->GetNumberOfPolys()) << "the quads stay quads";
  vtkDataArray* weights = mesh->GetPointData()->GetArray("SkinWeights");
  ASSERT_TRUE(weights);
  vtkPolyData* skeletonOut = binding->GetOutput(1);
  EXPECT_EQ(weights->GetNumberOfComponents(), skeletonOut->GetNumberOfLines());
  ASSERT_EQ(weights->GetNumberOfTuples(), mesh->GetNumberOfPoints());
  for (vtkIdType v = 0; v < weights->GetNumberOfTuples(); ++v) {
    double sum = 0;
    for (int bone = 0; bone < weights->GetNumberOfComponents(); ++bone) sum += weights->GetComponent(v, bone);
    ASSERT_NEAR(sum, 1.0, 1e-9) << v;
  }
  ASSERT_TRUE(vtkIntArray::SafeDownCast(mesh->GetPointData()->GetArray("Bone")));
  auto* root = vtkIntArray::SafeDownCast(skeletonOut->GetFieldData()->GetArray("Root"));
  ASSERT_TRUE(root);
  EXPECT_EQ(root->GetValue(0), binding->GetChosenRoot());
  EXPECT_EQ(binding->GetNodesOutside(), 0);

  const std::string path = medial::test::scratchDir("skin-binding") + "/humanoid.glb";
  auto writer = vtkSmartPointer<vtkMedialRigWriter>::New();
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(0, binding->GetOutputPort(0));
  writer->SetInputConnection(1, binding->GetOutputPort(1));
  ASSERT_EQ(writer->Write(), 1);
  const medial::RigSummary rig = medial::readRigSummary(path);
  ASSERT_TRUE(rig.error.empty()) << rig.error;
  EXPECT_EQ(rig.unweightedVertices, 0);
  EXPECT_LT(rig.maxWeightSumError, 1e-3);
  EXPECT_GT(rig.bones, 20);
}

TEST(SkinBinding, BadInputsAreErrorsWithEmptyOutputs) {
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->Update();
  auto skeleton = readerOf(medial::test::dataPath("skeletons/sqm/humanoid.vtp"));
  skeleton->Update();
  const auto run = [&](vtkPolyData* mesh, vtkPolyData* bones, int root = -1) {
    auto binding = vtkSmartPointer<vtkMedialSkinBinding>::New();
    auto errors = medial::ErrorCollector::Watch(binding);
    binding->SetInputData(0, mesh);
    binding->SetSkeletonData(bones);
    binding->SetRoot(root);
    binding->Update();
    EXPECT_EQ(binding->GetOutput(0)->GetNumberOfPoints(), 0);
    EXPECT_EQ(binding->GetOutput(1)->GetNumberOfPoints(), 0);
    return errors->Joined();
  };
  auto* humanoid = vtkPolyData::SafeDownCast(skeleton->GetOutputDataObject(0));
  // The skeleton as the mesh, the sphere as the skeleton, a root past the last node, a skeleton metres
  // away from a mesh in millimetres.
  EXPECT_NE(run(humanoid, humanoid).find("has no polygons"), std::string::npos);
  EXPECT_NE(run(sphere->GetOutput(), sphere->GetOutput()).find("the skeleton: "), std::string::npos);
  EXPECT_NE(run(sphere->GetOutput(), humanoid, 100000).find("is not a node of the skeleton"),
            std::string::npos);
  auto far = vtkSmartPointer<vtkSphereSource>::New();
  far->SetCenter(1000, 0, 0);
  far->Update();
  EXPECT_NE(run(far->GetOutput(), humanoid).find("outside the mesh's bounding box"), std::string::npos);
}
