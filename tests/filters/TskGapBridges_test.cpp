// A bridge across a collapsed stretch with no lumen in it follows the tube's course: the helix phantom
// with 12 mm of its tube removed (a collapsed segment in a label volume). The least-cost path alone ran
// as the bend's chord, 2.3 mm (2.3 voxels) off the true axis with no true-axis point of the gap within a
// voxel of it; the Hermite curve continuing both ends' directions stays within 1.5 mm.
#include "TestPaths.h"
#include "TrueAxis.h"

#include "vtkMedialReader.h"
#include "vtkMedialTskCenterline.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace {

using Point = medial::test::Point3;
using medial::test::distance;
using medial::test::distanceToPolyline;

vtkSmartPointer<vtkDataObject> read(const std::string& path) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutputDataObject(0);
}

}  // namespace

TEST(TskGapBridges, ABridgeWithoutLumenFollowsTheHelix) {
  const std::string folder = medial::test::dataPath("volumes/tubes/");
  const vtkSmartPointer<vtkDataObject> imageData = read(folder + "helix.nii.gz"),
                                       axisObject = read(folder + "helix-axis.vtp");
  auto* image = vtkImageData::SafeDownCast(imageData);
  auto* axisData = vtkPolyData::SafeDownCast(axisObject);
  ASSERT_NE(image, nullptr);
  ASSERT_NE(axisData, nullptr);
  std::vector<Point> axis;
  std::vector<double> arc;
  auto ids = vtkSmartPointer<vtkIdList>::New();
  axisData->GetLines()->InitTraversal();
  axisData->GetLines()->GetNextCell(ids);
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
    Point p;
    axisData->GetPoint(ids->GetId(k), p.data());
    arc.push_back(axis.empty() ? 0.0 : arc.back() + distance(axis.back(), p));
    axis.push_back(p);
  }
  // The collapse: every voxel of the tube whose nearest axis point lies in the 12 mm from mid-length.
  const double from = 0.5 * arc.back(), to = from + 12;
  vtkDataArray* labels = image->GetPointData()->GetScalars();
  int removed = 0;
  for (vtkIdType v = 0; v < image->GetNumberOfPoints(); ++v) {
    if (labels->GetComponent(v, 0) == 0) continue;
    Point p;
    image->GetPoint(v, p.data());
    size_t nearest = 0;
    for (size_t k = 1; k < axis.size(); ++k)
      if (distance(p, axis[k]) < distance(p, axis[nearest])) nearest = k;
    if (arc[nearest] >= from && arc[nearest] <= to) labels->SetComponent(v, 0, 0), ++removed;
  }
  ASSERT_GT(removed, 100);
  image->Modified();

  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  filter->SetInputData(image);
  filter->SetLabel(1);
  filter->Update();
  vtkPolyData* line = filter->GetOutput();
  ASSERT_EQ(line->GetNumberOfCells(), 1);
  ASSERT_EQ(filter->GetNumberOfBridgedGaps(), 1);
  vtkDataArray* bridged = line->GetPointData()->GetArray("Bridged");
  std::vector<Point> points(size_t(line->GetNumberOfPoints()));
  double worst = 0;
  int bridgePoints = 0;
  for (vtkIdType i = 0; i < line->GetNumberOfPoints(); ++i) {
    line->GetPoint(i, points[size_t(i)].data());
    if (bridged->GetComponent(i, 0) == 0) continue;
    ++bridgePoints;
    worst = std::max(worst, distanceToPolyline(points[size_t(i)], axis));
  }
  EXPECT_GT(bridgePoints, 5);
  EXPECT_LT(worst, 1.5) << "mm off the true axis on the bridge (0.98 measured; the least-cost path 2.27)";
  int covered = 0, inGap = 0;
  for (size_t k = 0; k < axis.size(); ++k)
    if (arc[k] >= from && arc[k] <= to) ++inGap, covered += distanceToPolyline(axis[k], points) <= 1.0;
  EXPECT_GT(covered, inGap / 2)
      << "of the gap's true axis within a voxel of the line (0.65 measured, 0.00 before)";
}
