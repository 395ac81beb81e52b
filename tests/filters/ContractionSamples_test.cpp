// vtkMedialContractionSkeleton on the real CGAL sample meshes (scripts/fetch-samples): the skeleton is
// connected, has as many independent cycles as the mesh has genus, and lies inside the mesh.
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "MedialMeshData.h"
#include "mesh/InsideTest.h"
#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialReader.h"

#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <cstdio>
#include <functional>
#include <numeric>

namespace {

struct Sample {
  const char* name;
  int genus;
  bool closed;  // inside tests are meaningful for closed meshes only
  // Edge midpoints allowed outside: 0, except where the surface intersects itself (man: 848 triangle pairs
  // where the fingers of the fists and the toes interpenetrate), so that inside is ambiguous there.
  int midpointsOutside = 0;
};

std::ostream& operator<<(std::ostream& os, const Sample& s) { return os << s.name; }

class ContractionSamples : public ::testing::TestWithParam<Sample> {};

TEST_P(ContractionSamples, ConnectedWithItsCyclesAndInside) {
  const Sample sample = GetParam();
  const std::string path = medial::test::externalPath(std::string("cgal/meshes/") + sample.name + ".off");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " missing: run scripts/fetch-samples";
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(path.c_str());
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  auto errors = medial::ErrorCollector::Watch(filter);
  filter->SetInputConnection(reader->GetOutputPort());
  filter->Update();
  ASSERT_FALSE(errors->HasErrors()) << errors->Joined();
  vtkPolyData* skeleton = filter->GetOutput(0);
  const vtkIdType nodes = skeleton->GetNumberOfPoints();
  ASSERT_GT(nodes, 1);
  // The target, 30, or a few more with a note where fewer would take a bone out of the mesh.
  if (nodes != 30) EXPECT_FALSE(filter->GetSelectionNote().empty()) << nodes << " nodes";
  EXPECT_LE(nodes, 33);

  // Components and independent cycles of the skeleton graph.
  std::vector<vtkIdType> parent(static_cast<size_t>(nodes));
  std::iota(parent.begin(), parent.end(), 0);
  std::function<vtkIdType(vtkIdType)> find = [&](vtkIdType x) {
    return parent[size_t(x)] == x ? x : parent[size_t(x)] = find(parent[size_t(x)]);
  };
  auto ids = vtkSmartPointer<vtkIdList>::New();
  std::vector<std::pair<vtkIdType, vtkIdType>> edges;
  vtkCellArray* lines = skeleton->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(ids);) {
    edges.emplace_back(ids->GetId(0), ids->GetId(1));
    parent[size_t(find(ids->GetId(0)))] = find(ids->GetId(1));
  }
  long components = 0;
  for (vtkIdType i = 0; i < nodes; ++i) components += find(i) == i;
  const long cycles = long(edges.size()) - long(nodes) + components;
  EXPECT_EQ(components, 1);
  EXPECT_EQ(cycles, sample.genus);

  if (!sample.closed) return;
  auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
  triangles->SetInputConnection(reader->GetOutputPort());
  triangles->Update();
  const medial::InsideTest inside(medial::toTriangleMesh(triangles->GetOutput()));
  int nodesInside = 0, midpointsInside = 0;
  for (vtkIdType i = 0; i < nodes; ++i)
    nodesInside += inside.contains(Eigen::Vector3d(skeleton->GetPoint(i)));
  for (const auto& [a, b] : edges)
    midpointsInside += inside.contains(
        0.5 * (Eigen::Vector3d(skeleton->GetPoint(a)) + Eigen::Vector3d(skeleton->GetPoint(b))));
  std::printf("%s: %d of %lld nodes and %d of %zu edge midpoints inside, %ld cycles (genus %d)\n",
              sample.name, nodesInside, static_cast<long long>(nodes), midpointsInside, edges.size(), cycles,
              sample.genus);
  EXPECT_EQ(nodesInside, nodes);
  EXPECT_GE(midpointsInside, long(edges.size()) - sample.midpointsOutside);
}

INSTANTIATE_TEST_SUITE_P(
    Cgal, ContractionSamples,
    ::testing::Values(Sample{"armadillo", 0, true}, Sample{"man", 0, true, 1}, Sample{"hand", 0, true},
                      Sample{"elephant", 3, true}, Sample{"femur", 2, true}, Sample{"knot1", 1, true},
                      Sample{"mannequin-devil", 0, false},
                      // above the default vertex budget: decimated before the contraction
                      Sample{"diplodocus", 0, true}, Sample{"bunny00", 0, true},
                      Sample{"refined_elephant", 3, true}),
    [](const ::testing::TestParamInfo<Sample>& info) {
      std::string name = info.param.name;
      std::replace(name.begin(), name.end(), '-', '_');
      return name;
    });

// --nodes N gives N nodes (issue 44: the selection stopped at 44 on the man for 15 or 30), or at most
// max(2, 10 %) more with a note saying why.
class NodesAskedFor : public ::testing::TestWithParam<std::pair<const char*, int>> {};

TEST_P(NodesAskedFor, TheSkeletonHasThem) {
  const auto [name, target] = GetParam();
  const std::string path = medial::test::externalPath(std::string("cgal/meshes/") + name + ".off");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " missing: run scripts/fetch-samples";
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(path.c_str());
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  auto errors = medial::ErrorCollector::Watch(filter, /*warningsToo=*/true);
  filter->SetInputConnection(reader->GetOutputPort());
  filter->SetTargetNodes(target);
  filter->Update();
  const vtkIdType nodes = filter->GetOutput(0)->GetNumberOfPoints();
  EXPECT_LE(std::abs(nodes - target), std::max(2, target / 10)) << name;
  const bool noted = filter->GetOutput(0)->GetFieldData()->GetAbstractArray("SelectionNote") != nullptr;
  EXPECT_EQ(noted, nodes != target) << filter->GetSelectionNote();
  EXPECT_EQ(errors->HasErrors(), nodes != target) << errors->Joined();  // the note as a warning
}

INSTANTIATE_TEST_SUITE_P(Cgal, NodesAskedFor,
                         ::testing::Values(std::make_pair("man", 15), std::make_pair("man", 40),
                                           std::make_pair("dino", 15), std::make_pair("dino", 40),
                                           std::make_pair("armadillo", 15), std::make_pair("camel", 40)),
                         [](const auto& info) {
                           return std::string(info.param.first) + "_" + std::to_string(info.param.second);
                         });

}  // namespace
