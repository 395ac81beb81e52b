// vtkMedialContractionSkeleton: outputs, arrays, progress, and errors on bad input.
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "MedialSkeletonData.h"
#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialReader.h"
#include "vtkMedialRigWriter.h"

#include <algorithm>
#include <filesystem>
#include <vector>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkPoints.h>

#include <cmath>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkLineSource.h>
#include <vtkMath.h>
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

TEST(ContractionSkeleton, AbortStopsWithCancelled) {
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
  EXPECT_EQ(errors->Joined(), "cancelled");
  EXPECT_TRUE(filter->GetAbortExecute());
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

// The rigs Medial writes open again: the mesh as written, and (RigSkeleton) the skeleton: every node with
// two or more edges at its joint, leaves near where they were (a file stores no bone length: the tail is
// estimated from the bone's vertices), a Radius from the weights. A joint tree has no cycles: each edge that
// closed one comes back as a leaf bone with a tail of its own.
TEST(ContractionSkeleton, RigFilesOpenAgainAsMeshAndSkeleton) {
  auto elephant = readMesh(medial::test::sourceDir() + "/data/external/cgal/meshes/elephant.off");
  ASSERT_TRUE(elephant);
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  filter->SetInputData(elephant);
  filter->ComputeWeightsOn();
  filter->Update();
  vtkPolyData* skeleton = filter->GetOutput(0);
  ASSERT_GT(skeleton->GetNumberOfLines(), 10);
  const double size = elephant->GetLength();
  const std::string dir = medial::test::scratchDir("filter-rig-round-trip");
  for (const char* name : {"elephant.glb", "elephant.fbx"}) {
    const std::string path = dir + "/" + name;
    auto writer = vtkSmartPointer<vtkMedialRigWriter>::New();
    writer->SetFileName(path.c_str());
    writer->SetInputConnection(0, filter->GetOutputPort(1));
    writer->SetInputConnection(1, filter->GetOutputPort(0));
    ASSERT_EQ(writer->Write(), 1) << name;

    auto mesh = vtkSmartPointer<vtkMedialReader>::New();
    mesh->SetFileName(path.c_str());
    mesh->Update();
    auto* meshOut = vtkPolyData::SafeDownCast(mesh->GetOutputDataObject(0));
    ASSERT_TRUE(meshOut) << mesh->GetErrorMessage();
    EXPECT_EQ(meshOut->GetNumberOfPoints(), elephant->GetNumberOfPoints()) << name;
    EXPECT_EQ(meshOut->GetNumberOfPolys(), elephant->GetNumberOfPolys()) << name;

    auto bones = vtkSmartPointer<vtkMedialReader>::New();
    bones->SetFileName(path.c_str());
    bones->RigSkeletonOn();
    bones->Update();
    auto* back = vtkPolyData::SafeDownCast(bones->GetOutputDataObject(0));
    ASSERT_TRUE(back) << bones->GetErrorMessage();
    // The same skeleton: the end joints mark every leaf's (and every cycle-closing bone's) tail.
    EXPECT_EQ(back->GetNumberOfPoints(), skeleton->GetNumberOfPoints()) << name;
    EXPECT_EQ(back->GetNumberOfLines(), skeleton->GetNumberOfLines()) << name;
    std::vector<int> degree(size_t(skeleton->GetNumberOfPoints()), 0);
    for (vtkIdType c = 0; c < skeleton->GetNumberOfCells(); ++c)
      for (vtkIdType k = 0; k < skeleton->GetCell(c)->GetNumberOfPoints(); ++k)
        ++degree[size_t(skeleton->GetCell(c)->GetPointId(k))];
    for (vtkIdType n = 0; n < skeleton->GetNumberOfPoints(); ++n) {
      double p[3], nearest = INFINITY;
      skeleton->GetPoint(n, p);
      for (vtkIdType m = 0; m < back->GetNumberOfPoints(); ++m) {
        double q[3];
        back->GetPoint(m, q);
        nearest = std::min(nearest, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
      }
      EXPECT_LT(nearest, 1e-5 * size) << name << " node " << n << " (degree " << degree[size_t(n)] << ")";
    }
    vtkDataArray* radius = back->GetPointData()->GetArray("Radius");
    ASSERT_TRUE(radius) << name;
    EXPECT_GT(radius->GetRange()[0], 0) << name;
    EXPECT_LT(radius->GetRange()[1], 0.5 * size) << name;
  }
  auto notARig = vtkSmartPointer<vtkMedialReader>::New();
  auto errors = medial::ErrorCollector::Watch(notARig);
  notARig->SetFileName(medial::test::dataPath("meshes/torus.off").c_str());
  notARig->RigSkeletonOn();  // ignored for a plain mesh format: the mesh is read
  notARig->Update();
  EXPECT_FALSE(errors->HasErrors()) << errors->Joined();
}

// The paper's intermediate results (RecordStages): the contracted mesh after every iteration with its
// weights (Figs. 5 and 7), shrinking towards the skeleton, and the curve skeletons before refinement and
// before selection.
TEST(ContractionSkeleton, RecordedStagesShowTheMeshContractingOntoTheSkeleton) {
  auto elephant = readMesh(medial::test::sourceDir() + "/data/external/cgal/meshes/elephant.off");
  ASSERT_TRUE(elephant);
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  filter->SetInputData(elephant);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfContractionSteps(), 0) << "nothing recorded unless asked";
  filter->RecordStagesOn();
  filter->Update();
  const int steps = filter->GetNumberOfContractionSteps();
  ASSERT_EQ(steps, filter->GetContractionIterations() + 1);
  EXPECT_EQ(filter->GetContractionStep(steps), nullptr);
  vtkPolyData* first = filter->GetContractionStep(0);
  vtkPolyData* last = filter->GetContractionStep(steps - 1);
  ASSERT_TRUE(first && last);
  EXPECT_EQ(first->GetNumberOfPoints(), filter->GetContractedVertices());
  for (const char* name : {"Laplacian", "AttractionWeight"})
    EXPECT_EQ(last->GetPointData()->GetArray(name)->GetNumberOfTuples(), last->GetNumberOfPoints()) << name;
  for (const char* name : {"ContractionWeight", "Iteration", "AreaRatio", "VolumeRatio"})
    EXPECT_TRUE(last->GetFieldData()->GetArray(name)) << name;
  // W_L grows by s_L each iteration until its cap; the area shrinks to a sliver.
  const auto field = [](vtkPolyData* mesh, const char* name) {
    return mesh->GetFieldData()->GetArray(name)->GetComponent(0, 0);
  };
  EXPECT_GT(field(filter->GetContractionStep(2), "ContractionWeight"),
            field(filter->GetContractionStep(1), "ContractionWeight"));
  EXPECT_LT(field(last, "AreaRatio"), 0.05);

  // The last step lies on the skeleton the surgery made of it: every vertex near one of its edges.
  vtkPolyData* surgery = filter->GetSurgerySkeleton();
  ASSERT_TRUE(surgery && surgery->GetNumberOfLines() > 0);
  medial::Skeleton curve;
  std::string error;
  ASSERT_TRUE(medial::skeletonFromPolyData(surgery, curve, error)) << error;
  std::vector<double> distances;
  for (vtkIdType v = 0; v < last->GetNumberOfPoints(); ++v) {
    const Eigen::Vector3d p(last->GetPoint(v));
    double nearest = INFINITY;
    for (const auto& e : curve.edges) {
      const Eigen::Vector3d a = curve.nodes[size_t(e[0])], b = curve.nodes[size_t(e[1])];
      const double t = std::clamp((p - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0.0, 1.0);
      nearest = std::min(nearest, (a + t * (b - a) - p).norm());
    }
    distances.push_back(nearest);
  }
  std::sort(distances.begin(), distances.end());
  const double size = elephant->GetLength();
  EXPECT_LT(distances[distances.size() / 2], 0.01 * size);
  EXPECT_LT(distances[distances.size() * 9 / 10], 0.03 * size);
  // The surgery's collapse order on the last step: every vertex but the nodes collapsed once, numbered
  // 1, 2, ... in order.
  vtkDataArray* order = last->GetPointData()->GetArray("CollapseOrder");
  ASSERT_TRUE(order);
  std::vector<int> collapsed;
  for (vtkIdType v = 0; v < order->GetNumberOfTuples(); ++v)
    if (order->GetComponent(v, 0) > 0) collapsed.push_back(int(order->GetComponent(v, 0)));
  EXPECT_EQ(vtkIdType(collapsed.size()) + surgery->GetNumberOfPoints(), last->GetNumberOfPoints());
  std::sort(collapsed.begin(), collapsed.end());
  for (size_t k = 0; k < collapsed.size(); ++k) ASSERT_EQ(collapsed[k], int(k) + 1);
  ASSERT_TRUE(filter->GetUnselectedSkeleton());
  EXPECT_GE(filter->GetUnselectedSkeleton()->GetNumberOfPoints(), filter->GetOutput(0)->GetNumberOfPoints());
}
