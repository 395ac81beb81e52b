// Benchmark: frame time of vtkMedialGhostPass against plain rendering of the same scene, in one run.
// Scene: a context mesh subdivided (Loop) to about a million triangles and its contraction skeleton as
// the object of interest, drawn as vtkMedialScene draws them, offscreen at 1280x1024 on this machine's
// OpenGL (llvmpipe under Xvfb). Each configuration gets its own window and a few warm-up frames; then the
// configurations take turns for `frames` timed frames each while their cameras turn 2° per frame (the
// map is view-dependent: rebuilt every frame); a frame is Render() plus glFinish. Configurations:
//   plain       the opaque mesh hides the skeleton (no pass)
//   peeled      the usual workaround: the mesh at opacity 0.3 over the skeleton, dual depth peeling
//   pass, off   the ghost pass installed with Mode Off (its delegate alone)
//   ghost S     the ghost pass at MapScale S (1, 0.5, 0.25)
//   layered     the ghost pass at MapScale 0.5 with LayeredGhosts (every occluder's shader writes depth)
// Prints medians and the ratios ghost / plain (paper: <= 2, goal: <= 1.3) and ghost / peeled.
//   medial_bench_ghost [--frames N] [--size WxH] [--triangles T] [MESH]   (default: armadillo, else torus)
#include "common/Stopwatch.h"
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
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
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
    if (arg == "--frames" && i + 1 < argc)
      o.frames = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--size" && i + 1 < argc)
      std::sscanf(argv[++i], "%dx%d", &o.width, &o.height);
    else if (arg == "--triangles" && i + 1 < argc)
      o.triangles = std::atoll(argv[++i]);
    else
      o.mesh = arg;
  }
  if (o.mesh.empty()) {
    const std::string armadillo = std::string(MEDIAL_SOURCE_DIR) + "/data/external/cgal/meshes/armadillo.off";
    o.mesh = std::filesystem::exists(armadillo) ? armadillo
                                                : std::string(MEDIAL_SOURCE_DIR) + "/data/meshes/torus.off";
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

enum class Config { Plain, Peeled, PassOff, Ghost, Layered };

// One configuration's scene in its own offscreen window, and its frame times.
struct Setup {
  std::string name;
  vtkSmartPointer<vtkMedialScene> scene;
  vtkSmartPointer<vtkRenderWindow> window;
  std::vector<double> times;

  void frame() {
    window->Render();
    if (auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window)) gl->WaitForCompletion();
  }
  double median() {
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
  }
};

std::unique_ptr<Setup> makeSetup(const std::string& name, const Options& o, vtkPolyData* context,
                                 vtkPolyData* skeleton, Config config, double mapScale) {
  auto setup = std::make_unique<Setup>();
  setup->name = name;
  setup->scene = vtkSmartPointer<vtkMedialScene>::New();
  vtkMedialScene* scene = setup->scene;
  scene->SetSkeletonRadiusScale(0.3);
  if (config == Config::Peeled) scene->SetMeshOpacity(0.3);
  scene->AddData(context);
  vtkProp3D* bones = scene->AddData(skeleton);
  vtkRenderer* renderer = scene->GetRenderer();
  if (config != Config::Plain && config != Config::Peeled) {
    scene->SetImportance(bones, 1.0);
    scene->GetGhostPass()->SetMapScale(mapScale);
    if (config == Config::PassOff) scene->GetGhostPass()->SetModeToOff();
    scene->GetGhostPass()->SetLayeredGhosts(config == Config::Layered);
  }
  setup->window = vtkSmartPointer<vtkRenderWindow>::New();
  vtkRenderWindow* window = setup->window;
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
  for (int i = 0; i < 3; ++i) setup->frame();  // shaders, buffers
  return setup;
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
              std::filesystem::path(o.mesh).filename().c_str(),
              static_cast<long long>(mesh->GetNumberOfPolys()),
              static_cast<long long>(context->GetNumberOfPolys()),
              static_cast<long long>(skeleton->GetNumberOfPoints()), o.width, o.height, o.frames);
  if (skeleton->GetNumberOfPoints() == 0) {
    std::fprintf(stderr, "%s: no skeleton\n", o.mesh.c_str());
    return 1;
  }

  // All configurations live at once and take turns frame by frame, so that the machine's drift (another
  // process, the clock) falls on all of them alike; ratios are of medians.
  std::vector<std::unique_ptr<Setup>> setups;
  setups.push_back(makeSetup("plain", o, context, skeleton, Config::Plain, 0));
  setups.push_back(makeSetup("peeled 0.3", o, context, skeleton, Config::Peeled, 0));
  setups.push_back(makeSetup("pass, mode off", o, context, skeleton, Config::PassOff, 0.5));
  for (double scale : {1.0, 0.5, 0.25}) {
    char name[32];
    std::snprintf(name, sizeof name, "ghost %.2f", scale);
    setups.push_back(makeSetup(name, o, context, skeleton, Config::Ghost, scale));
  }
  setups.push_back(makeSetup("layered 0.50", o, context, skeleton, Config::Layered, 0.5));
  for (int i = 0; i < o.frames; ++i)
    for (auto& setup : setups) {
      setup->scene->GetRenderer()->GetActiveCamera()->Azimuth(2.0);
      const medial::Stopwatch stopwatch;
      setup->frame();
      setup->times.push_back(stopwatch.seconds());
    }
  const double plain = setups[0]->median(), peeled = setups[1]->median();
  std::printf("%-14s %10s %14s %15s\n", "configuration", "median ms", "ratio / plain", "ratio / peeled");
  for (auto& setup : setups) {
    const double t = setup->median();
    std::printf("%-14s %10.1f %14.2f %15.2f\n", setup->name.c_str(), 1e3 * t, t / plain, t / peeled);
  }
  for (auto& setup : setups) {
    setup->window->RemoveRenderer(setup->scene->GetRenderer());
    setup->window->Finalize();
  }
  return 0;
}
