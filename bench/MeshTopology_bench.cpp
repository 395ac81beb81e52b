// Benchmark: vtkMedialMeshTopology against the VTK filters a user would combine for the same counts
// (vtkFeatureEdges for border and non-manifold edges, vtkPolyDataConnectivityFilter for components),
// on the same meshes in one run. Prints per mesh the medians of both and the ratio peer / Medial.
//   medial_bench_mesh_topology [--repeat N] MESH...
// With no mesh: the CGAL samples under data/external (scripts/fetch-samples), armadillo also after one
// Loop subdivision (~104k vertices).
#include "MedianSeconds.h"
#include "vtkMedialMeshTopology.h"
#include "vtkMedialReader.h"

#include <vtkFeatureEdges.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace {

struct Counts {
  long border = 0, nonManifold = 0, components = 0;
};

Counts medialCounts(vtkPolyData* mesh) {
  auto topology = vtkSmartPointer<vtkMedialMeshTopology>::New();
  topology->SetInputData(mesh);
  topology->Update();
  return {static_cast<long>(topology->GetNumberOfBorderEdges()),
          static_cast<long>(topology->GetNumberOfNonManifoldEdges()),
          static_cast<long>(topology->GetNumberOfComponents())};
}

Counts vtkCounts(vtkPolyData* mesh) {
  Counts c;
  auto edges = vtkSmartPointer<vtkFeatureEdges>::New();
  edges->SetInputData(mesh);
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOff();
  edges->Update();
  c.border = edges->GetOutput()->GetNumberOfLines();
  edges->BoundaryEdgesOff();
  edges->NonManifoldEdgesOn();
  edges->Update();
  c.nonManifold = edges->GetOutput()->GetNumberOfLines();
  auto connectivity = vtkSmartPointer<vtkPolyDataConnectivityFilter>::New();
  connectivity->SetInputData(mesh);
  connectivity->SetExtractionModeToAllRegions();
  connectivity->Update();
  c.components = connectivity->GetNumberOfExtractedRegions();
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 15;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else
      meshes.push_back(argv[i]);
  }
  bool subdivideArmadillo = false;
  if (meshes.empty()) {
    const std::string dir = std::string(MEDIAL_SOURCE_DIR) + "/data/external/cgal/meshes/";
    for (const char* name : {"elephant", "femur", "mannequin-devil", "man", "armadillo"})
      if (std::filesystem::exists(dir + name + ".off")) meshes.push_back(dir + name + ".off");
    subdivideArmadillo = std::filesystem::exists(dir + "armadillo.off");
    if (meshes.empty()) {
      std::fprintf(stderr, "no meshes given and none under %s (run scripts/fetch-samples)\n", dir.c_str());
      return 1;
    }
  }

  std::printf("%-28s %9s %9s | %12s %12s %7s | counts agree\n", "mesh", "vertices", "faces", "medial [ms]",
              "vtk [ms]", "ratio");
  auto runOne = [&](const std::string& label, vtkPolyData* mesh) {
    const Counts a = medialCounts(mesh), b = vtkCounts(mesh);
    const double medial = medianSeconds(repeat, [&] { medialCounts(mesh); });
    const double peer = medianSeconds(repeat, [&] { vtkCounts(mesh); });
    const bool agree = a.border == b.border && a.nonManifold == b.nonManifold && a.components == b.components;
    std::printf("%-28s %9lld %9lld | %12.2f %12.2f %6.1fx | %s\n", label.c_str(),
                static_cast<long long>(mesh->GetNumberOfPoints()),
                static_cast<long long>(mesh->GetNumberOfPolys()), medial * 1e3, peer * 1e3, peer / medial,
                agree ? "yes" : "NO");
    return agree;
  };

  bool allAgree = true;
  for (const std::string& path : meshes) {
    auto reader = vtkSmartPointer<vtkMedialReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    auto* mesh = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
    if (!mesh || mesh->GetNumberOfPolys() == 0) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), reader->GetErrorMessage());
      return 1;
    }
    allAgree &= runOne(std::filesystem::path(path).stem().string(), mesh);
    if (subdivideArmadillo && path.find("armadillo") != std::string::npos) {
      auto loop = vtkSmartPointer<vtkLoopSubdivisionFilter>::New();
      loop->SetInputData(mesh);
      loop->SetNumberOfSubdivisions(1);
      loop->Update();
      allAgree &= runOne("armadillo (Loop x1)", loop->GetOutput());
    }
  }
  std::printf("median of %d runs each; ratio = vtk time / medial time\n", repeat);
  return allAgree ? 0 : 1;
}
