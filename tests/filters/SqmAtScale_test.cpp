// vtkMedialSQM at scale (issue 46): a 20,000-node branching chain whose tubes overlap wherever its walk
// comes back (data/make-long-chain.py, the kind a neuron tracing gives) meshed with the overlap count in
// seconds - the count took minutes when it was CGAL's whole-mesh test - and the count the same as CGAL's,
// also for a chain lying in one plane (every box sharing its z with all others).
#include "TestPaths.h"

#include "MedialErrorCollector.h"
#include "MedialMeshData.h"
#include "mesh/SelfIntersections.h"
#include "vtkMedialReader.h"
#include "vtkMedialSQM.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

// A chain made by data/make-long-chain.py, read back as a skeleton (empty if it could not be made).
vtkSmartPointer<vtkPolyData> longChain(int nodes, const std::string& options) {
  const std::string path = medial::test::scratchDir("SqmAtScale-" + std::to_string(nodes)) + "/chain.swc";
  const std::string command = "'" + medial::test::sourceDir() + "/data/make-long-chain.py' " +
                              std::to_string(nodes) + " '" + path + "' " + options;
  if (std::system(command.c_str()) != 0) return vtkSmartPointer<vtkPolyData>::New();
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
}

}  // namespace

TEST(SqmAtScale, TwentyThousandNodesWithOverlapsInSeconds) {
  const vtkSmartPointer<vtkPolyData> chain = longChain(20000, "--seed 2");
  ASSERT_EQ(chain->GetNumberOfPoints(), 20000);
  auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
  auto errors = medial::ErrorCollector::Watch(sqm);
  sqm->SetInputData(chain);
  sqm->CountOverlapsOn();
  const auto start = std::chrono::steady_clock::now();
  sqm->Update();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_FALSE(errors->HasErrors()) << errors->Joined();
  EXPECT_GT(sqm->GetOutput()->GetNumberOfPolys(), 150000);
  EXPECT_GT(sqm->GetOverlappingNodePairs(), 1000) << "the walk comes back across its own tubes";
  EXPECT_TRUE(sqm->GetOverlapCountComplete());
  // 0.4 s in a release build, a few seconds under the sanitizers; CGAL's count alone took 7 s at 10^5 nodes.
  EXPECT_LT(seconds, 30.0);
  std::printf("20,000 nodes: %lld faces, %d overlapping face pairs, %.2f s\n",
              static_cast<long long>(sqm->GetOutput()->GetNumberOfPolys()), sqm->GetOverlappingFacePairs(),
              seconds);
}

TEST(SqmAtScale, OverlapCountIsCgalsOnChains) {
  for (const char* options : {"--seed 3", "--seed 4 --flat"}) {
    const vtkSmartPointer<vtkPolyData> chain = longChain(3000, options);
    ASSERT_EQ(chain->GetNumberOfPoints(), 3000) << options;
    auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
    sqm->SetInputData(chain);
    sqm->CountOverlapsOn();
    sqm->Update();
    const auto cgal = medial::selfIntersectingFaces(medial::pointsOf(sqm->GetOutput()),
                                                    medial::polygonsOf(sqm->GetOutput()));
    EXPECT_GT(cgal.size(), 0u) << options;
    EXPECT_EQ(size_t(sqm->GetOverlappingFacePairs()), cgal.size()) << options;
  }
}
