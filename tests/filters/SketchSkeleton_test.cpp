// vtkMedialSketchReader -> vtkMedialSketchSkeleton -> vtkMedialSQM on the strokes of data/sketches: the
// issue's pipeline test (the SQM mesh of every sketch is a closed manifold), the output arrays, errors.
#include "MedialMeshData.h"
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "mesh/MeshTopology.h"
#include "vtkMedialSQM.h"
#include "vtkMedialSketchReader.h"
#include "vtkMedialSketchSkeleton.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

namespace {

medial::MeshTopology topologyOf(vtkPolyData* mesh) {
  return medial::computeMeshTopology(mesh->GetNumberOfPoints(), medial::polygonsOf(mesh));
}

class SketchSamples : public ::testing::TestWithParam<const char*> {};

TEST_P(SketchSamples, SqmMeshOfTheSketchIsAClosedManifold) {
  auto reader = vtkSmartPointer<vtkMedialSketchReader>::New();
  reader->SetFileName(medial::test::dataPath(std::string("sketches/") + GetParam()).c_str());
  auto sketch = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
  auto errors = medial::ErrorCollector::Watch(sketch);
  sketch->SetInputConnection(reader->GetOutputPort());
  auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
  auto sqmErrors = medial::ErrorCollector::Watch(sqm);
  sqm->SetInputConnection(sketch->GetOutputPort(0));
  sqm->Update();
  ASSERT_FALSE(errors->HasErrors()) << errors->Joined();
  ASSERT_FALSE(sqmErrors->HasErrors()) << sqmErrors->Joined();

  vtkPolyData* skeleton = sketch->GetOutput(0);
  ASSERT_GT(skeleton->GetNumberOfPoints(), 1);
  for (const char* name : {"Radius", "NodeType", "Part"})
    EXPECT_TRUE(skeleton->GetPointData()->GetArray(name)) << name;
  for (const char* name : {"Part", "Branch"}) EXPECT_TRUE(skeleton->GetCellData()->GetArray(name)) << name;
  EXPECT_TRUE(skeleton->GetFieldData()->GetArray("Root"));

  const auto tube = topologyOf(sqm->GetOutput());
  EXPECT_EQ(tube.borderEdges, 0);
  EXPECT_EQ(tube.nonManifoldEdges, 0);
  EXPECT_EQ(tube.components, 1);  // every sketch here is one tree
  EXPECT_EQ(tube.eulerCharacteristic, 2);

  vtkPolyData* inflated = sketch->GetOutput(1);
  const auto parts = topologyOf(inflated);
  EXPECT_TRUE(parts.isClosedManifold());
  EXPECT_TRUE(inflated->GetPointData()->GetArray("Part"));
}

INSTANTIATE_TEST_SUITE_P(Sketches, SketchSamples,
                         ::testing::Values("rectangle.txt", "star.txt", "hand.txt", "bird.txt",
                                           "unsteady.txt"));

TEST(SketchSkeleton, ReaderKeepsPartsAndPlacements) {
  auto reader = vtkSmartPointer<vtkMedialSketchReader>::New();
  reader->SetFileName(medial::test::dataPath("sketches/bird.txt").c_str());
  reader->Update();
  vtkPolyData* strokes = reader->GetOutput();
  EXPECT_EQ(strokes->GetNumberOfLines(), 3);
  vtkDataArray* placement = strokes->GetCellData()->GetArray("Placement");
  ASSERT_TRUE(placement);
  EXPECT_EQ(placement->GetNumberOfComponents(), 16);
  EXPECT_EQ(placement->GetComponent(0, 0), 1.0);  // the body: identity
  EXPECT_EQ(placement->GetComponent(1, 0), 0.0);  // a wing: stroke x -> world z
  EXPECT_EQ(placement->GetComponent(1, 9), 0.0);
  EXPECT_EQ(placement->GetComponent(1, 8), 1.0);
}

TEST(SketchSkeleton, EmptyInputIsAnErrorWithEmptyOutputs) {
  auto sketch = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
  auto errors = medial::ErrorCollector::Watch(sketch);
  sketch->SetInputData(vtkSmartPointer<vtkPolyData>::New());
  sketch->Update();
  EXPECT_TRUE(errors->HasErrors());
  EXPECT_NE(errors->Joined().find("no stroke"), std::string::npos) << errors->Joined();
  EXPECT_EQ(sketch->GetOutput(0)->GetNumberOfPoints(), 0);
  EXPECT_EQ(sketch->GetOutput(1)->GetNumberOfPoints(), 0);
}

}  // namespace

// The skeleton after each step (RecordStages, the paper's Figs. 3-9): every stage there with its labels,
// the refinement never adding nodes, the connection joining the bird's three parts into one tree.
TEST(SketchSkeleton, RecordedStagesFollowThePipeline) {
  auto reader = vtkSmartPointer<vtkMedialSketchReader>::New();
  reader->SetFileName(medial::test::dataPath("sketches/bird.txt").c_str());
  auto filter = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
  filter->SetInputConnection(reader->GetOutputPort());
  filter->InflateOff();
  filter->RecordStagesOn();
  filter->Update();
  vtkIdType previous = -1;
  for (const std::string& name : vtkMedialSketchSkeleton::GetStageSkeletonNames()) {
    vtkPolyData* stage = filter->GetStageSkeleton(name);
    ASSERT_TRUE(stage) << name;
    EXPECT_TRUE(stage->GetPointData()->GetArray("Part") && stage->GetCellData()->GetArray("Branch")) << name;
    EXPECT_EQ(int(stage->GetPointData()->GetArray("Part")->GetRange()[1]), 2) << name;
    if (name == "connected")
      EXPECT_EQ(stage->GetNumberOfLines(), stage->GetNumberOfPoints() - 1) << "one tree";
    if (name == "pruned" || name == "merged") EXPECT_LE(stage->GetNumberOfPoints(), previous) << name;
    previous = stage->GetNumberOfPoints();
  }
  EXPECT_LE(filter->GetOutput(0)->GetNumberOfPoints(), previous) << "collapsing never adds a node";
  EXPECT_EQ(filter->GetStageSkeleton("nonsense"), nullptr);
}
