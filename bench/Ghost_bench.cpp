// Benchmark: frame time of vtkMedialGhostPass against plain rendering of the same scene, in one run.
// Scene: a context mesh subdivided (Loop) to about a million triangles and its contraction skeleton as
// the object of interest, drawn as vtkMedialScene draws them, offscreen at 1280x1024 on this machine's
// OpenGL (llvmpipe under Xvfb). Each configuration gets its own window, a few warm-up frames, then
// `frames` timed frames while the camera turns 2° per frame (the map is view-dependent: rebuilt every
// frame); a frame is Render() plus glFinish. Configurations:
//   plain       the opaque mesh hides the skeleton (no pass)
//   peeled      the usual workaround: the mesh at opacity 0.3 over the skeleton, dual depth peeling
//   pass, off   the ghost pass installed with Mode Off (its delegate alone)
//   ghost S     the ghost pass at MapScale S (1, 0.5, 0.25)
// Prints medians and the ratios ghost / plain (paper: <= 2, goal: <= 1.3) and ghost / peeled.
//   medial_bench_ghost [--frames N] [--size WxH] [--triangles T] [MESH]   (default: armadillo, else torus)
#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialGhostPass.h"
#include "vtkMedialReader.h"
#include "vtkMedialScene.h"

#include <vtkCamera.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPolyData.h>
#include <vtkProp3D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace {

struct Options {
  int frames = 30;
  int width = 1280, height = 1024;
  vtkIdType triangles = 1000000;
  std::string mesh;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--frames" && i + 1 < argc) o.frames = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--size" && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &o.width, &o.height);
    else if (arg == "--triangles" && i + 1 < argc) o.triangles = std::atoll(argv[++i]);
    else o.mesh = arg;
  }
  if (o.mesh.empty()) {
    const std::string armadillo = std::string(MEDIAL_SOURCE_DIR) + "/data/external/cgal/meshes/armadillo.off";
    o.mesh = std::filesystem::exists(armadillo) ? armadillo : std::string(MEDIAL_SOURCE_DIR) + "/data/meshes/torus.off";
  }
  return o;
}

vtkSmartPointer<vtkPolyData> readMesh(const std::string& path) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(path.c_str());
  auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
  triangles->SetInputConnection(reader->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
}

// Loop subdivision to the level whose triangle count (x4 per level) comes nearest `target`.
vtkSmartPointer<vtkPolyData> subdivideTo(vtkPolyData* mesh, vtkIdType target) {
  int levels = 0;
  for (vtkIdType n = mesh->GetNumberOfPolys(); 4 * n <= 2 * target; n *= 4) ++levels;
  if (levels == 0) return mesh;
  auto loop = vtkSmartPointer<vtkLoopSubdivisionFilter>::New();
  loop->SetInputData(mesh);
  loop->SetNumberOfSubdivisions(levels);
  loop->Update();
  return loop->GetOutput();
}

enum class Config { Plain, Peeled, PassOff, Ghost };

double medianFrameSeconds(const Options& o, vtkPolyData* context, vtkPolyData* skeleton, Config config,
                          double mapScale) {
  auto scene = vtkSmartPointer<vtkMedialScene>::New();
  scene->SetSkeletonRadiusScale(0.3);
  if (config == Config::Peeled) scene->SetMeshOpacity(0.3);
  scene->AddData(context);
  vtkProp3D* bones = scene->AddData(skeleton);
  vtkRenderer* renderer = scene->GetRenderer();
  if (config == Config::Ghost || config == Config::PassOff) {
    scene->SetImportance(bones, 1.0);
    scene->GetGhostPass()->SetMapScale(mapScale);
    if (config == Config::PassOff) scene->GetGhostPass()->SetModeToOff();
  }
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);  // depth peeling needs it; the same for every configuration
  window->SetAlphaBitPlanes(1);
  window->SetSize(o.width, o.height);
  window->AddRenderer(renderer);
  if (config == Config::Peeled) {
    renderer->SetUseDepthPeeling(1);
    renderer->SetMaximumNumberOfPeels(8);
    renderer->SetOcclusionRatio(0.0);
  }
  scene->ResetCamera(static_cast<double>(o.width) / o.height);
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  auto frame = [&] {
    window->Render();
    if (gl) gl->WaitForCompletion();
  };
  for (int i = 0; i < 3; ++i) frame();  // shaders, buffers
  std::vector<double> times;
  for (int i = 0; i < o.frames; ++i) {
    renderer->GetActiveCamera()->Azimuth(2.0);
    const auto start = std::chrono::steady_clock::now();
    frame();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  window->RemoveRenderer(renderer);
  window->Finalize();
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const vtkSmartPointer<vtkPolyData> mesh = readMesh(o.mesh);
  if (mesh->GetNumberOfPolys() == 0) {
    std::fprintf(stderr, "%s: no triangles\n", o.mesh.c_str());
    return 1;
  }
  auto contraction = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  contraction->SetInputData(mesh);
  contraction->Update();
  vtkPolyData* skeleton = contraction->GetOutput();
  const vtkSmartPointer<vtkPolyData> context = subdivideTo(mesh, o.triangles);
  std::printf("mesh %s: %lld triangles subdivided to %lld; skeleton %lld nodes; %dx%d, %d frames\n",
              std::filesystem::path(o.mesh).filename().c_str(), static_cast<long long>(mesh->GetNumberOfPolys()),
              static_cast<long long>(context->GetNumberOfPolys()),
              static_cast<long long>(skeleton->GetNumberOfPoints()), o.width, o.height, o.frames);
  if (skeleton->GetNumberOfPoints() == 0) {
    std::fprintf(stderr, "%s: no skeleton\n", o.mesh.c_str());
    return 1;
  }

  const double plain = medianFrameSeconds(o, context, skeleton, Config::Plain, 0);
  const double peeled = medianFrameSeconds(o, context, skeleton, Config::Peeled, 0);
  std::printf("%-14s %10s %14s %15s\n", "configuration", "median ms", "ratio / plain", "ratio / peeled");
  std::printf("%-14s %10.1f %14.2f %15.2f\n", "plain", 1e3 * plain, 1.0, plain / peeled);
  std::printf("%-14s %10.1f %14.2f %15.2f\n", "peeled 0.3", 1e3 * peeled, peeled / plain, 1.0);
  const double passOff = medianFrameSeconds(o, context, skeleton, Config::PassOff, 0.5);
  std::printf("%-14s %10.1f %14.2f %15.2f\n", "pass, mode off", 1e3 * passOff, passOff / plain, passOff / peeled);
  for (double scale : {1.0, 0.5, 0.25}) {
    const double ghost = medianFrameSeconds(o, context, skeleton, Config::Ghost, scale);
    char name[32];
    std::snprintf(name, sizeof name, "ghost %.2f", scale);
    std::printf("%-14s %10.1f %14.2f %15.2f\n", name, 1e3 * ghost, ghost / plain, ghost / peeled);
  }
  return 0;
}
