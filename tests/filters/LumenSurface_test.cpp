// The TSK filter's lumen surface (ComputeSurface, output port 3): closed, within its triangle budget, on
// the colon phantom's true wall, and holding the centerline - all of it but the bridges across collapsed
// segments, where there is no lumen.
#include "TestPaths.h"
#include "TrueAxis.h"

#include "vtkMedialReader.h"
#include "vtkMedialTskCenterline.h"

#include <vtkDataArray.h>
#include <vtkFeatureEdges.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkSelectEnclosedPoints.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace {

// |distance to the true axis - its radius there| (mm) for every `step`-th point of the surface.
std::vector<double> wallErrors(vtkPolyData* surface, const std::vector<medial::test::AxisPoint>& axis,
                               int step) {
  const std::vector<medial::test::Point3> line = medial::test::pointsOf(axis);
  std::vector<double> errors;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); i += step) {
    medial::test::Point3 p;
    surface->GetPoint(i, p.data());
    size_t nearest = 0;
    const double d = medial::test::distanceToPolyline(p, line, &nearest);
    errors.push_back(std::fabs(d - axis[nearest].radius));
  }
  std::sort(errors.begin(), errors.end());
  return errors;
}

}  // namespace

TEST(LumenSurface, ClosedOnTheWallAndHoldingTheCenterline) {
  const std::string dir = medial::test::scratchDir("lumen-surface");
  ASSERT_TRUE(medial::test::makeColonPhantom(dir + " " + dir + "/ct.mha --no-dicom --collapse 2 --gap 12"));
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName((dir + "/ct.mha").c_str());
  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  filter->SetInputConnection(reader->GetOutputPort());
  filter->ComputeSurfaceOn();
  filter->SetSurfaceTriangles(60000);
  filter->Update();
  vtkPolyData* line = filter->GetOutput();
  auto* surface = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(3));
  ASSERT_NE(surface, nullptr);
  ASSERT_GT(line->GetNumberOfPoints(), 300);
  EXPECT_LE(surface->GetNumberOfPolys(), 60000);
  EXPECT_GT(surface->GetNumberOfPolys(), 30000);

  auto edges = vtkSmartPointer<vtkFeatureEdges>::New();
  edges->SetInputData(surface);
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  EXPECT_EQ(edges->GetOutput()->GetNumberOfLines(), 0) << "closed and manifold";
  auto parts = vtkSmartPointer<vtkPolyDataConnectivityFilter>::New();
  parts->SetInputData(surface);
  parts->SetExtractionModeToAllRegions();
  parts->Update();
  EXPECT_EQ(parts->GetNumberOfExtractedRegions(), 3) << "the colon in three parts between two collapses";

  auto enclosed = vtkSmartPointer<vtkSelectEnclosedPoints>::New();
  enclosed->SetInputData(line);
  enclosed->SetSurfaceData(surface);
  enclosed->Update();
  vtkDataArray* inside = enclosed->GetOutput()->GetPointData()->GetArray("SelectedPoints");
  vtkDataArray* bridged = line->GetPointData()->GetArray("Bridged");
  int lumenPoints = 0, lumenInside = 0, bridgePoints = 0, bridgeInside = 0;
  for (vtkIdType i = 0; i < line->GetNumberOfPoints(); ++i) {
    const bool in = inside->GetComponent(i, 0) != 0;
    if (bridged->GetComponent(i, 0) != 0)
      ++bridgePoints, bridgeInside += in;
    else
      ++lumenPoints, lumenInside += in;
  }
  EXPECT_EQ(lumenInside, lumenPoints) << "the centerline inside its lumen";
  EXPECT_GT(bridgePoints, 10);
  EXPECT_LT(bridgeInside, bridgePoints / 4) << "the bridges cross tissue, outside the lumen";

  // On the true wall: the median within a third of a voxel (0.7 mm), where the folds and polyps do not
  // reach; measured 0.10-0.13 mm.
  const std::vector<double> errors = wallErrors(surface, medial::test::readAxisFile(dir + "/axis.txt"), 7);
  EXPECT_LT(errors[errors.size() / 2], 0.25) << "median |distance to the true wall| (mm)";
}

TEST(LumenSurface, NotAskedNotMade) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(medial::test::dataPath("volumes/tubes/u.nii.gz").c_str());
  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  filter->SetInputConnection(reader->GetOutputPort());
  filter->SetLabel(1);
  filter->Update();
  EXPECT_GT(filter->GetOutput()->GetNumberOfPoints(), 20);
  EXPECT_EQ(vtkPolyData::SafeDownCast(filter->GetOutputDataObject(3))->GetNumberOfPolys(), 0);
  filter->ComputeSurfaceOn();
  filter->Update();
  EXPECT_GT(vtkPolyData::SafeDownCast(filter->GetOutputDataObject(3))->GetNumberOfPolys(), 1000);
}
