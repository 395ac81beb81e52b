// Benchmark: vtkMedialSQM against vtkTubeFilter (the tube VTK users reach for) on the same skeletons in one
// run. Per skeleton: nodes, output faces, quad share and median time of each, the ratio tube / SQM, and
// the open (border) and non-manifold edges of each output - SQM's is one closed surface, the tube filter's
// is one open tube per line cell. The paper's Table 1: 74 ms for 150 nodes (goal: >= 10x faster).
// Then the paper's Table 1 (stage times and counts) and the refined rows: K = 2, 3, 4 levels per skeleton,
// time, faces, quad share, intersecting pairs. Last, the skeleton editor's rows (SQM paper §6): the octopus
// split to 150 nodes, one leaf dragged in 40 steps, the mesh rebuilt at every step: base mesh (goal: one
// frame, 16 ms), K = 2 while dragging (no fold repair; goal 100 ms), K = 2 on release (with the repair),
// beside the tube filter rebuilding its tubes of the same skeleton. Without SKELETON arguments, last the
// --union rows on the overlapping skeletons (crossing tubes, the dense tree), and the rows at scale:
// long branching chains whose tubes overlap (data/make-long-chain.py, 1,000 to 100,000 nodes), meshed with
// the overlap count as `medial sqm` does, beside vtkTubeFilter on the same chain and CGAL's
// self-intersection test on the same mesh (what the count was before issue 46); `--scale` runs only those.
//   medial_bench_sqm [--repeat N] [--scale] [SKELETON...]   (default: data/skeletons/sqm/*.vtp, figure, hand)
#include "MedialMeshData.h"
#include "MedialSkeletonData.h"
#include "MedianSeconds.h"
#include "skeleton/SkeletonEdits.h"
#include "mesh/SelfIntersections.h"
#include "vtkMedialMeshTopology.h"
#include "vtkMedialReader.h"
#include "vtkMedialSQM.h"

#include <vtkCell.h>
#include <vtkCleanPolyData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTubeFilter.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace {

struct Summary {
  vtkIdType faces = 0, border = 0, nonManifold = 0;
  double quadShare = 0;
};

Summary summarize(vtkPolyData* mesh) {
  auto topology = vtkSmartPointer<vtkMedialMeshTopology>::New();
  topology->SetInputData(mesh);
  topology->Update();
  Summary s;
  s.faces = mesh->GetNumberOfCells();
  s.border = topology->GetNumberOfBorderEdges();
  s.nonManifold = topology->GetNumberOfNonManifoldEdges();
  vtkIdType quads = 0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    quads += mesh->GetCell(c)->GetNumberOfPoints() == 4;
  s.quadShare = s.faces ? double(quads) / double(s.faces) : 0;
  return s;
}

// Faces of the mesh that cut another (CGAL's exact test), counted in pairs.
size_t intersectingPairs(vtkPolyData* mesh) {
  std::vector<Eigen::Vector3d> points;
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p) {
    double x[3];
    mesh->GetPoint(p, x);
    points.emplace_back(x[0], x[1], x[2]);
  }
  std::vector<std::vector<int64_t>> faces;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c) {
    vtkIdType count;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, count, ids);
    faces.emplace_back(ids, ids + count);
  }
  return medial::selfIntersectingFaces(points, faces).size();
}

// Stage 8, refinement: K levels of the paper's tessellation projected onto the swept spheres, with the
// fold repair (on by default), per skeleton and K = 2, 3, 4.
void refinedRows(const std::vector<std::string>& paths, int repeat) {
  // The first run at a level also pays for its fresh memory (page faults: 40k at K = 4 on the octopus, about
  // half of that run here); the GUI's slider and editor run it again and again: the median is of the runs
  // after it, the first has a column of its own.
  std::printf("\nSQM refined (--subdivide K, fold repair on), first run and median of the %d after it\n",
              repeat);
  std::printf("%-16s %2s | %9s %9s %8s %6s %6s %6s\n", "skeleton", "K", "first ms", "SQM ms", "faces",
              "quads", "border", "pairs");
  for (const std::string& path : paths) {
    auto reader = vtkSmartPointer<vtkMedialReader>::New();
    reader->SetFileName(path.c_str());
    auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
    sqm->SetInputConnection(reader->GetOutputPort());
    for (int levels = 2; levels <= 4; ++levels) {
      sqm->SetSubdivisionLevels(levels);
      const auto run = [&] {
        sqm->Modified();
        sqm->Update();
      };
      const double first = medianSeconds(1, run);
      const double seconds = medianSeconds(repeat, run);
      const Summary s = summarize(sqm->GetOutput());
      const std::string name = path.substr(path.find_last_of('/') + 1);
      std::printf("%-16s %2d | %9.1f %9.1f %8lld %5.0f%% %6lld %6zu\n", name.c_str(), levels, 1e3 * first,
                  1e3 * seconds, static_cast<long long>(s.faces), 100 * s.quadShare,
                  static_cast<long long>(s.border), intersectingPairs(sqm->GetOutput()));
    }
  }
}

// Overlapping tubes (issue 27): the mesh as SQM makes it and with --union, on the overlapping skeletons
// (capsule ends, so that the volume compares with the swept spheres' union): time of each, the union's
// share, faces, quad share and intersecting pairs before and after.
void unionRows(int repeat) {
  std::printf("\nSQM --union on overlapping tubes (capsules), median of %d runs\n", repeat);
  std::printf("%-16s %2s | %9s %8s %6s | %9s %9s %8s %6s %6s %6s\n", "skeleton", "K", "SQM ms", "faces",
              "pairs", "union ms", "of which", "faces", "quads", "border", "pairs");
  const std::string data = std::string(MEDIAL_SOURCE_DIR) + "/data/skeletons/";
  for (const char* name : {"overlapping/crossing.vtp", "overlapping/dense-tree.vtp"}) {
    auto reader = vtkSmartPointer<vtkMedialReader>::New();
    reader->SetFileName((data + name).c_str());
    auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
    sqm->SetInputConnection(reader->GetOutputPort());
    sqm->CapsulesOn();
    for (int levels : {0, 2}) {
      sqm->SetSubdivisionLevels(levels);
      sqm->UnionOff();
      const double plainSeconds = medianSeconds(repeat, [&] {
        sqm->Modified();
        sqm->Update();
      });
      const Summary plain = summarize(sqm->GetOutput());
      const size_t plainPairs = intersectingPairs(sqm->GetOutput());
      sqm->UnionOn();
      const double unionSeconds = medianSeconds(repeat, [&] {
        sqm->Modified();
        sqm->Update();
      });
      const Summary united = summarize(sqm->GetOutput());
      std::printf("%-16s %2d | %9.1f %8lld %6zu | %9.1f %8.0f%% %8lld %5.0f%% %6lld %6zu\n",
                  std::strrchr(name, '/') + 1, levels, 1e3 * plainSeconds,
                  static_cast<long long>(plain.faces), plainPairs, 1e3 * unionSeconds,
                  100 * sqm->GetStageSeconds("union") / unionSeconds, static_cast<long long>(united.faces),
                  100 * united.quadShare, static_cast<long long>(united.border),
                  intersectingPairs(sqm->GetOutput()));
    }
  }
}

// The paper's Table 1 on this machine: stage times (ms, median) and counts per skeleton, unrefined.
void table1(const std::vector<std::string>& paths, int repeat) {
  std::printf("\nTable 1 (the paper's stages, ms, median of %d runs; counts)\n", repeat);
  std::printf("%-14s", "skeleton");
  for (const std::string& stage : vtkMedialSQM::GetStageNames()) std::printf(" %8.8s", stage.c_str());
  std::printf(" | %6s %6s %5s %6s %6s %5s %9s\n", "branch", "conn", "leaf", "merged", "quads", "tris",
              "irregular");
  for (const std::string& path : paths) {
    auto reader = vtkSmartPointer<vtkMedialReader>::New();
    reader->SetFileName(path.c_str());
    auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
    sqm->SetInputConnection(reader->GetOutputPort());
    const std::vector<std::string> stages = vtkMedialSQM::GetStageNames();
    std::vector<std::vector<double>> seconds(stages.size());
    for (int run = 0; run < repeat; ++run) {
      sqm->Modified();
      sqm->Update();
      for (size_t k = 0; k < stages.size(); ++k) seconds[k].push_back(sqm->GetStageSeconds(stages[k]));
    }
    const std::string name = path.substr(path.find_last_of('/') + 1);
    std::printf("%-14s", name.c_str());
    for (auto& s : seconds) {
      std::nth_element(s.begin(), s.begin() + s.size() / 2, s.end());
      std::printf(" %8.3f", 1e3 * s[s.size() / 2]);
    }
    std::printf(" | %6d %6d %5d %6d %6d %5d %9d\n", sqm->GetBranchNodes(), sqm->GetConnectionNodes(),
                sqm->GetLeafNodes(), sqm->GetMergedNodes(), sqm->GetQuads(), sqm->GetTriangles(),
                sqm->GetIrregularVertices());
  }
}

}  // namespace

// The skeleton editor: a drag of one leaf of a 150-node skeleton, the mesh rebuilt at each step: the
// octopus split to 150 nodes, and the dense tree (150 nodes, tubes overlapping: issue 46).
void editorRows(int steps, const std::string& sample) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName((std::string(MEDIAL_SOURCE_DIR) + "/data/skeletons/" + sample).c_str());
  reader->Update();
  medial::Skeleton skeleton;
  std::string error;
  if (!medial::skeletonFromPolyData(vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0)), skeleton,
                                    error)) {
    std::printf("editor: %s\n", error.c_str());
    return;
  }
  while (skeleton.nodeCount() < 150) {  // split the longest edge until there are 150 nodes
    int longest = 0;
    for (int e = 1; e < skeleton.edgeCount(); ++e) {
      const auto length = [&](int i) {
        return (skeleton.nodes[size_t(skeleton.edges[size_t(i)][0])] -
                skeleton.nodes[size_t(skeleton.edges[size_t(i)][1])])
            .norm();
      };
      if (length(e) > length(longest)) longest = e;
    }
    medial::splitEdge(skeleton, longest, 0.5);
  }
  const std::vector<int> degrees = medial::nodeDegrees(skeleton);
  const int leaf = int(std::find(degrees.begin(), degrees.end(), 1) - degrees.begin());
  const Eigen::Vector3d start = skeleton.nodes[size_t(leaf)];
  const double step = 0.02 * skeleton.radii[size_t(leaf)];
  const auto dragTimes = [&](const std::function<void(vtkPolyData*)>& rebuild) {
    medial::Skeleton dragged = skeleton;
    return medianSeconds(steps, [&, i = 0]() mutable {
      ++i;
      medial::moveNode(dragged, leaf, start + Eigen::Vector3d(step * i, 0.5 * step * i, 0));
      rebuild(medial::polyDataFromSkeleton(dragged));
    });
  };
  const auto sqmAt = [](int levels, bool repair) {
    return [levels, repair](vtkPolyData* input) {
      auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
      sqm->SetInputData(input);
      sqm->SetSubdivisionLevels(levels);
      sqm->SetFoldRepair(repair);
      sqm->Update();
    };
  };
  const double base = dragTimes(sqmAt(0, true)), drag2 = dragTimes(sqmAt(2, false)),
               release2 = dragTimes(sqmAt(2, true));
  const double tube = dragTimes([](vtkPolyData* input) {
    auto withScalars = vtkSmartPointer<vtkPolyData>::New();
    withScalars->ShallowCopy(input);
    withScalars->GetPointData()->SetScalars(input->GetPointData()->GetArray("Radius"));
    auto tubes = vtkSmartPointer<vtkTubeFilter>::New();
    tubes->SetInputData(withScalars);
    tubes->SetNumberOfSides(8);
    tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
    tubes->Update();
  });
  std::printf("\nSkeleton editor (%s, %d nodes, a leaf dragged in %d steps), median ms per step\n",
              sample.c_str(), skeleton.nodeCount(), steps);
  std::printf("%-28s %9s %9s %10s\n", "rebuild", "ms", "goal ms", "ms / tube");
  std::printf("%-28s %9.2f %9.0f %10.2f\n", "base mesh (K = 0)", 1e3 * base, 16.0, base / tube);
  std::printf("%-28s %9.2f %9.0f %10.2f\n", "K = 2 while dragging", 1e3 * drag2, 100.0, drag2 / tube);
  std::printf("%-28s %9.2f %9s %10.2f\n", "K = 2 on release (repair)", 1e3 * release2, "-", release2 / tube);
  std::printf("%-28s %9.2f %9s %10s\n", "vtkTubeFilter (peer)", 1e3 * tube, "-", "1.00");
}

// Long chains at scale (issue 46): time linear in the nodes, the overlap count well below the meshing.
void scaleRows(int repeat) {
  std::printf(
      "\nAt scale: data/make-long-chain.py chains (tubes overlap where the walk returns), median of %d\n",
      repeat);
  std::printf("%7s %8s %6s | %8s %8s %7s | %8s %8s | %8s %9s\n", "nodes", "faces", "pairs", "SQM s",
              "count s", "us/node", "tube s", "SQM/tube", "CGAL s", "CGAL/ours");
  for (const int nodes : {1000, 10000, 100000}) {
    const std::string path = "/tmp/medial-bench-chain-" + std::to_string(nodes) + ".swc";
    const std::string make = "python3 '" + std::string(MEDIAL_SOURCE_DIR) + "/data/make-long-chain.py' " +
                             std::to_string(nodes) + " '" + path + "'";
    if (std::system(make.c_str()) != 0) {
      std::printf("%7d cannot make the chain (python3 data/make-long-chain.py)\n", nodes);
      continue;
    }
    auto reader = vtkSmartPointer<vtkMedialReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    auto skeleton = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
    auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
    sqm->SetInputData(skeleton);
    sqm->CountOverlapsOn();
    std::vector<double> counts;
    const double sqmSeconds = medianSeconds(repeat, [&] {
      sqm->Modified();
      sqm->Update();
      counts.push_back(sqm->GetStageSeconds("union"));
    });
    std::nth_element(counts.begin(), counts.begin() + long(counts.size() / 2), counts.end());
    auto withScalars = vtkSmartPointer<vtkPolyData>::New();
    withScalars->ShallowCopy(skeleton);
    withScalars->GetPointData()->SetScalars(skeleton->GetPointData()->GetArray("Radius"));
    auto tube = vtkSmartPointer<vtkTubeFilter>::New();
    tube->SetInputData(withScalars);
    tube->SetNumberOfSides(8);
    tube->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
    const double tubeSeconds = medianSeconds(repeat, [&] {
      tube->Modified();
      tube->Update();
    });
    const auto points = medial::pointsOf(sqm->GetOutput());
    const auto faces = medial::polygonsOf(sqm->GetOutput());
    const double cgalSeconds = medianSeconds(1, [&] { medial::selfIntersectingFaces(points, faces); });
    std::printf("%7d %8lld %s%5d | %8.3f %8.3f %7.1f | %8.3f %8.2f | %8.3f %9.2f\n", nodes,
                static_cast<long long>(faces.size()), sqm->GetOverlapCountComplete() ? " " : ">",
                sqm->GetOverlappingFacePairs(), sqmSeconds, counts[counts.size() / 2],
                1e6 * sqmSeconds / nodes, tubeSeconds, sqmSeconds / tubeSeconds, cgalSeconds,
                cgalSeconds / counts[counts.size() / 2]);
    std::remove(path.c_str());
  }
}

int main(int argc, char** argv) {
  int repeat = 200;
  std::vector<std::string> paths;
  bool givenPaths = false, scaleOnly = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--scale"))
      scaleOnly = true;
    else
      paths.push_back(argv[i]);
  }
  givenPaths = !paths.empty();
  if (scaleOnly) {
    scaleRows(std::max(1, std::min(repeat, 3)));
    return 0;
  }
  if (paths.empty()) {
    const std::string data = std::string(MEDIAL_SOURCE_DIR) + "/data/skeletons/";
    for (const char* name : {"sqm/worm.vtp", "sqm/fish.vtp", "sqm/humanoid.vtp", "sqm/quadruped.vtp",
                             "sqm/octopus.vtp", "figure.vtp", "hand.swc"})
      paths.push_back(data + name);
  }
  std::printf("SQM (vtkMedialSQM) vs vtkTubeFilter (8 sides, radius by Radius), median of %d runs\n", repeat);
  std::printf("%-16s %5s | %9s %6s %6s %6s %5s | %9s %6s %6s %5s | %8s\n", "skeleton", "nodes", "SQM ms",
              "faces", "quads", "border", "nonm", "tube ms", "faces", "border", "nonm", "tube/SQM");
  for (const std::string& path : paths) {
    auto reader = vtkSmartPointer<vtkMedialReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    auto skeleton = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
    if (!skeleton || skeleton->GetNumberOfPoints() == 0) {
      std::printf("%-16s cannot read\n", path.c_str());
      continue;
    }
    auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
    sqm->SetInputData(skeleton);
    const double sqmSeconds = medianSeconds(repeat, [&] {
      sqm->Modified();
      sqm->Update();
    });
    auto withScalars = vtkSmartPointer<vtkPolyData>::New();
    withScalars->ShallowCopy(skeleton);
    withScalars->GetPointData()->SetScalars(skeleton->GetPointData()->GetArray("Radius"));
    auto tube = vtkSmartPointer<vtkTubeFilter>::New();
    tube->SetInputData(withScalars);
    tube->SetNumberOfSides(8);
    tube->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
    const double tubeSeconds = medianSeconds(repeat, [&] {
      tube->Modified();
      tube->Update();
    });
    // The tube filter emits triangle strips: count them after cleaning, as faces a user would get.
    auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
    clean->SetInputConnection(tube->GetOutputPort());
    clean->Update();
    const Summary ours = summarize(sqm->GetOutput()), peer = summarize(clean->GetOutput());
    const std::string name = path.substr(path.find_last_of('/') + 1);
    std::printf("%-16s %5lld | %9.3f %6lld %5.0f%% %6lld %5lld | %9.3f %6lld %6lld %5lld | %8.2f\n",
                name.c_str(), static_cast<long long>(skeleton->GetNumberOfPoints()), 1e3 * sqmSeconds,
                static_cast<long long>(ours.faces), 100 * ours.quadShare, static_cast<long long>(ours.border),
                static_cast<long long>(ours.nonManifold), 1e3 * tubeSeconds,
                static_cast<long long>(peer.faces), static_cast<long long>(peer.border),
                static_cast<long long>(peer.nonManifold), tubeSeconds / sqmSeconds);
  }
  table1(paths, repeat);
  refinedRows(paths, std::max(1, std::min(repeat, 5)));
  for (const char* sample : {"sqm/octopus.vtp", "overlapping/dense-tree.vtp"})
    editorRows(std::max(3, std::min(repeat, 40)), sample);
  if (!givenPaths) {  // the whole benchmark only: seconds per run
    unionRows(std::max(1, std::min(repeat, 3)));
    scaleRows(std::max(1, std::min(repeat, 3)));
  }
  return 0;
}
