// Benchmark: Medial's skeleton by contraction (stages 1-4 of the contraction paper: contraction, surgery,
// refinement, selection; by default after decimation to the vertex budget, and once more on the full
// mesh) against CGAL's Mean_curvature_flow_skeletonization (contraction + conversion to a
// skeleton) on the same meshes in one run. Prints per mesh the medians of both, the ratio CGAL / Medial,
// the iteration counts, the peak memory of each, and the share of Medial's time spent factorizing; then
// the solver x ordering study of the paper's Table I (contraction only) on one mesh.
//   medial_bench_contraction [--repeat N] [--table MESH|none] [--no-subdivided] [--centring-only]
//                            [--centring-vertices N] [--rotations K] [--write DIR] [MESH...]
// (--write DIR: the skeletons of the off-centre table as legacy VTK line files, and their samples as points
// with the ratio as point data, to look at.)
// Then the off-centre ratio of issue 26 (src/contraction/CrossSections.h) of each mesh's skeletons.
// With no mesh: the CGAL samples under data/external (scripts/fetch-samples) and armadillo after one Loop
// subdivision (~104k vertices). Each run is a child process (fork), so that its peak resident memory
// (wait4's ru_maxrss) is its own.
#include "common/Stopwatch.h"
#include "CgalSkeletonPeer.h"
#include "contraction/CrossSections.h"
#include "contraction/MeshContraction.h"
#include "contraction/SkeletonByContraction.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace {

using medial::peer::cgalSkeleton;
using medial::peer::Skeletonization;
using medial::peer::SurfaceMesh;
using medial::peer::toTriangleMesh;

struct RunResult {
  double seconds = NAN;
  int iterations = 0;
  double factorizationSeconds = 0;
  int nodes = 0;
  bool ok = false;
};

struct Measured {
  RunResult run;       // the median run
  double peakMiB = 0;  // the largest peak over the runs
};

// Runs `work` in a child process and returns what it reported with the child's peak memory.
bool runInChild(const std::function<RunResult()>& work, RunResult& result, double& peakMiB) {
  int channel[2];
  if (pipe(channel) != 0) return false;
  const pid_t child = fork();
  if (child == 0) {
    close(channel[0]);
    RunResult r = work();
    if (write(channel[1], &r, sizeof r) != ssize_t(sizeof r)) _exit(2);
    _exit(0);
  }
  close(channel[1]);
  const bool got = read(channel[0], &result, sizeof result) == ssize_t(sizeof result);
  close(channel[0]);
  int status = 0;
  struct rusage usage {};
  wait4(child, &status, 0, &usage);
  peakMiB = double(usage.ru_maxrss) / 1024.0;
  return got && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

Measured measure(int repeat, const std::function<RunResult()>& work) {
  std::vector<RunResult> runs;
  Measured m;
  for (int i = 0; i < repeat; ++i) {
    RunResult r;
    double peak = 0;
    if (!runInChild(work, r, peak)) r.ok = false;
    m.peakMiB = std::max(m.peakMiB, peak);
    runs.push_back(r);
  }
  std::sort(runs.begin(), runs.end(),
            [](const RunResult& a, const RunResult& b) { return a.seconds < b.seconds; });
  m.run = runs[runs.size() / 2];
  return m;
}

// contractionVertices: the default budget (decimation first), or 0 to contract the full mesh.
RunResult runMedial(const medial::TriangleMesh& mesh, int contractionVertices) {
  medial::SkeletonByContractionParameters p;
  p.contractionVertices = contractionVertices;
  const medial::Stopwatch start;
  const auto r = medial::skeletonByContraction(mesh, p);
  RunResult out;
  out.seconds = start.seconds();
  out.iterations = r.contractionIterations;
  out.factorizationSeconds = r.factorizationSeconds;
  out.nodes = r.skeleton.nodeCount();
  out.ok = r.ok();
  return out;
}

// CGAL's contract_until_convergence, spelled out to count the iterations (same loop, same stop test).
RunResult runCgal(const SurfaceMesh& input) {
  const medial::Stopwatch start;
  Skeletonization mcs(input);
  const double originalArea = CGAL::Polygon_mesh_processing::area(input);
  double lastArea = 0;
  RunResult out;
  while (true) {
    mcs.contract();
    ++out.iterations;
    const double area = CGAL::Polygon_mesh_processing::area(mcs.meso_skeleton());
    if (std::abs(lastArea - area) / originalArea < mcs.area_variation_factor()) break;
    lastArea = area;
    if (std::size_t(out.iterations) >= mcs.max_iterations()) break;
  }
  Skeletonization::Skeleton skeleton;
  mcs.convert_to_skeleton(skeleton);
  out.seconds = start.seconds();
  out.nodes = int(boost::num_vertices(skeleton));
  out.ok = true;
  return out;
}

RunResult runContractionOnly(const medial::TriangleMesh& mesh, medial::SparseSolverKind kind) {
  medial::ContractionParameters p;
  p.solver = kind;
  const medial::Stopwatch start;
  const auto r = medial::contractMesh(mesh, p);
  RunResult out;
  out.seconds = start.seconds();
  out.iterations = r.iterations;
  out.factorizationSeconds = r.analyzeSeconds + r.factorizeSeconds;
  out.ok = r.ok();
  return out;
}

// Writes a skeleton as a legacy VTK file of lines (ParaView and Medial's GUI open it).
void writeSkeleton(const medial::Skeleton& s, const std::string& path) {
  FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return;
  std::fprintf(file, "# vtk DataFile Version 3.0\nskeleton\nASCII\nDATASET POLYDATA\nPOINTS %d double\n",
               s.nodeCount());
  for (const auto& p : s.nodes) std::fprintf(file, "%.9g %.9g %.9g\n", p.x(), p.y(), p.z());
  std::fprintf(file, "LINES %d %d\n", s.edgeCount(), 3 * s.edgeCount());
  for (const auto& e : s.edges) std::fprintf(file, "2 %d %d\n", e[0], e[1]);
  std::fclose(file);
}

// Writes the off-centre samples as legacy VTK vertices with their ratio as point data `OffCentre`.
void writeSamples(const medial::OffCentreSummary& summary, const std::string& path) {
  FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return;
  const int n = int(summary.points.size());
  std::fprintf(
      file, "# vtk DataFile Version 3.0\noff-centre samples\nASCII\nDATASET POLYDATA\nPOINTS %d double\n", n);
  for (const auto& p : summary.points) std::fprintf(file, "%.9g %.9g %.9g\n", p.x(), p.y(), p.z());
  std::fprintf(file, "VERTICES %d %d\n", n, 2 * n);
  for (int k = 0; k < n; ++k) std::fprintf(file, "1 %d\n", k);
  std::fprintf(file, "POINT_DATA %d\nSCALARS OffCentre double 1\nLOOKUP_TABLE default\n", n);
  for (double r : summary.ratios) std::fprintf(file, "%.6g\n", r);
  std::fclose(file);
}

// The mesh turned by `degrees` about a fixed oblique axis through the origin.
SurfaceMesh rotated(const SurfaceMesh& mesh, double degrees) {
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  SurfaceMesh out = mesh;
  for (auto v : out.vertices()) {
    const auto& p = out.point(v);
    const Eigen::Vector3d q = turn * Eigen::Vector3d(p.x(), p.y(), p.z());
    out.point(v) = medial::peer::Kernel::Point_3(q.x(), q.y(), q.z());
  }
  return out;
}

double medianOf(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? NAN : values[values.size() / 2];
}

// The off-centre ratio (src/contraction/CrossSections.h) of Medial's default skeleton, of its
// unselected one (--nodes 0) and of CGAL's: median and 90th percentile, and the samples outside. With
// `rotations` > 1, the mesh is also turned by 1, 2, ... degrees and each skeleton measured again: the
// medians of the turns' medians and 90th percentiles, the range of the medians, the most samples outside.
// (Both skeletons react to a change that small: CGAL's flow differs from run to run, and a 0.1 % change
// of Medial's W_L0 moved bunny00's median from 0.43 to 0.12.) With `folder`, the three skeletons of the
// unturned mesh are written there (NAME-medial.vtk, NAME-medial-nodes0.vtk, NAME-cgal.vtk), each with
// its samples (NAME-...-samples.vtk).
void centringRow(const std::string& name, const SurfaceMesh& input, const std::string& folder,
                 int centringVertices, int rotations) {
  const char* suffixes[] = {"-medial", "-medial-nodes0", "-cgal"};
  std::vector<double> medians[3], percentiles[3];
  int outside[3] = {0, 0, 0};
  std::vector<double> nodeMedians[2];  // the selected nodes', their sources'
  int worseNodes = 0, pairedNodes = 0;
  for (int turn = 0; turn < rotations; ++turn) {
    const SurfaceMesh sm = turn == 0 ? input : rotated(input, turn);
    const medial::TriangleMesh mesh = toTriangleMesh(sm);
    const medial::CrossSections sections(mesh);
    medial::SkeletonByContractionParameters p;
    if (centringVertices >= 0) p.contractionVertices = centringVertices;
    p.recordStages = true;  // for the selected nodes' sources
    const medial::SkeletonByContractionResult selectedRun = medial::skeletonByContraction(mesh, p);
    const medial::Skeleton& selected = selectedRun.skeleton;
    const medial::SelectionCentring nodes = medial::measureSelectionCentring(selectedRun, mesh);
    nodeMedians[0].push_back(nodes.selected.median());
    nodeMedians[1].push_back(nodes.source.median());
    worseNodes = std::max(worseNodes, nodes.worse);
    pairedNodes = std::max(pairedNodes, int(nodes.selected.ratios.size()));
    p.recordStages = false;
    p.targetNodes = 0;
    const medial::Skeleton unselected = medial::skeletonByContraction(mesh, p).skeleton;
    const medial::Skeleton cgal = cgalSkeleton(sm);
    const medial::Skeleton* skeletons[] = {&selected, &unselected, &cgal};
    for (int k = 0; k < 3; ++k) {
      const auto m = medial::offCentre(*skeletons[k], sections);
      medians[k].push_back(m.median());
      percentiles[k].push_back(m.percentile90());
      outside[k] = std::max(outside[k], m.outside);
      if (folder.empty() || turn > 0) continue;
      writeSkeleton(*skeletons[k], folder + "/" + name + suffixes[k] + ".vtk");
      writeSamples(m, folder + "/" + name + suffixes[k] + "-samples.vtk");
    }
  }
  std::printf("%-18s", name.c_str());
  for (int k = 0; k < 3; ++k) {
    std::printf(" | %6.3f %6.3f %4d", medianOf(medians[k]), medianOf(percentiles[k]), outside[k]);
    if (rotations > 1)
      std::printf(" [%.3f-%.3f]", *std::min_element(medians[k].begin(), medians[k].end()),
                  *std::max_element(medians[k].begin(), medians[k].end()));
  }
  std::printf(" | %6.3f %6.3f %3d/%-3d\n", medianOf(nodeMedians[0]), medianOf(nodeMedians[1]), worseNodes,
              pairedNodes);
  std::fflush(stdout);
}

bool readMesh(const std::string& path, SurfaceMesh& mesh) {
  if (!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty() || !CGAL::is_triangle_mesh(mesh))
    return false;
  return true;
}

std::string sampleMesh(const std::string& name) {
  if (std::filesystem::exists(name)) return name;
  return std::string(MEDIAL_SOURCE_DIR) + "/data/external/cgal/meshes/" + name + ".off";
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 3;
  bool subdivided = true, timing = true;
  std::string writeFolder;
  int centringVertices = -1;  // the centring table's vertex budget: Medial's default unless given
  int rotations = 1;          // the centring table's turns of each mesh (1: the mesh as it is)
  std::string tableMesh = "elephant";
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--table") && i + 1 < argc) {
      tableMesh = argv[++i];
    } else if (!std::strcmp(argv[i], "--no-subdivided")) {
      subdivided = false;
    } else if (!std::strcmp(argv[i], "--centring-only")) {
      timing = false;
    } else if (!std::strcmp(argv[i], "--centring-vertices") && i + 1 < argc) {
      centringVertices = std::max(0, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--rotations") && i + 1 < argc) {
      rotations = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--write") && i + 1 < argc) {
      writeFolder = argv[++i];
    } else if (argv[i][0] == '-') {
      std::fprintf(stderr,
                   "usage: %s [--repeat N] [--table MESH|none] [--no-subdivided] [--centring-only] "
                   "[--centring-vertices N] [--rotations K] [--write DIR] [MESH...]\n",
                   argv[0]);
      return 2;
    } else {
      meshes.push_back(argv[i]);
    }
  }
  if (meshes.empty())
    meshes = {"knot1", "elephant",   "femur",     "hand",    "mannequin-devil",
              "man",   "diplodocus", "armadillo", "bunny00", "refined_elephant"};

  std::printf(
      "Skeleton by contraction: Medial (stages 1-4) vs CGAL Mean_curvature_flow_skeletonization, "
      "median of %d runs each\n",
      repeat);
  const int budget = medial::SkeletonByContractionParameters().contractionVertices;
  std::printf(
      "Medial: the default (meshes above %d vertices decimated to %d first); Medial full: the mesh "
      "contracted as it is\n",
      budget, budget);
  std::printf("%-18s %8s | %8s %5s %6s %8s | %8s %5s | %8s %5s %8s | %8s %8s\n", "mesh", "vertices",
              "Medial s", "iters", "factor", "peak MiB", "full s", "iters", "CGAL s", "iters", "peak MiB",
              "CGAL/Med", "CGAL/full");
  auto row = [&](const std::string& name, const SurfaceMesh& sm) {
    const medial::TriangleMesh mesh = toTriangleMesh(sm);
    const Measured ours = measure(repeat, [&] { return runMedial(mesh, budget); });
    const Measured full = sm.number_of_vertices() > std::size_t(budget)
                              ? measure(repeat, [&] { return runMedial(mesh, 0); })
                              : ours;
    const Measured peer = measure(repeat, [&] { return runCgal(sm); });
    std::printf("%-18s %8zu | %8.3f %5d %5.0f%% %8.0f | %8.3f %5d | %8.3f %5d %8.0f | %8.2f %8.2f%s\n",
                name.c_str(), std::size_t(sm.number_of_vertices()), ours.run.seconds, ours.run.iterations,
                100.0 * ours.run.factorizationSeconds / ours.run.seconds, ours.peakMiB, full.run.seconds,
                full.run.iterations, peer.run.seconds, peer.run.iterations, peer.peakMiB,
                peer.run.seconds / ours.run.seconds, peer.run.seconds / full.run.seconds,
                ours.run.ok && full.run.ok && peer.run.ok ? "" : "  (a run failed)");
    std::fflush(stdout);
  };
  for (const std::string& name : meshes) {
    if (!timing) break;
    SurfaceMesh sm;
    if (!readMesh(sampleMesh(name), sm)) {
      std::printf("%-22s cannot read %s (run scripts/fetch-samples)\n", name.c_str(),
                  sampleMesh(name).c_str());
      continue;
    }
    row(std::filesystem::path(name).stem().string(), sm);
    if (subdivided && std::filesystem::path(name).stem() == "armadillo") {
      CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(1));
      row("armadillo-loop1", sm);
    }
  }

  // Centring: the off-centre ratio of the issue, 150 samples with a fixed seed.
  std::printf(
      "\nOff-centre ratio (distance to the cross-section's centroid / its equivalent radius; 150 "
      "samples): median, 90th percentile, samples outside\n");
  const int width = rotations > 1 ? 34 : 20;
  if (rotations > 1)
    std::printf(
        "Each the median over the mesh and %d turns of it (1, 2, ... degrees), most samples outside, "
        "[range of the medians]\n",
        rotations - 1);
  std::printf(
      "Selected nodes: the default skeleton's nodes and the unselected (centred) nodes they came from, "
      "off-centre at the node: medians (over turns), and the most nodes more than 0.1 further off than "
      "their source / nodes compared\n");
  std::printf("%-18s | %*s | %*s | %*s | %21s\n", "mesh", width, "Medial default", width, "Medial --nodes 0",
              width, "CGAL", "selected source worse");
  for (const std::string& name : meshes) {
    SurfaceMesh sm;
    if (readMesh(sampleMesh(name), sm))
      centringRow(std::filesystem::path(name).stem().string(), sm, writeFolder, centringVertices, rotations);
  }

  // Table I of the paper: every solver x ordering on one mesh, contraction only.
  if (tableMesh == "none") return 0;
  SurfaceMesh sm;
  if (!readMesh(sampleMesh(tableMesh), sm)) return 0;
  const medial::TriangleMesh mesh = toTriangleMesh(sm);
  std::printf("\nSolver x ordering (contraction only), %s, %zu vertices, median of %d runs\n",
              tableMesh.c_str(), std::size_t(sm.number_of_vertices()), repeat);
  std::printf("%-14s %9s %5s %9s %8s | %s\n", "solver", "seconds", "iters", "factor s", "peak MiB",
              "vs auto (the default)");
  double reference = NAN;
  for (medial::SparseSolverKind kind : medial::allSparseSolverKinds()) {
    const Measured m = measure(repeat, [&] { return runContractionOnly(mesh, kind); });
    if (std::isnan(reference)) reference = m.run.seconds;
    std::printf("%-14s %9.3f %5d %9.3f %8.0f | %.2f%s\n", medial::sparseSolverName(kind).c_str(),
                m.run.seconds, m.run.iterations, m.run.factorizationSeconds, m.peakMiB,
                m.run.seconds / reference, m.run.ok ? "" : "  (failed)");
    std::fflush(stdout);
  }
  return 0;
}
