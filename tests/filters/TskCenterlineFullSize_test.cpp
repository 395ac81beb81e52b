// The TSK centerline on a full-size CT (512 x 512 x 400, a colon about 1 m long) with two collapsed
// segments, with the defaults a user runs: outside the gaps the line stays within 0.3 of the local radius
// of the true axis (it hugged the wall after the second gap, 0.67 radius off, when the parts' lines stopped
// up to 3 radii short of their caps), and it runs to within one radius of both ends of the colon (it
// started 1.7 radii inside the rectum).
#include "TestPaths.h"

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

struct AxisPoint {
  std::array<double, 3> p;
  double radius;
};

std::vector<AxisPoint> readAxis(const std::string& path) {
  std::vector<AxisPoint> axis;
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line))
    if (!line.empty() && line[0] != '#') {
      AxisPoint a{};
      std::istringstream(line) >> a.p[0] >> a.p[1] >> a.p[2] >> a.radius;
      axis.push_back(a);
    }
  return axis;
}

double distance(const double* a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// Distance from `p` to the true axis polyline, and the radius at its nearest point.
double distanceToAxis(const double p[3], const std::vector<AxisPoint>& axis, double& radius) {
  double best = INFINITY;
  for (size_t k = 0; k + 1 < axis.size(); ++k) {
    double ab[3], ap[3], t = 0, length2 = 0;
    for (int i = 0; i < 3; ++i) {
      ab[i] = axis[k + 1].p[size_t(i)] - axis[k].p[size_t(i)];
      ap[i] = p[i] - axis[k].p[size_t(i)];
      t += ab[i] * ap[i];
      length2 += ab[i] * ab[i];
    }
    t = length2 > 0 ? std::clamp(t / length2, 0.0, 1.0) : 0.0;
    const double d = std::hypot(ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]);
    if (d < best) best = d, radius = axis[k].radius;
  }
  return best;
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
  const std::vector<AxisPoint> axis = readAxis(dir + "/axis.txt");
  ASSERT_GT(axis.size(), 100u);

  double first[3], last[3];
  line->GetPoint(0, first);
  line->GetPoint(line->GetNumberOfPoints() - 1, last);
  EXPECT_LT(distance(first, axis.front().p), axis.front().radius) << "the line starts at the rectum's end";
  EXPECT_LT(distance(last, axis.back().p), axis.back().radius) << "and ends at the cecum's";

  vtkDataArray* bridged = line->GetPointData()->GetArray("Bridged");
  double worst = 0;
  int measured = 0;
  for (vtkIdType i = 0; i < line->GetNumberOfPoints(); ++i) {
    double p[3], radius = 1;
    line->GetPoint(i, p);
    if (bridged->GetComponent(i, 0) != 0) continue;
    if (distance(p, axis.front().p) < axis.front().radius || distance(p, axis.back().p) < axis.back().radius)
      continue;
    worst = std::max(worst, distanceToAxis(p, axis, radius) / radius);
    ++measured;
  }
  EXPECT_GT(measured, 1000);
  EXPECT_LT(worst, 0.3) << "of the local radius off the true axis, outside the gaps (0.17 measured)";
}
