// vtkMedialTskCenterline on the phantoms of data/volumes/tubes (data/make-tube-phantoms.py): error against
// the analytic axes, physical units through NIfTI, and errors on bad input.
#include "TestPaths.h"

#include "MedialAxisTicks.h"
#include "MedialErrorCollector.h"
#include "vtkMedialReader.h"
#include "vtkMedialTskCenterline.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>
#include <vector>

namespace {

vtkSmartPointer<vtkDataObject> read(const std::string& path) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutputDataObject(0);
}

double distanceToLine(const double p[3], vtkPolyData* line) {
  // Over the segments of every polyline cell (an axis file may hold several branches).
  double best = INFINITY;
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (line->GetLines()->InitTraversal(); line->GetLines()->GetNextCell(ids);) {
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k) {
      double a[3], b[3];
      line->GetPoint(ids->GetId(k), a);
      line->GetPoint(ids->GetId(k + 1), b);
      double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ap[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
      const double length2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
      const double t =
          std::clamp((ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / std::max(length2, 1e-300), 0.0, 1.0);
      const double d[3] = {a[0] + t * ab[0] - p[0], a[1] + t * ab[1] - p[1], a[2] + t * ab[2] - p[2]};
      best = std::min(best, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    }
  }
  return best;
}

struct Phantom {
  const char* name;
  double maxMeanError;  // mm, measured + margin
};

std::ostream& operator<<(std::ostream& os, const Phantom& p) { return os << p.name; }

class TubePhantoms : public ::testing::TestWithParam<Phantom> {};

TEST_P(TubePhantoms, CenterlineFollowsTheTrueAxis) {
  const std::string folder = medial::test::dataPath("volumes/tubes/");
  const auto imageData = read(folder + GetParam().name + ".nii.gz");  // keeps the data alive
  const auto axisData = read(folder + GetParam().name + "-axis.vtp");
  auto image = vtkImageData::SafeDownCast(imageData);
  auto axis = vtkPolyData::SafeDownCast(axisData);
  ASSERT_TRUE(image && axis);
  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  auto errors = medial::ErrorCollector::Watch(filter);
  filter->SetInputData(image);
  filter->SetLabel(1);
  filter->Update();
  ASSERT_FALSE(errors->HasErrors()) << errors->Joined();
  vtkPolyData* centerline = filter->GetOutput();
  ASSERT_EQ(centerline->GetNumberOfLines(), 1);
  ASSERT_TRUE(centerline->GetPointData()->GetArray("Radius"));
  vtkDataArray* arc = centerline->GetPointData()->GetArray("ArcLength");
  ASSERT_TRUE(arc);
  double sum = 0, worst = 0;
  for (vtkIdType i = 0; i < centerline->GetNumberOfPoints(); ++i) {
    double p[3];
    centerline->GetPoint(i, p);
    const double d = distanceToLine(p, axis);
    sum += d;
    worst = std::max(worst, d);
  }
  const double mean = sum / double(centerline->GetNumberOfPoints());
  std::printf("%s: %lld points, %.0f mm long, mean %.3f mm, max %.3f mm\n", GetParam().name,
              static_cast<long long>(centerline->GetNumberOfPoints()),
              arc->GetTuple1(arc->GetNumberOfTuples() - 1), mean, worst);
  EXPECT_LT(mean, GetParam().maxMeanError);
  EXPECT_LT(worst, 1.6);
}

// The goals of issue 45 on a tube whose radius grows twofold (taper, 1 mm voxels, a label) and on a noisy CT
// (ct-spiral, Hounsfield units, 0.75 mm voxels, followed with the defaults: its air): mean at most 0.09
// voxel and worst at most 0.3 voxel off the true axis, one radius at each end left out (as
// bench/tsk_bench.py measures; VMTK per the issue 0.094 / 0.23 mm and 0.067 / 0.20 mm). Measured 0.030 /
// 0.11 mm and 0.040 / 0.14 mm; the CT was 0.41 / 1.83 mm when its air below -1024 HU was left out.
TEST(TskCenterlineFilter, VaryingRadiusAndNoisyCtStayWithinATenthOfAVoxel) {
  const std::string folder = medial::test::dataPath("volumes/tubes/");
  // Name, the tube's radius at its first and last end, and whether it is a label volume.
  using Case = std::tuple<const char*, double, double, bool>;
  for (const auto& [name, firstRadius, lastRadius, label] :
       {Case{"taper", 4, 8, true}, Case{"ct-spiral", 4, 4, false}}) {
    const auto imageData = read(folder + name + ".nii.gz");
    const auto axisData = read(folder + name + "-axis.vtp");
    auto* image = vtkImageData::SafeDownCast(imageData);
    auto* axis = vtkPolyData::SafeDownCast(axisData);
    ASSERT_TRUE(image && axis) << name;
    auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
    filter->SetInputData(image);
    if (label) filter->SetLabel(1);
    filter->Update();
    vtkPolyData* line = filter->GetOutput();
    ASSERT_GT(line->GetNumberOfPoints(), 50) << name;
    double first[3], last[3];
    axis->GetPoint(0, first);
    axis->GetPoint(axis->GetNumberOfPoints() - 1, last);
    double sum = 0, worst = 0;
    int counted = 0;
    for (vtkIdType i = 0; i < line->GetNumberOfPoints(); ++i) {
      double p[3];
      line->GetPoint(i, p);
      if (std::sqrt(vtkMath::Distance2BetweenPoints(p, first)) < firstRadius ||
          std::sqrt(vtkMath::Distance2BetweenPoints(p, last)) < lastRadius)
        continue;
      const double d = distanceToLine(p, axis);
      sum += d, worst = std::max(worst, d), ++counted;
    }
    const double voxel = std::min({image->GetSpacing()[0], image->GetSpacing()[1], image->GetSpacing()[2]});
    EXPECT_LT(sum / counted, 0.09 * voxel) << name << ": mean mm off the true axis";
    EXPECT_LT(worst, 0.3 * voxel) << name << ": worst mm off the true axis";
  }
}

TEST(TskCenterlineFilter, CenteringBringsTheAxisCloserThanThePapersCurve) {
  const std::string folder = medial::test::dataPath("volumes/tubes/");
  const auto imageData = read(folder + "s-3d.nii.gz");
  const auto axisData = read(folder + "s-3d-axis.vtp");
  auto meanError = [&](int iterations) {
    auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
    filter->SetInputData(imageData);
    filter->SetLabel(1);
    filter->SetCenteringIterations(iterations);
    filter->Update();
    vtkPolyData* line = filter->GetOutput();
    double sum = 0;
    for (vtkIdType i = 0; i < line->GetNumberOfPoints(); ++i) {
      double p[3];
      line->GetPoint(i, p);
      sum += distanceToLine(p, vtkPolyData::SafeDownCast(axisData));
    }
    return sum / double(std::max<vtkIdType>(line->GetNumberOfPoints(), 1));
  };
  const double paper = meanError(0), centred = meanError(2);
  EXPECT_LT(centred, 0.5 * paper) << "paper's curve " << paper << " mm, centred " << centred << " mm";
}

INSTANTIATE_TEST_SUITE_P(Paper, TubePhantoms,
                         // Mean bounds with the default centering (2 passes); measured 0.06-0.15 mm.
                         ::testing::Values(Phantom{"u", 0.15}, Phantom{"s-plane", 0.2}, Phantom{"s-3d", 0.2},
                                           Phantom{"s-radius", 0.25}, Phantom{"helix", 0.15},
                                           Phantom{"helix-tight", 0.15}),
                         [](const ::testing::TestParamInfo<Phantom>& info) {
                           std::string name = info.param.name;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(TskCenterlineFilter, BadInputGivesErrorsAndEmptyOutput) {
  const auto data = read(medial::test::dataPath("volumes/tubes/u.nii.gz"));
  auto image = vtkImageData::SafeDownCast(data);
  ASSERT_TRUE(image);
  auto expectError = [&](vtkMedialTskCenterline* filter, const std::string& text) {
    auto errors = medial::ErrorCollector::Watch(filter);
    filter->SetInputData(image);
    filter->Update();
    EXPECT_NE(errors->Joined().find(text), std::string::npos) << errors->Joined();
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  };
  auto missingLabel = vtkSmartPointer<vtkMedialTskCenterline>::New();
  missingLabel->SetLabel(7);
  expectError(missingLabel, "no voxel has the label 7");
  auto outsideSeed = vtkSmartPointer<vtkMedialTskCenterline>::New();
  outsideSeed->SetSeed(0, 0, 0);
  expectError(outsideSeed, "lies outside the structure");
  auto nothingLeft = vtkSmartPointer<vtkMedialTskCenterline>::New();
  nothingLeft->SetThreshold(5, 9);
  expectError(nothingLeft, "nothing is left to follow");

  auto flat = vtkSmartPointer<vtkImageData>::New();
  flat->SetDimensions(20, 20, 1);
  flat->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto flatFilter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  auto errors = medial::ErrorCollector::Watch(flatFilter);
  flatFilter->SetInputData(flat);
  flatFilter->Update();
  EXPECT_NE(errors->Joined().find("a 3-D volume is needed"), std::string::npos) << errors->Joined();
}

}  // namespace

// Without a label or a threshold, a CT in Hounsfield units is followed through its air (the colon's), as
// with the window given, and a note says so; a CT with no air, and a volume whose non-zero voxels fill it,
// are refused with a message naming --threshold, never followed as a body-sized line.
TEST(TskCenterlineFilter, ACtWithoutThresholdFollowsItsAirAndSaysSo) {
  const std::string dir = medial::test::scratchDir("automatic-selection");
  ASSERT_TRUE(medial::test::makeColonPhantom(dir + " " + dir + "/ct.mha --no-dicom"));
  const auto ct = read(dir + "/ct.mha");
  auto automatic = vtkSmartPointer<vtkMedialTskCenterline>::New();
  auto windowed = vtkSmartPointer<vtkMedialTskCenterline>::New();
  windowed->SetThreshold(-1024, -600);
  for (vtkMedialTskCenterline* filter : {automatic.Get(), windowed.Get()}) {
    filter->SetInputData(ct);
    filter->Update();
  }
  EXPECT_STREQ(automatic->GetSelectionName(), "automatic");
  ASSERT_GT(automatic->GetOutput()->GetNumberOfPoints(), 100);
  ASSERT_EQ(automatic->GetOutput()->GetNumberOfPoints(), windowed->GetOutput()->GetNumberOfPoints());
  for (vtkIdType i = 0; i < automatic->GetOutput()->GetNumberOfPoints(); ++i) {
    double a[3], w[3];
    automatic->GetOutput()->GetPoint(i, a);
    windowed->GetOutput()->GetPoint(i, w);
    ASSERT_EQ(std::vector<double>(a, a + 3), std::vector<double>(w, w + 3)) << "point " << i;
  }
  ASSERT_GT(automatic->GetNumberOfNotes(), 0);
  EXPECT_NE(std::string(automatic->GetNote(0)).find("Hounsfield units"), std::string::npos)
      << automatic->GetNote(0);
}

TEST(TskCenterlineFilter, AVolumeWithNoTubeToFindIsRefusedWithAMessage) {
  const auto volume = [](int type, double background, double inner) {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(30, 30, 30);
    image->AllocateScalars(type, 1);
    for (int k = 0; k < 30; ++k)
      for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 30; ++i)
          image->SetScalarComponentFromDouble(
              i, j, k, 0, std::abs(i - 15) < 6 && std::abs(j - 15) < 6 ? inner : background);
    return image;
  };
  const auto refused = [](vtkImageData* image, const std::string& text) {
    auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
    auto errors = medial::ErrorCollector::Watch(filter);
    filter->SetInputData(image);
    filter->Update();
    EXPECT_NE(errors->Joined().find(text), std::string::npos) << errors->Joined();
    EXPECT_NE(errors->Joined().find("--threshold"), std::string::npos) << errors->Joined();
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  };
  // A CT (soft tissue at 40 HU, fat-like -300 HU inside) with nothing in the air window.
  refused(volume(VTK_SHORT, 40, -300), "no voxel in the air window");
  // Unsigned voxels, non-zero nearly everywhere (a CT stored with an offset, or a body mask).
  refused(volume(VTK_UNSIGNED_SHORT, 1100, 0), "fill 87 % of the volume");
  // The same as a label volume with a tube of ones in zeros: followed as before.
  auto tube = vtkSmartPointer<vtkMedialTskCenterline>::New();
  tube->SetInputData(volume(VTK_UNSIGNED_CHAR, 0, 1));
  tube->Update();
  EXPECT_GT(tube->GetOutput()->GetNumberOfPoints(), 2);
}

TEST(TskCenterlineFilter, SectionsMeasureTheChangingRadius) {
  // s-radius: an S whose radius goes from 3 to 7 mm; the sections' mean diameter at both ends.
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(medial::test::dataPath("volumes/tubes/s-radius.nii.gz").c_str());
  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  filter->SetInputConnection(reader->GetOutputPort());
  filter->SetLabel(1);
  filter->ComputeSectionsOn();
  filter->SetSectionSpacing(2.0);
  filter->Update();
  auto* profile = vtkTable::SafeDownCast(filter->GetOutputDataObject(1));
  ASSERT_NE(profile, nullptr);
  ASSERT_GT(profile->GetNumberOfRows(), 20);
  auto* low = vtkDataArray::SafeDownCast(profile->GetColumnByName("MinDiameter"));
  auto* high = vtkDataArray::SafeDownCast(profile->GetColumnByName("MaxDiameter"));
  ASSERT_TRUE(low && high);
  // The min diameter: where the S bends, the perpendicular plane cuts the tube obliquely and the max
  // diameter jumps (up to 46 mm here), as it would on a real bend.
  auto meanDiameter = [&](vtkIdType first, vtkIdType last) {
    double sum = 0;
    for (vtkIdType i = first; i < last; ++i) sum += low->GetComponent(i, 0);
    return sum / double(last - first);
  };
  // Skip the rounded end caps: rows 3..7 from each end.
  const vtkIdType rows = profile->GetNumberOfRows();
  double a = meanDiameter(3, 8), b = meanDiameter(rows - 8, rows - 3);
  if (a > b) std::swap(a, b);
  // 6 to 16 mm in from the ends the radius is about 3.3 and 6.5 mm (it changes linearly along the S).
  EXPECT_NEAR(a, 6.5, 1.0);
  EXPECT_NEAR(b, 13.0, 1.0);
  EXPECT_GT(high->GetComponent(rows / 2, 0), low->GetComponent(rows / 2, 0) - 1e-9);
  // And the diameter follows the arc length almost linearly (|correlation| > 0.9).
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  for (vtkIdType i = 3; i < rows - 3; ++i) {
    const double x = double(i), y = low->GetComponent(i, 0);
    sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y;
  }
  const double n = double(rows - 6);
  const double correlation = (n * sxy - sx * sy) / std::sqrt((n * sxx - sx * sx) * (n * syy - sy * sy));
  EXPECT_GT(std::fabs(correlation), 0.9);
  auto* terrain = vtkImageData::SafeDownCast(filter->GetOutputDataObject(2));
  ASSERT_NE(terrain, nullptr);
  EXPECT_EQ(terrain->GetDimensions()[0], 72);
  EXPECT_EQ(terrain->GetDimensions()[1], rows);
  ASSERT_NE(terrain->GetPointData()->GetArray("WallDistance"), nullptr);
}

TEST(TskCenterlineFilter, BranchingTreeGivesOnePolylinePerBranch) {
  // tree.nii.gz: a trunk splitting into two branches, the right one splitting again (5 true branches).
  const std::string folder = medial::test::dataPath("volumes/tubes/");
  const auto imageData = read(folder + "tree.nii.gz");
  const auto axisData = read(folder + "tree-axis.vtp");
  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  auto errors = medial::ErrorCollector::Watch(filter);
  filter->SetInputData(imageData);
  filter->SetLabel(1);
  filter->DetectBranchesOn();
  filter->Update();
  ASSERT_FALSE(errors->HasErrors()) << errors->Joined();
  vtkPolyData* tree = filter->GetOutput();
  ASSERT_EQ(tree->GetNumberOfLines(), 5);
  vtkDataArray* parent = tree->GetCellData()->GetArray("ParentBranch");
  ASSERT_NE(parent, nullptr);
  // The topology: the root, two children of the root, two children of one of those.
  std::map<int, int> children;
  for (vtkIdType c = 0; c < 5; ++c) ++children[int(parent->GetComponent(c, 0))];
  EXPECT_EQ(children[-1], 1);
  EXPECT_EQ(children[0], 2);
  int grandParents = 0;
  for (const auto& [p, n] : children) grandParents += p > 0 && n == 2;
  EXPECT_EQ(grandParents, 1);
  // Every point lies near the true tree, and each child starts on its parent (a shared junction point).
  double sum = 0, worst = 0;
  for (vtkIdType i = 0; i < tree->GetNumberOfPoints(); ++i) {
    double p[3];
    tree->GetPoint(i, p);
    const double d = distanceToLine(p, vtkPolyData::SafeDownCast(axisData));
    sum += d;
    worst = std::max(worst, d);
  }
  EXPECT_LT(sum / double(tree->GetNumberOfPoints()), 0.5);
  EXPECT_LT(worst, 2.5);
  // Through the junctions (within 3 branch radii, 12 mm, of where the true axes meet) the line stays within
  // 0.3 of the branch radius (4 mm) of the true axis, and closer than VMTK's worst on this tree (0.50 mm,
  // issue 45): 0.42 mm measured; 0.58 with one junction curve leaving along the parent, 1.91 when the
  // parent ran on up the middle of the junction's blob (src/centerline/Junctions.h).
  const double junctions[2][3] = {{40, 30, 42}, {62, 30, 70}};
  double worstAtJunctions = 0;
  for (vtkIdType i = 0; i < tree->GetNumberOfPoints(); ++i) {
    double p[3];
    tree->GetPoint(i, p);
    for (const auto& j : junctions)
      if (std::hypot(p[0] - j[0], p[1] - j[1], p[2] - j[2]) < 12)
        worstAtJunctions = std::max(worstAtJunctions, distanceToLine(p, vtkPolyData::SafeDownCast(axisData)));
  }
  EXPECT_LT(worstAtJunctions, 0.3 * 4) << "mm off the true axis at a junction";
  EXPECT_LT(worstAtJunctions, 0.5) << "mm off the true axis at a junction: VMTK's worst is 0.50";
  auto ids = vtkSmartPointer<vtkIdList>::New();
  std::vector<std::vector<vtkIdType>> cells;
  for (tree->GetLines()->InitTraversal(); tree->GetLines()->GetNextCell(ids);)
    cells.emplace_back(ids->begin(), ids->end());
  for (size_t c = 0; c < cells.size(); ++c) {
    const int p = int(parent->GetComponent(vtkIdType(c), 0));
    if (p < 0) continue;
    const auto& own = cells[c];
    const auto& theirs = cells[size_t(p)];
    EXPECT_NE(std::find(theirs.begin(), theirs.end(), own.front()), theirs.end()) << "branch " << c;
  }
  // Without DetectBranches: one polyline, as in the paper.
  filter->DetectBranchesOff();
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfLines(), 1);
}

// Collapsed and fluid-filled segments (medial-make-colon-phantom --collapse N --gap MM [--fluid]): the colon
// air falls into N + 1 parts; the centerline is still one polyline over the whole colon, bridged across
// each gap: every point of the true axis lies near it, the parts' points stay on the axis, and the points
// marked Bridged lie in the gaps (and in every gap).
struct Collapse {
  int count;
  double gap;  // mm along the axis
  bool fluid;
};

std::ostream& operator<<(std::ostream& os, const Collapse& c) {
  return os << c.count << " x " << c.gap << " mm" << (c.fluid ? " fluid" : "");
}

class CollapsedColon : public ::testing::TestWithParam<Collapse> {};

// The true axis ("x y z radius" lines with the arc length added) of a phantom.
std::vector<std::array<double, 5>> readAxis(const std::string& path) {
  std::ifstream file(path);
  std::string row;
  std::vector<std::array<double, 5>> axis;
  while (std::getline(file, row)) {
    if (row.empty() || row[0] == '#') continue;
    std::array<double, 5> a{};
    std::istringstream(row) >> a[0] >> a[1] >> a[2] >> a[3];
    if (!axis.empty())
      a[4] = axis.back()[4] + std::hypot(a[0] - axis.back()[0], a[1] - axis.back()[1], a[2] - axis.back()[2]);
    axis.push_back(a);
  }
  return axis;
}

TEST_P(CollapsedColon, OneCenterlineBridgesEveryGap) {
  const Collapse c = GetParam();
  const std::string dir = medial::test::scratchDir("collapsed-" + std::to_string(c.count) + "-" +
                                                   std::to_string(int(c.gap)) + (c.fluid ? "-fluid" : ""));
  ASSERT_TRUE(medial::test::makeColonPhantom(dir + " " + dir + "/ct.mha --no-dicom --collapse " +
                                             std::to_string(c.count) + " --gap " + std::to_string(c.gap) +
                                             (c.fluid ? " --fluid" : "")));
  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  filter->SetInputData(read(dir + "/ct.mha"));
  filter->SetThreshold(-1024, -600);
  filter->ComputeSectionsOn();
  filter->SetSectionSpacing(2);
  filter->Update();
  vtkPolyData* line = filter->GetOutput();
  ASSERT_EQ(line->GetNumberOfCells(), 1) << "one polyline";
  EXPECT_EQ(filter->GetPartsFollowed(), c.count + 1);
  ASSERT_EQ(filter->GetNumberOfBridgedGaps(), c.count);
  for (int i = 0; i < c.count; ++i)
    EXPECT_NEAR(filter->GetBridgedGap(i), c.gap, 0.25 * c.gap + 2.5) << "gap " << i;
  ASSERT_GT(filter->GetNumberOfNotes(), 0);
  EXPECT_NE(std::string(filter->GetNote(0)).find("joined across"), std::string::npos) << filter->GetNote(0);

  // Gaps along the true axis, then the axis' points: each near the centerline (the whole length covered).
  std::vector<std::pair<double, double>> gaps;
  std::ifstream gapFile(dir + "/gaps.txt");
  std::string row;
  while (std::getline(gapFile, row))
    if (!row.empty() && row[0] != '#') {
      double start = 0, end = 0;
      std::istringstream(row) >> start >> end;
      gaps.push_back({start, end});
    }
  ASSERT_EQ(int(gaps.size()), c.count);
  const auto axis = readAxis(dir + "/axis.txt");
  auto axisLine = vtkSmartPointer<vtkPolyData>::New();
  {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->InsertNextCell(vtkIdType(axis.size()));
    for (const auto& a : axis) cells->InsertCellPoint(points->InsertNextPoint(a[0], a[1], a[2]));
    axisLine->SetPoints(points);
    axisLine->SetLines(cells);
  }
  double farthest = 0;
  for (const auto& a : axis) {
    const double p[3] = {a[0], a[1], a[2]};
    // The ends: a TSK line stops about a radius short of the caps.
    if (a[4] < 15 || a[4] > axis.back()[4] - 15) continue;
    farthest = std::max(farthest, distanceToLine(p, line));
  }
  EXPECT_LT(farthest, 8.0) << "mm from the true axis to the centerline (the bridges cut the bends' corners)";

  vtkDataArray* bridged = line->GetPointData()->GetArray("Bridged");
  ASSERT_NE(bridged, nullptr);
  std::vector<int> bridgedInGap(gaps.size(), 0);
  double onParts = 0;
  int partPoints = 0;
  for (vtkIdType i = 0; i < line->GetNumberOfPoints(); ++i) {
    double p[3];
    line->GetPoint(i, p);
    if (bridged->GetComponent(i, 0) == 0) {
      onParts += distanceToLine(p, axisLine);
      ++partPoints;
      continue;
    }
    // A bridged point: its nearest axis point lies in a gap (within 3 mm of its ends).
    size_t nearest = 0;
    for (size_t k = 1; k < axis.size(); ++k)
      if (std::hypot(axis[k][0] - p[0], axis[k][1] - p[1], axis[k][2] - p[2]) <
          std::hypot(axis[nearest][0] - p[0], axis[nearest][1] - p[1], axis[nearest][2] - p[2]))
        nearest = k;
    bool inGap = false;
    for (size_t g = 0; g < gaps.size(); ++g)
      if (axis[nearest][4] > gaps[g].first - 3 && axis[nearest][4] < gaps[g].second + 3) {
        inGap = true;
        ++bridgedInGap[g];
      }
    EXPECT_TRUE(inGap) << "a bridged point at arc " << axis[nearest][4] << " mm of the axis";
  }
  for (size_t g = 0; g < gaps.size(); ++g) EXPECT_GT(bridgedInGap[g], 0) << "gap " << g << " is not bridged";
  EXPECT_LT(onParts / partPoints, 0.6) << "mean mm from the axis of the points in the colon's lumen";

  // The profile marks the bridged sections, and has no measure there.
  vtkTable* profile = vtkTable::SafeDownCast(filter->GetOutputDataObject(1));
  vtkDataArray* rows = vtkDataArray::SafeDownCast(profile->GetColumnByName("Bridged"));
  vtkDataArray* diameter = vtkDataArray::SafeDownCast(profile->GetColumnByName("MaxDiameter"));
  ASSERT_TRUE(rows && diameter);
  int bridgedRows = 0;
  for (vtkIdType r = 0; r < rows->GetNumberOfTuples(); ++r)
    if (rows->GetComponent(r, 0) != 0) {
      ++bridgedRows;
      EXPECT_TRUE(std::isnan(diameter->GetComponent(r, 0)));
    }
  EXPECT_GE(bridgedRows, c.count);
}

INSTANTIATE_TEST_SUITE_P(TskCenterlineFilter, CollapsedColon,
                         ::testing::Values(Collapse{1, 3, false}, Collapse{1, 20, false},
                                           Collapse{2, 12, false}, Collapse{3, 8, false},
                                           Collapse{2, 12, true}));

// A gap longer than MaxGap: two polylines and a note; MaxGap 0: the largest part only (the paper's input).
TEST(TskCenterlineFilter, AGapLongerThanTheMaximumSplitsTheCenterline) {
  const std::string dir = medial::test::scratchDir("collapsed-long");
  ASSERT_TRUE(medial::test::makeColonPhantom(dir + " " + dir + "/ct.mha --no-dicom --collapse 1 --gap 60"));
  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  filter->SetInputData(read(dir + "/ct.mha"));
  filter->SetThreshold(-1024, -600);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 2);
  EXPECT_EQ(filter->GetNumberOfBridgedGaps(), 0);
  bool noted = false;
  for (int i = 0; i < filter->GetNumberOfNotes(); ++i)
    noted = noted || std::string(filter->GetNote(i)).find("longer than the maximum gap") != std::string::npos;
  EXPECT_TRUE(noted);
  const vtkIdType bothParts = filter->GetOutput()->GetNumberOfPoints();

  filter->SetMaxGap(80);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 1);
  EXPECT_EQ(filter->GetNumberOfBridgedGaps(), 1);

  filter->SetMaxGap(0);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 1);
  EXPECT_EQ(filter->GetPartsFollowed(), 1);
  EXPECT_LT(filter->GetOutput()->GetNumberOfPoints(), 0.8 * bothParts) << "the largest part only";
}

// The paper's intermediate results (RecordStages) on the helix: every structure voxel in the order with its
// layer and cluster; the primitive centerline inside the structure, one cluster per point, its layers
// rising from P0; the TSK models over t, whose curve (the paper's own) the centring then improves on.
TEST(TskCenterlineFilter, RecordedStagesAreThePapersIntermediates) {
  const std::string folder = medial::test::dataPath("volumes/tubes/");
  const auto imageData = read(folder + "helix.nii.gz");
  const auto axisData = read(folder + "helix-axis.vtp");  // kept: the cast below does not own it
  auto* axis = vtkPolyData::SafeDownCast(axisData);
  ASSERT_TRUE(axis);
  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  filter->SetInputData(imageData);
  filter->SetLabel(1);
  filter->RecordStagesOn();
  filter->Update();
  vtkPolyData* voxels = filter->GetStageData("voxels");
  vtkPolyData* primitive = filter->GetStageData("primitive");
  vtkPolyData* model = filter->GetStageData("tsk-model");
  ASSERT_TRUE(voxels && primitive && model);
  EXPECT_EQ(voxels->GetNumberOfPoints(), filter->GetStructureVoxels());
  EXPECT_EQ(primitive->GetNumberOfPoints(), filter->GetPrimitiveCenterlinePoints());
  vtkDataArray* cluster = voxels->GetPointData()->GetArray("Cluster");
  vtkDataArray* layer = voxels->GetPointData()->GetArray("Layer");
  ASSERT_TRUE(cluster && layer && voxels->GetPointData()->GetArray("T"));
  EXPECT_EQ(int(cluster->GetRange()[1]), primitive->GetNumberOfPoints() - 1);
  EXPECT_EQ(layer->GetRange()[0], 0.0) << "P0's layer";
  vtkDataArray* primitiveLayer = primitive->GetPointData()->GetArray("Layer");
  for (vtkIdType k = 1; k < primitive->GetNumberOfPoints(); ++k)
    EXPECT_GT(primitiveLayer->GetComponent(k, 0), primitiveLayer->GetComponent(k - 1, 0)) << k;
  // Inside: each chosen point is a voxel of the structure (label 1 there).
  auto* image = vtkImageData::SafeDownCast(imageData);
  for (vtkIdType k = 0; k < primitive->GetNumberOfPoints(); ++k) {
    double p[3], index[3];
    primitive->GetPoint(k, p);
    image->TransformPhysicalPointToContinuousIndex(p, index);
    EXPECT_EQ(image->GetScalarComponentAsDouble(int(std::lround(index[0])), int(std::lround(index[1])),
                                                int(std::lround(index[2])), 0),
              1.0)
        << k;
  }
  // The layers and clusters as label volumes (for the slice views): as many labelled voxels as the
  // structure has, layer 0 at P0.
  vtkImageData* labels = filter->GetStageLabels();
  ASSERT_TRUE(labels);
  vtkDataArray* layers = labels->GetPointData()->GetArray("Layer");
  ASSERT_TRUE(layers && labels->GetPointData()->GetArray("Cluster"));
  vtkIdType labelled = 0;
  for (vtkIdType v = 0; v < layers->GetNumberOfTuples(); ++v) labelled += layers->GetComponent(v, 0) >= 0;
  EXPECT_EQ(labelled, filter->GetStructureVoxels());
  double p0[3], p0Index[3];
  primitive->GetPoint(0, p0);
  labels->TransformPhysicalPointToContinuousIndex(p0, p0Index);
  EXPECT_EQ(labels->GetScalarComponentAsDouble(int(std::lround(p0Index[0])), int(std::lround(p0Index[1])),
                                               int(std::lround(p0Index[2])), 0),
            0.0);
  vtkDataArray* t = model->GetPointData()->GetArray("T");
  for (vtkIdType k = 1; k < model->GetNumberOfPoints(); ++k)
    EXPECT_GT(t->GetComponent(k, 0), t->GetComponent(k - 1, 0));
  // The paper's curve (before centring) against the output (centred), both measured against the true axis.
  const auto meanError = [&](vtkPolyData* line) {
    double sum = 0;
    for (vtkIdType i = 0; i < line->GetNumberOfPoints(); ++i) sum += distanceToLine(line->GetPoint(i), axis);
    return sum / double(std::max<vtkIdType>(line->GetNumberOfPoints(), 1));
  };
  EXPECT_LT(meanError(filter->GetOutput()), meanError(model));
}

// The charts' ticks are round: steps of 1, 2 or 5 times a power of ten, labels without stray digits (the
// profile chart showed 13.2, 26.3, ...).
TEST(AxisTicks, RoundStepsAndLabels) {
  const medial::AxisTicks diameters = medial::roundTicks(0, 26.3, 5);
  EXPECT_EQ(diameters.step, 5);
  EXPECT_EQ(diameters.values, (std::vector<double>{0, 5, 10, 15, 20, 25}));
  EXPECT_EQ(diameters.label(25), "25");
  const medial::AxisTicks wall = medial::roundTicks(7.7, 12.3, 5);
  EXPECT_EQ(wall.step, 1);
  EXPECT_EQ(wall.values.front(), 8);
  EXPECT_EQ(wall.values.back(), 12);
  const medial::AxisTicks fine = medial::roundTicks(0.1, 0.33, 5);
  EXPECT_DOUBLE_EQ(fine.step, 0.05);
  EXPECT_EQ(fine.label(fine.values.front()), "0.10");
  EXPECT_EQ(medial::roundTicks(0, 1000, 6).step, 200);
  EXPECT_EQ(medial::roundTicks(3, 3, 5).values.size(), 1u);
}
