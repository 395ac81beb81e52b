// vtkMedialContractionSkeleton does not depend on the mesh's units or place (issue 44): the CGAL samples
// scaled by 0.01 and 100 and moved ten diagonals away give the same skeleton, mapped back - the same node
// count, every node within 2 % of the diagonal of a node of the original's and the other way round.
//
// DISABLED until issue 44 is mended: it fails today, and not through a constant in absolute units - the
// pipeline is already scale-free in exact arithmetic (the same mesh scaled by 0.01 in double precision,
// or by 2^-7 in float, gives the man's skeleton; a normalised frame around the whole pipeline changed no
// number). What moves it is the float rounding of the scaled or moved coordinates, 1e-7 of the diagonal.
// Since the selection gives the nodes asked for, the node counts agree; the places do not (7-20 % of the
// diagonal apart). Stage by stage (stage recording, each run mapped back): meshes within the vertex
// budget come out the same (cow, dino, elephant, bull scaled: every stage within 1e-5); above it, CGAL's
// greedy quadric decimation picks other vertices (camel, bull moved, man: coarse meshes 0.3-0.7 of the
// diagonal apart row by row), and the man's contraction itself turns 2e-8 into 4e-3 even undecimated (his
// self-intersecting fists). The mend is a decimation and a contraction stable under noise that small.
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialReader.h"

#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <filesystem>
#include <vector>

namespace {

std::vector<Eigen::Vector3d> nodesOf(vtkPolyData* skeleton) {
  std::vector<Eigen::Vector3d> nodes;
  for (vtkIdType i = 0; i < skeleton->GetNumberOfPoints(); ++i) {
    double p[3];
    skeleton->GetPoint(i, p);
    nodes.emplace_back(p[0], p[1], p[2]);
  }
  return nodes;
}

// The skeleton's nodes of `mesh` with every point mapped by x -> x * scale + offset, mapped back.
std::vector<Eigen::Vector3d> skeletonNodes(vtkPolyData* mesh, double scale, const Eigen::Vector3d& offset) {
  auto moved = vtkSmartPointer<vtkPolyData>::New();
  moved->DeepCopy(mesh);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();  // as a file of the moved mesh would hold them
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) {
    double p[3];
    mesh->GetPoint(i, p);
    points->InsertNextPoint(p[0] * scale + offset.x(), p[1] * scale + offset.y(), p[2] * scale + offset.z());
  }
  moved->SetPoints(points);
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  auto errors = medial::ErrorCollector::Watch(filter);
  filter->SetInputData(moved);
  filter->Update();
  EXPECT_FALSE(errors->HasErrors()) << errors->Joined();
  std::vector<Eigen::Vector3d> nodes = nodesOf(filter->GetOutput(0));
  for (Eigen::Vector3d& node : nodes) node = (node - offset) / scale;
  return nodes;
}

double farthestFromNearest(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to) {
  double worst = 0;
  for (const Eigen::Vector3d& a : from) {
    double nearest = INFINITY;
    for (const Eigen::Vector3d& b : to) nearest = std::min(nearest, (a - b).norm());
    worst = std::max(worst, nearest);
  }
  return worst;
}

class ContractionInvariance : public ::testing::TestWithParam<const char*> {};

TEST_P(ContractionInvariance, DISABLED_TheSameSkeletonInAnyUnitAndPlace) {
  const std::string path = medial::test::externalPath(std::string("cgal/meshes/") + GetParam() + ".off");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " missing: run scripts/fetch-samples";
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  ASSERT_TRUE(mesh);
  const double diagonal = mesh->GetLength();
  const std::vector<Eigen::Vector3d> reference = skeletonNodes(mesh, 1, Eigen::Vector3d::Zero());
  const Eigen::Vector3d far = Eigen::Vector3d(10, -7, 3).normalized() * 10 * diagonal;
  for (const auto& [scale, offset] : {std::make_pair(0.01, Eigen::Vector3d::Zero().eval()),
                                      std::make_pair(100.0, Eigen::Vector3d::Zero().eval()),
                                      std::make_pair(1.0, far), std::make_pair(0.01, (far * 0.01).eval())}) {
    const std::vector<Eigen::Vector3d> nodes = skeletonNodes(mesh, scale, offset);
    EXPECT_EQ(nodes.size(), reference.size())
        << "x" << scale << " moved " << offset.norm() / (scale * diagonal);
    EXPECT_LT(farthestFromNearest(nodes, reference), 0.02 * diagonal) << "x" << scale;
    EXPECT_LT(farthestFromNearest(reference, nodes), 0.02 * diagonal) << "x" << scale;
  }
}

INSTANTIATE_TEST_SUITE_P(Cgal, ContractionInvariance, ::testing::Values("man", "camel", "armadillo", "cow"));

}  // namespace
