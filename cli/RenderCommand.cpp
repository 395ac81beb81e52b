// `medial render INPUT... -o IMAGE.png [--size WxH] [--camera AZIMUTH,ELEVATION] [--skeleton-scale S]
//                [--mesh-opacity A]`
#include "Commands.h"
#include "CommandLine.h"
#include "PrivateDisplay.h"
#include "Progress.h"
#include "ReadInput.h"
#include "Timings.h"

#include "MedialErrorCollector.h"
#include "MedialFileNames.h"
#include "vtkMedialScene.h"

#include <vtkSmartPointer.h>

#include <cstdio>

namespace medial::cli {

int runRender(const std::vector<std::string>& args) {
  const ParsedArgs parsed =
      parseArgs(args, {{"-o", "--output", "--size", "--camera", "--skeleton-scale", "--mesh-opacity"}, {"--quiet", "--timings"}});
  if (parsed.positional.empty()) throw UsageError("render needs at least one INPUT file");
  std::string output = parsed.value("-o", parsed.value("--output"));
  if (output.empty()) throw UsageError("render needs -o IMAGE.png");
  if (medial::fileExtension(output) != ".png") throw UsageError("the output image must be a .png file: " + output);
  const auto [width, height] = parseSize(parsed.value("--size", "1024x768"));
  std::vector<double> camera = {30, 20};
  if (parsed.has("--camera")) camera = parseNumbers(parsed.value("--camera"), 2, "--camera");
  double skeletonScale = 1.0;
  if (parsed.has("--skeleton-scale")) {
    skeletonScale = parseNumbers(parsed.value("--skeleton-scale"), 1, "--skeleton-scale")[0];
    if (!(skeletonScale > 0)) throw UsageError("--skeleton-scale must be positive");
  }

  double meshOpacity = 1.0;
  if (parsed.has("--mesh-opacity")) {
    meshOpacity = parseNumbers(parsed.value("--mesh-opacity"), 1, "--mesh-opacity")[0];
    if (!(meshOpacity >= 0 && meshOpacity <= 1)) throw UsageError("--mesh-opacity must be in [0, 1]");
  }

  Timings timings;
  ProgressLine progress(parsed.has("--quiet"));
  auto scene = vtkSmartPointer<vtkMedialScene>::New();
  scene->SetSkeletonRadiusScale(skeletonScale);
  scene->SetMeshOpacity(meshOpacity);
  for (const std::string& input : parsed.positional) {
    timings.start("read");
    const vtkSmartPointer<vtkDataObject> data = readInput(input, progress);
    timings.start("scene");
    auto sceneErrors = medial::ErrorCollector::Watch(scene);
    if (!scene->AddData(data)) throw Failure(input + ": " + sceneErrors->Joined());
  }

  timings.start("display");
  PrivateDisplay display;
  std::string error;
  if (!display.ensure(error)) throw Failure(error);
  scene->SetDisplayId(display.displayId());

  timings.start("render");
  progress.show("rendering " + output, 0.0);
  scene->ResetCamera(static_cast<double>(width) / height, camera[0], camera[1]);
  auto renderErrors = medial::ErrorCollector::Watch(scene);
  if (!scene->RenderToImage(output.c_str(), width, height)) throw Failure(renderErrors->Joined());
  progress.finish();
  timings.stop();
  if (parsed.has("--timings")) std::printf("%s\n", timings.json().c_str());
  return kSuccess;
}

}  // namespace medial::cli
