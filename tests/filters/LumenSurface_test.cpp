// The TSK filter's lumen surface (ComputeSurface, output port 3): closed, within its triangle budget, on
// the colon phantom's true wall, and holding the centerline - all of it but the bridges across collapsed
// segments, where there is no lumen.
#include "TestPaths.h"

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

std::vector<std::array<double, 4>> readAxis(const std::string& path) {  // x y z radius per line
  std::vector<std::array<double, 4>> axis;
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line))
    if (!line.empty() && line[0] != '#') {
      std::array<double, 4> p{};
      std::istringstream(line) >> p[0] >> p[1] >> p[2] >> p[3];
      axis.push_back(p);
    }
  return axis;
}

// |distance to the nearest true axis point - its radius| (mm) for every `step`-th point of the surface.
std::vector<double> wallErrors(vtkPolyData* surface, const std::vector<std::array<double, 4>>& axis,
                               int step) {
  std::vector<double> errors;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); i += step) {
    double p[3], best = INFINITY, radius = 0;
    surface->GetPoint(i, p);
    for (const auto& a : axis) {
      const double d = std::hypot(p[0] - a[0], p[1] - a[1], p[2] - a[2]);
      if (d < best) best = d, radius = a[3];
    }
    errors.push_back(std::fabs(best - radius));
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
  const std::vector<double> errors = wallErrors(surface, readAxis(dir + "/axis.txt"), 7);
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
