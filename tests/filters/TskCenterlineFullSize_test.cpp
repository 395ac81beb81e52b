// The TSK centerline on a full-size CT (512 x 512 x 400, a colon about 1 m long) with two collapsed
// segments, with the defaults a user runs: outside the gaps the line stays within 0.3 of the local radius
// of the true axis (it hugged the wall after the second gap, 0.67 radius off, when the parts' lines stopped
// up to 3 radii short of their caps), and it runs to within one radius of both ends of the colon (it
// started 1.7 radii inside the rectum).
#include "TestPaths.h"
#include "TrueAxis.h"

#include "vtkMedialReader.h"
#include "vtkMedialTskCenterline.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace {

using medial::test::distance;

// Distance from `p` to the true axis, and the radius there.
double distanceToAxis(const medial::test::Point3& p, const std::vector<medial::test::AxisPoint>& axis,
                      const std::vector<medial::test::Point3>& line, double& radius) {
  size_t nearest = 0;
  const double d = medial::test::distanceToPolyline(p, line, &nearest);
  radius = axis[nearest].radius;
  return d;
}

}  // namespace

TEST(TskCenterlineFullSize, CollapsedColonStaysOnItsAxisFromEndToEnd) {
  const std::string dir = medial::test::scratchDir("tsk-full-size");
  ASSERT_TRUE(medial::test::makeColonPhantom(dir + " " + dir +
                                             "/ct.mha --size 512x512x400 --collapse 2 --gap 12 --no-dicom"));
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName((dir + "/ct.mha").c_str());
  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();  // the defaults: the CT's air, chosen
  filter->SetInputConnection(reader->GetOutputPort());
  filter->Update();
  vtkPolyData* line = filter->GetOutput();
  ASSERT_EQ(line->GetNumberOfCells(), 1);
  ASSERT_EQ(filter->GetNumberOfBridgedGaps(), 2);
  const std::vector<medial::test::AxisPoint> axis = medial::test::readAxisFile(dir + "/axis.txt");
  ASSERT_GT(axis.size(), 100u);
  const std::vector<medial::test::Point3> axisLine = medial::test::pointsOf(axis);

  medial::test::Point3 first, last;
  line->GetPoint(0, first.data());
  line->GetPoint(line->GetNumberOfPoints() - 1, last.data());
  EXPECT_LT(distance(first, axis.front().p), axis.front().radius) << "the line starts at the rectum's end";
  EXPECT_LT(distance(last, axis.back().p), axis.back().radius) << "and ends at the cecum's";

  vtkDataArray* bridged = line->GetPointData()->GetArray("Bridged");
  double worst = 0;
  int measured = 0;
  for (vtkIdType i = 0; i < line->GetNumberOfPoints(); ++i) {
    medial::test::Point3 p;
    double radius = 1;
    line->GetPoint(i, p.data());
    if (bridged->GetComponent(i, 0) != 0) continue;
    if (distance(p, axis.front().p) < axis.front().radius || distance(p, axis.back().p) < axis.back().radius)
      continue;
    worst = std::max(worst, distanceToAxis(p, axis, axisLine, radius) / radius);
    ++measured;
  }
  EXPECT_GT(measured, 1000);
  EXPECT_LT(worst, 0.3) << "of the local radius off the true axis, outside the gaps (0.17 measured)";
}
