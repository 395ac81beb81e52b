// Skeleton I/O (docs/ARCHITECTURE.md §4): SWC and VTP round trips, and each validation error through the
// readers.
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "vtkMedialPolyDataWriter.h"
#include "vtkMedialReader.h"
#include "vtkMedialSWCReader.h"
#include "vtkMedialSWCWriter.h"
#include "vtkMedialSkeletonValidator.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <set>

namespace {

using medial::test::scratchDir;

// A small tree: 0 root - 1 - 2, and 1 - 3 (node 1 is a branch).
vtkSmartPointer<vtkPolyData> makeTree(bool withRoot = true) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0.5, 0);
  points->InsertNextPoint(2, 0, 0.25);
  points->InsertNextPoint(1, 2, -1e-3);
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (auto [a, b] : {std::pair<vtkIdType, vtkIdType>{0, 1}, {1, 2}, {1, 3}}) {
    const vtkIdType ids[2] = {a, b};
    lines->InsertNextCell(2, ids);
  }
  auto radius = vtkSmartPointer<vtkDoubleArray>::New();
  radius->SetName("Radius");
  for (double r : {0.5, 0.25, 0.125, 1.0 / 3.0}) radius->InsertNextValue(r);
  auto tree = vtkSmartPointer<vtkPolyData>::New();
  tree->SetPoints(points);
  tree->SetLines(lines);
  tree->GetPointData()->AddArray(radius);
  if (withRoot) {
    auto root = vtkSmartPointer<vtkIntArray>::New();
    root->SetName("Root");
    root->InsertNextValue(0);
    tree->GetFieldData()->AddArray(root);
  }
  return tree;
}

// Undirected edges as (min, max) pairs of node positions, to compare skeletons independent of ids.
std::set<std::pair<std::string, std::string>> edgeSet(vtkPolyData* skeleton) {
  auto key = [&](vtkIdType id) {
    double p[3];
    skeleton->GetPoint(id, p);
    char text[128];
    std::snprintf(text, sizeof text, "%.9g %.9g %.9g", p[0], p[1], p[2]);
    return std::string(text);
  };
  std::set<std::pair<std::string, std::string>> edges;
  auto ids = vtkSmartPointer<vtkIdList>::New();
  vtkCellArray* lines = skeleton->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(ids);) {
    auto a = key(ids->GetId(0)), b = key(ids->GetId(1));
    edges.insert(a < b ? std::make_pair(a, b) : std::make_pair(b, a));
  }
  return edges;
}

double radiusAt(vtkPolyData* skeleton, const double where[3]) {
  for (vtkIdType i = 0; i < skeleton->GetNumberOfPoints(); ++i) {
    double p[3];
    skeleton->GetPoint(i, p);
    if (std::abs(p[0] - where[0]) + std::abs(p[1] - where[1]) + std::abs(p[2] - where[2]) < 1e-12)
      return skeleton->GetPointData()->GetArray("Radius")->GetComponent(i, 0);
  }
  return -1;
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Reads `path` with vtkMedialReader; returns the error message (empty on success).
std::string readError(const std::string& path, vtkSmartPointer<vtkDataObject>* output = nullptr) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  auto errors = medial::ErrorCollector::Watch(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  if (output) *output = reader->GetOutputDataObject(0);
  return errors->HasErrors() ? std::string(reader->GetErrorMessage()) : std::string();
}

bool writeWith(const std::string& path, vtkPolyData* data, std::string* error = nullptr) {
  auto writer = vtkSmartPointer<vtkMedialPolyDataWriter>::New();
  auto errors = medial::ErrorCollector::Watch(writer);
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  const int ok = writer->Write();
  if (error) *error = errors->Joined();
  return ok && !errors->HasErrors();
}

// Writes `skeleton` to dir/name with vtkMedialPolyDataWriter and reads it back with vtkMedialReader.
vtkSmartPointer<vtkPolyData> roundTrip(vtkPolyData* skeleton, const std::string& dir,
                                       const std::string& name) {
  const std::string path = dir + "/" + name;
  EXPECT_TRUE(writeWith(path, skeleton));
  vtkSmartPointer<vtkDataObject> read;
  EXPECT_EQ(readError(path, &read), "");
  return vtkPolyData::SafeDownCast(read);
}

}  // namespace

TEST(SkeletonIO, SwcRoundTripKeepsNodesRadiiEdgesAndRoot) {
  auto tree = makeTree();
  vtkSmartPointer<vtkPolyData> skeleton = roundTrip(tree, scratchDir("swc-round-trip"), "tree.swc");
  ASSERT_NE(skeleton, nullptr);
  EXPECT_EQ(skeleton->GetNumberOfPoints(), 4);
  EXPECT_EQ(edgeSet(skeleton), edgeSet(tree));
  for (vtkIdType i = 0; i < 4; ++i) {
    double p[3];
    tree->GetPoint(i, p);
    EXPECT_DOUBLE_EQ(radiusAt(skeleton, p), tree->GetPointData()->GetArray("Radius")->GetComponent(i, 0));
  }
  ASSERT_NE(skeleton->GetFieldData()->GetArray("Root"), nullptr);
  double rootPoint[3];
  skeleton->GetPoint(static_cast<vtkIdType>(skeleton->GetFieldData()->GetArray("Root")->GetComponent(0, 0)),
                     rootPoint);
  EXPECT_EQ(rootPoint[0], 0.0);
  EXPECT_NE(skeleton->GetPointData()->GetArray("NodeType"), nullptr);
}

TEST(SkeletonIO, VtpRoundTripKeepsEverything) {
  auto tree = makeTree();
  vtkSmartPointer<vtkPolyData> skeleton = roundTrip(tree, scratchDir("vtp-round-trip"), "tree.vtp");
  ASSERT_NE(skeleton, nullptr);
  EXPECT_EQ(edgeSet(skeleton), edgeSet(tree));
  for (vtkIdType i = 0; i < 4; ++i)
    EXPECT_DOUBLE_EQ(skeleton->GetPointData()->GetArray("Radius")->GetComponent(i, 0),
                     tree->GetPointData()->GetArray("Radius")->GetComponent(i, 0));
  EXPECT_EQ(skeleton->GetFieldData()->GetArray("Root")->GetComponent(0, 0), 0);
}

TEST(SkeletonIO, SwcWithArbitraryIdsAndCommentsIsRead) {
  const std::string dir = scratchDir("swc-ids");
  writeText(dir + "/ids.swc",
            "# comment\n\n 10 1 0 0 0 1.5 -1\n20 3 1 0 0 1 10\n  # indented comment\n30 3 2 0 0 0.5 20\n"
            "40 3 1 1 0 0.5 20\n");
  vtkSmartPointer<vtkDataObject> read;
  ASSERT_EQ(readError(dir + "/ids.swc", &read), "");
  auto* skeleton = vtkPolyData::SafeDownCast(read);
  EXPECT_EQ(skeleton->GetNumberOfPoints(), 4);
  EXPECT_EQ(skeleton->GetNumberOfLines(), 3);
  EXPECT_EQ(skeleton->GetPointData()->GetArray("SWCType")->GetComponent(1, 0), 3);
  EXPECT_EQ(skeleton->GetPointData()->GetArray("NodeType")->GetComponent(1, 0), 2);  // branch
}

struct BadSwc {
  const char* name;
  const char* text;
  const char* expected;  // a piece of the error message
};

class SwcErrors : public ::testing::TestWithParam<BadSwc> {};

TEST_P(SwcErrors, AreReportedWithFileAndLine) {
  const BadSwc& bad = GetParam();
  const std::string path = scratchDir(std::string("swc-") + bad.name) + "/bad.swc";
  writeText(path, bad.text);
  vtkSmartPointer<vtkDataObject> read;
  const std::string error = readError(path, &read);
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find(bad.expected), std::string::npos) << error;
  auto* output = vtkPolyData::SafeDownCast(read);
  EXPECT_TRUE(!output || output->GetNumberOfPoints() == 0);
}

INSTANTIATE_TEST_SUITE_P(
    SkeletonIO, SwcErrors,
    ::testing::Values(BadSwc{"nan", "1 1 0 0 0 1 -1\n2 3 nan 0 0 1 1\n",
                             ":2: node 1 has non-finite coordinates"},
                      BadSwc{"negative-radius", "1 1 0 0 0 1 -1\n2 3 1 0 0 -2 1\n", "radius -2"},
                      BadSwc{"zero-radius", "1 1 0 0 0 0 -1\n", "radius 0"},
                      BadSwc{"self-loop", "1 1 0 0 0 1 -1\n2 3 1 0 0 1 2\n", "its own parent"},
                      BadSwc{"missing-parent", "1 1 0 0 0 1 -1\n2 3 1 0 0 1 7\n", "parent 7 of node 2"},
                      BadSwc{"cycle", "1 1 0 0 0 1 3\n2 3 1 0 0 1 1\n3 3 2 0 0 1 2\n",
                             ":1: the parents of node 1 lead back"},
                      BadSwc{"duplicate-id", "1 1 0 0 0 1 -1\n1 3 1 0 0 1 -1\n", "node id 1 appears twice"},
                      BadSwc{"malformed", "1 1 0 0 0 1 -1\n2 3 1 0 zero 1 1\n", ":2: expected"},
                      BadSwc{"short-line", "1 1 0 0 0 1\n", ":1: expected"},
                      BadSwc{"empty", "# nothing here\n", "no nodes"}),
    [](const ::testing::TestParamInfo<BadSwc>& info) {
      std::string name = info.param.name;
      for (char& c : name)
        if (c == '-') c = '_';
      return name;
    });

TEST(SkeletonIO, VtpValidationErrorsAreReported) {
  const std::string dir = scratchDir("vtp-errors");
  struct Case {
    const char* name;
    std::function<void(vtkPolyData*)> spoil;
    const char* expected;
  };
  const std::vector<Case> cases = {
      {"nan", [](vtkPolyData* s) { s->GetPoints()->SetPoint(2, std::nan(""), 0, 0); },
       "non-finite coordinates"},
      {"radius", [](vtkPolyData* s) { s->GetPointData()->GetArray("Radius")->SetComponent(3, 0, 0.0); },
       "node 3 has radius 0"},
      {"self-loop",
       [](vtkPolyData* s) {
         const vtkIdType ids[2] = {2, 2};
         s->GetLines()->InsertNextCell(2, ids);
       },
       "self-loop on node 2"},
      {"out-of-range",
       [](vtkPolyData* s) {
         const vtkIdType ids[2] = {1, 9};
         s->GetLines()->InsertNextCell(2, ids);
       },
       "joins nodes 1 and 9"},
      {"root", [](vtkPolyData* s) { s->GetFieldData()->GetArray("Root")->SetComponent(0, 0, 12); },
       "root 12 is not a node id"},
  };
  for (const Case& c : cases) {
    auto tree = makeTree();
    c.spoil(tree);
    // The VTP writer stores whatever it is given; the reader is the one that validates.
    const std::string path = dir + "/" + c.name + ".vtp";
    ASSERT_TRUE(writeWith(path, tree)) << c.name;
    const std::string error = readError(path);
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.name << ": " << error;
    EXPECT_NE(error.find(path), std::string::npos) << error;
  }
}

TEST(SkeletonIO, SwcWriterRefusesCyclesAndMissingRadius) {
  const std::string dir = scratchDir("swc-writer-errors");
  auto cyclic = makeTree();
  const vtkIdType ids[2] = {2, 3};
  cyclic->GetLines()->InsertNextCell(2, ids);
  std::string error;
  EXPECT_FALSE(writeWith(dir + "/cycle.swc", cyclic, &error));
  EXPECT_NE(error.find("cycle"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(dir + "/cycle.swc"));

  auto noRadius = makeTree();
  noRadius->GetPointData()->RemoveArray("Radius");
  EXPECT_FALSE(writeWith(dir + "/no-radius.swc", noRadius, &error));
  EXPECT_NE(error.find("Radius"), std::string::npos) << error;
  // Nothing left behind, not even the temporary file.
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(SkeletonIO, FailedWriteKeepsThePreviousFile) {
  const std::string dir = scratchDir("atomic-write");
  const std::string path = dir + "/tree.swc";
  writeText(path, "1 1 0 0 0 1 -1\n");
  auto cyclic = makeTree();
  const vtkIdType ids[2] = {0, 3};
  cyclic->GetLines()->InsertNextCell(2, ids);
  EXPECT_FALSE(writeWith(path, cyclic));
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(text, "1 1 0 0 0 1 -1\n");
}

TEST(SkeletonIO, ValidatorPassesValidSkeletonAndAddsNodeType) {
  auto validator = vtkSmartPointer<vtkMedialSkeletonValidator>::New();
  validator->SetInputData(makeTree());
  validator->RequireRadiusOn();
  validator->Update();
  EXPECT_EQ(validator->GetProblemCount(), 0);
  vtkDataArray* types = validator->GetOutput()->GetPointData()->GetArray("NodeType");
  ASSERT_NE(types, nullptr);
  EXPECT_EQ(types->GetComponent(0, 0), 0);  // leaf
  EXPECT_EQ(types->GetComponent(1, 0), 2);  // branch
}

TEST(SkeletonIO, ValidatorRejectsMeshesAndEmptyOutput) {
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  auto validator = vtkSmartPointer<vtkMedialSkeletonValidator>::New();
  auto errors = medial::ErrorCollector::Watch(validator);
  validator->SetInputConnection(sphere->GetOutputPort());
  validator->Update();
  EXPECT_TRUE(errors->HasErrors());
  EXPECT_NE(errors->Joined().find("polygons"), std::string::npos) << errors->Joined();
  EXPECT_EQ(validator->GetOutput()->GetNumberOfPoints(), 0);

  auto noRadius = makeTree();
  noRadius->GetPointData()->RemoveArray("Radius");
  validator->SetInputData(noRadius);
  validator->RequireRadiusOn();
  errors->Clear();
  validator->Update();
  EXPECT_NE(errors->Joined().find("Radius"), std::string::npos) << errors->Joined();
}

TEST(SkeletonIO, BundledSamplesAreValidSkeletons) {
  for (const char* name : {"skeletons/figure.vtp", "skeletons/hand.swc"}) {
    vtkSmartPointer<vtkDataObject> read;
    EXPECT_EQ(readError(medial::test::dataPath(name), &read), "") << name;
    auto* skeleton = vtkPolyData::SafeDownCast(read);
    ASSERT_NE(skeleton, nullptr);
    EXPECT_GT(skeleton->GetNumberOfLines(), 10) << name;
    EXPECT_NE(skeleton->GetPointData()->GetArray("Radius"), nullptr) << name;
  }
}
