// vtkMedialContractionSkeleton: outputs, arrays, progress, and errors on bad input.
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialReader.h"
#include "vtkMedialRigWriter.h"

#include <filesystem>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkPoints.h>

#include <cmath>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkLineSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

namespace {

vtkSmartPointer<vtkPolyData> readMesh(const std::string& path) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
}

}  // namespace

TEST(ContractionSkeleton, TorusFileGivesSkeletonWithRadiiAndSegmentation) {
  auto torus = readMesh(medial::test::dataPath("meshes/torus.off"));
  ASSERT_TRUE(torus);
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  filter->SetInputData(torus);
  filter->SetTargetNodes(16);
  double lastProgress = 0;
  auto observer = vtkSmartPointer<vtkCallbackCommand>::New();
  observer->SetClientData(&lastProgress);
  observer->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    *static_cast<double*>(client) = *static_cast<double*>(data);
  });
  filter->AddObserver(vtkCommand::ProgressEvent, observer);
  filter->Update();

  vtkPolyData* skeleton = filter->GetOutput(0);
  ASSERT_GE(skeleton->GetNumberOfPoints(), 3);
  EXPECT_LE(skeleton->GetNumberOfPoints(), 16);
  // One cycle: as many edges as nodes on a single loop component.
  EXPECT_EQ(skeleton->GetNumberOfLines(), skeleton->GetNumberOfPoints());
  vtkDataArray* radius = skeleton->GetPointData()->GetArray("Radius");
  ASSERT_TRUE(radius);
  EXPECT_GT(radius->GetRange()[0], 0);
  EXPECT_TRUE(skeleton->GetFieldData()->GetArray("Root"));

  vtkPolyData* mesh = filter->GetOutput(1);
  EXPECT_EQ(mesh->GetNumberOfPoints(), torus->GetNumberOfPoints());
  auto* nodes = vtkIntArray::SafeDownCast(mesh->GetPointData()->GetArray("SkeletonNode"));
  ASSERT_TRUE(nodes);
  EXPECT_GE(nodes->GetRange()[0], 0);
  EXPECT_LT(nodes->GetRange()[1], skeleton->GetNumberOfPoints());
  EXPECT_GT(filter->GetContractionIterations(), 0);
  EXPECT_GT(filter->GetStageSeconds("contraction"), 0);
  EXPECT_DOUBLE_EQ(lastProgress, 1.0);
}

TEST(ContractionSkeleton, QuadMeshIsTriangulated) {
  auto capsule = readMesh(medial::test::dataPath("meshes/capsule.vtp"));
  ASSERT_TRUE(capsule);
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  filter->SetInputData(capsule);
  filter->Update();
  EXPECT_GT(filter->GetOutput(0)->GetNumberOfPoints(), 1);
  EXPECT_EQ(filter->GetOutput(1)->GetNumberOfPoints(), capsule->GetNumberOfPoints());
}

TEST(ContractionSkeleton, LinesOnlyInputIsAnErrorWithEmptyOutput) {
  auto line = vtkSmartPointer<vtkLineSource>::New();
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  auto errors = medial::ErrorCollector::Watch(filter);
  filter->SetInputConnection(line->GetOutputPort());
  filter->Update();
  EXPECT_TRUE(errors->HasErrors());
  EXPECT_NE(errors->Joined().find("no polygons"), std::string::npos) << errors->Joined();
  EXPECT_EQ(filter->GetOutput(0)->GetNumberOfPoints(), 0);
}

TEST(ContractionSkeleton, NaNCoordinateIsAnError) {
  auto torus = readMesh(medial::test::dataPath("meshes/torus.off"));
  ASSERT_TRUE(torus);
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(torus);
  copy->GetPoints()->SetPoint(5, std::nan(""), 0, 0);
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  auto errors = medial::ErrorCollector::Watch(filter);
  filter->SetInputData(copy);
  filter->Update();
  EXPECT_NE(errors->Joined().find("vertex 5 has a non-finite coordinate"), std::string::npos)
      << errors->Joined();
  EXPECT_EQ(filter->GetOutput(0)->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetOutput(1)->GetNumberOfPoints(), 0);
}

TEST(ContractionSkeleton, AbortStopsWithAnError) {
  auto torus = readMesh(medial::test::dataPath("meshes/torus.off"));
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  auto errors = medial::ErrorCollector::Watch(filter);
  filter->SetInputData(torus);
  auto abort = vtkSmartPointer<vtkCallbackCommand>::New();
  abort->SetClientData(filter.Get());
  abort->SetCallback([](vtkObject*, unsigned long, void* client, void*) {
    static_cast<vtkMedialContractionSkeleton*>(client)->SetAbortExecute(1);
  });
  filter->AddObserver(vtkCommand::ProgressEvent, abort);
  filter->Update();
  EXPECT_NE(errors->Joined().find("aborted"), std::string::npos) << errors->Joined();
  EXPECT_EQ(filter->GetOutput(0)->GetNumberOfPoints(), 0);
}

TEST(ContractionSkeleton, WeightsPerBoneAndRigFile) {
  auto torus = readMesh(medial::test::dataPath("meshes/torus.off"));
  ASSERT_TRUE(torus);
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  filter->SetInputData(torus);
  filter->SetTargetNodes(8);
  filter->ComputeWeightsOn();
  filter->Update();
  vtkPolyData* skeleton = filter->GetOutput(0);
  vtkDataArray* weights = filter->GetOutput(1)->GetPointData()->GetArray("SkinWeights");
  ASSERT_TRUE(weights);
  EXPECT_EQ(weights->GetNumberOfComponents(), skeleton->GetNumberOfLines());
  EXPECT_EQ(weights->GetNumberOfTuples(), torus->GetNumberOfPoints());
  for (vtkIdType v = 0; v < weights->GetNumberOfTuples(); ++v) {
    double sum = 0;
    for (int bone = 0; bone < weights->GetNumberOfComponents(); ++bone) sum += weights->GetComponent(v, bone);
    ASSERT_NEAR(sum, 1.0, 1e-9) << v;
  }
  EXPECT_GT(filter->GetStageSeconds("weights"), 0);

  const std::string dir = medial::test::scratchDir("filter-rig");
  auto writer = vtkSmartPointer<vtkMedialRigWriter>::New();
  auto errors = medial::ErrorCollector::Watch(writer);
  writer->SetFileName((dir + "/torus.glb").c_str());
  writer->SetInputConnection(0, filter->GetOutputPort(1));
  writer->SetInputConnection(1, filter->GetOutputPort(0));
  EXPECT_EQ(writer->Write(), 1) << errors->Joined();
  EXPECT_GT(std::filesystem::file_size(dir + "/torus.glb"), 1000u);

  // Without weights the writer refuses and leaves nothing behind.
  auto plain = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  plain->SetInputData(torus);
  plain->SetTargetNodes(8);
  plain->Update();
  auto refused = vtkSmartPointer<vtkMedialRigWriter>::New();
  auto refusal = medial::ErrorCollector::Watch(refused);
  refused->SetFileName((dir + "/plain.glb").c_str());
  refused->SetInputData(0, plain->GetOutput(1));
  refused->SetSkeletonData(plain->GetOutput(0));
  EXPECT_EQ(refused->Write(), 0);
  EXPECT_NE(refusal->Joined().find("no SkinWeights"), std::string::npos) << refusal->Joined();
  EXPECT_FALSE(std::filesystem::exists(dir + "/plain.glb"));
}
