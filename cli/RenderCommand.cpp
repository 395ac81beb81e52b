// `medial render INPUT... -o IMAGE.png [--size WxH] [--camera AZIMUTH,ELEVATION] [--skeleton-scale S]
//                [--mesh-opacity A] [--ghost INPUT]... [--cutaway] [--ghost-opacity A]
//                [--ghost-importance I,...] [--ghost-conflict gradual|depth] [--ghost-map-scale S]
//                [--ghost-layers] [--importance-map MAP.png] [--volume-rendering STYLE]`
#include "CommandRun.h"
#include "Commands.h"
#include "CommandLine.h"
#include "PrivateDisplay.h"

#include "MedialErrorCollector.h"
#include "MedialFileNames.h"
#include "MedialVolumeRendering.h"
#include "vtkMedialGhostPass.h"
#include "vtkMedialScene.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkProp3D.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

namespace medial::cli {

namespace {

double parseFraction(const ParsedArgs& parsed, const std::string& option, double fallback, double low,
                     double high, const std::string& range) {
  if (!parsed.has(option)) return fallback;
  const double value = parseNumbers(parsed.value(option), 1, option)[0];
  if (!(value >= low && value <= high)) throw UsageError(option + " must be in " + range);
  return value;
}

// Two spellings of one file name the same input.
std::string sameFileKey(const std::string& path) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
  return error ? path : canonical.string();
}

struct GhostOptions {
  std::vector<std::string> inputs;
  std::vector<double> importance;
  bool cutaway = false;
  double opacity = 0.25;
  bool depthSorting = false;
  double mapScale = 0.5;
  bool layers = false;
  std::string importanceMap;  // --importance-map: where the last frame's map goes
};

GhostOptions parseGhostOptions(const ParsedArgs& parsed) {
  GhostOptions ghost;
  ghost.inputs = parsed.all("--ghost");
  ghost.importance.assign(ghost.inputs.size(), 1.0);
  if (parsed.has("--ghost-importance")) {
    if (ghost.inputs.empty()) throw UsageError("--ghost-importance needs --ghost INPUT");
    ghost.importance =
        parseNumbers(parsed.value("--ghost-importance"), ghost.inputs.size(), "--ghost-importance");
    for (double value : ghost.importance)
      if (!(value > 0 && value <= 1)) throw UsageError("--ghost-importance values must be in (0, 1]");
  }
  ghost.cutaway = parsed.has("--cutaway");
  ghost.layers = parsed.has("--ghost-layers");
  if (ghost.layers && ghost.inputs.empty()) throw UsageError("--ghost-layers needs --ghost INPUT");
  ghost.opacity = parseFraction(parsed, "--ghost-opacity", 0.25, 0, 1, "[0, 1]");
  ghost.mapScale = parseFraction(parsed, "--ghost-map-scale", 0.5, 0.05, 1, "[0.05, 1]");
  const std::string conflict = parsed.value("--ghost-conflict", "gradual");
  if (conflict != "gradual" && conflict != "depth")
    throw UsageError("--ghost-conflict must be gradual or depth, got '" + conflict + "'");
  ghost.depthSorting = conflict == "depth";
  ghost.importanceMap = parsed.value("--importance-map");
  if (parsed.has("--importance-map")) {
    if (ghost.inputs.empty()) throw UsageError("--importance-map needs --ghost INPUT");
    if (medial::fileExtension(ghost.importanceMap) != ".png")
      throw UsageError("--importance-map must be a .png file: " + ghost.importanceMap);
  }
  return ghost;
}

// The importance map (the paper's Figs. 2, 4, 6) as a grey PNG at the map's resolution: importance x
// coverage, white where the most important object projects, 0 where no object of interest does.
void writeImportanceMap(vtkImageData* map, const std::string& path) {
  vtkDataArray* values = map ? map->GetPointData()->GetScalars() : nullptr;
  if (!values) throw Failure(path + ": no importance map was drawn (no object of interest in view)");
  auto grey = vtkSmartPointer<vtkImageData>::New();
  grey->SetDimensions(map->GetDimensions());
  grey->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* pixels = static_cast<unsigned char*>(grey->GetScalarPointer());
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    pixels[i] = static_cast<unsigned char>(
        std::lround(255 * std::clamp(values->GetComponent(i, 0) * values->GetComponent(i, 2), 0.0, 1.0)));
  std::string error;
  const auto write = [&grey](const std::string& temporary, std::string& why) {
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetFileName(temporary.c_str());
    writer->SetInputData(grey);
    writer->Write();
    if (writer->GetErrorCode() != 0) why = "cannot write the file";
    return writer->GetErrorCode() == 0;
  };
  if (!medial::writeAtomically(path, write, error)) throw Failure(path + ": " + error);
}

}  // namespace

// The options of `medial render`: those that take a value, and the flags (medial render --list-options).
const OptionSpec& renderOptions() {
  static const OptionSpec spec = {
      {"-o", "--output", "--size", "--camera", "--skeleton-scale", "--mesh-opacity", "--ghost",
       "--ghost-opacity", "--ghost-importance", "--ghost-conflict", "--ghost-map-scale", "--importance-map",
       "--volume-rendering"},
      {"--quiet", "--timings", "--cutaway", "--ghost-layers"}};
  return spec;
}

// The --help text of `medial render`, built once; its defaults and names are a fresh filter's.
const std::string& renderUsage() {
  static const std::string text = [] {
    return std::string() +
           "usage: medial render INPUT... -o IMAGE.png [--size WxH] [--camera AZIMUTH,ELEVATION]\n"
           "                     [--skeleton-scale S] [--mesh-opacity A]\n"
           "                     [--ghost INPUT]... [--cutaway] [--ghost-opacity A] [--ghost-importance "
           "I,...]\n"
           "                     [--ghost-conflict gradual|depth] [--ghost-map-scale S] [--ghost-layers]\n"
           "                     [--importance-map MAP.png]\n"
           "                     [--volume-rendering STYLE] [--quiet] [--timings]\n"
           "\n"
           "Renders every INPUT (meshes: .vtp .vtk .vtu .obj .ply .stl .off; skeletons: .vtp .swc, drawn as\n"
           "tubes from their Radius; volumes: .nii .nii.gz .mha .mhd .nrrd .inr .inr.gz .vti .inv3 or a "
           "DICOM\n"
           "directory, drawn as three orthogonal slices) into one PNG.\n"
           "  -o, --output IMAGE.png   the image to write (written atomically)\n"
           "  --size WxH               image size in pixels (default 1024x768)\n"
           "  --camera AZ,EL           degrees around the front view (default 30,20)\n"
           "  --skeleton-scale S       scale of skeleton tube radii (default 1)\n"
           "  --mesh-opacity A         opacity of meshes in [0, 1] (default 1); below 1 shows skeletons "
           "inside\n"
           "  --ghost INPUT            an object of interest, kept visible through what hides it (ghost "
           "view,\n"
           "                           Luboschik and Schumann 2008); repeat for several; an INPUT already "
           "listed "
           "is\n"
           "                           marked, another file is added\n"
           "  --cutaway                remove the occluders over the objects of interest instead of "
           "ghosting\n"
           "  --ghost-opacity A        opacity of a ghosted occluder, 0..1 (default 0.25)\n"
           "  --ghost-importance I,... importance of each --ghost object in order, (0, 1] (default all 1)\n"
           "  --ghost-conflict C       gradual: the more important object shows through the less (default);\n"
           "                           depth: the nearer object of interest wins\n"
           "  --ghost-map-scale S      importance-map resolution as a fraction of the image's (default 0.5)\n"
           "  --ghost-layers           every occluding layer in front of an object of interest shows, not\n"
           "                           only the one drawn last (slower: about 0.2 of a frame in software "
           "GL)\n"
           "  --importance-map MAP.png the ghost view's importance map as a grey image at the map's "
           "resolution\n"
           "                           (importance x coverage: where the objects of interest project)\n"
           "  --volume-rendering STYLE volumes as a ray-cast rendering instead of three slices: ct-bone,\n"
           "                           ct-soft-tissue or full-range (transfer-function presets); ghosted "
           "like\n"
           "                           any occluder in front of --ghost objects\n"
           "  --quiet                  no progress line\n"
           "  --timings                print stage times as JSON on stdout\n"
           "Without an X display, a private Xvfb is started (package xvfb).\n";
  }();
  return text;
}

int runRender(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, renderOptions());
  if (parsed.positional.empty()) throw UsageError("render needs at least one INPUT file");
  std::string output = parsed.value("-o", parsed.value("--output"));
  if (output.empty()) throw UsageError("render needs -o IMAGE.png");
  if (medial::fileExtension(output) != ".png")
    throw UsageError("the output image must be a .png file: " + output);
  const auto [width, height] = parseSize(parsed.value("--size", "1024x768"));
  std::vector<double> camera = {30, 20};
  if (parsed.has("--camera")) camera = parseNumbers(parsed.value("--camera"), 2, "--camera");
  double skeletonScale = 1.0;
  if (parsed.has("--skeleton-scale")) {
    skeletonScale = parseNumbers(parsed.value("--skeleton-scale"), 1, "--skeleton-scale")[0];
    if (!(skeletonScale > 0)) throw UsageError("--skeleton-scale must be positive");
  }
  const double meshOpacity = parseFraction(parsed, "--mesh-opacity", 1.0, 0, 1, "[0, 1]");
  const GhostOptions ghost = parseGhostOptions(parsed);
  medial::VolumeStyle volumeStyle = medial::VolumeStyle::Slices;
  if (parsed.has("--volume-rendering") &&
      !medial::parseVolumeStyle(parsed.value("--volume-rendering"), volumeStyle))
    throw UsageError("--volume-rendering must be slices, ct-bone, ct-soft-tissue or full-range, got '" +
                     parsed.value("--volume-rendering") + "'");

  CommandRun command(parsed);
  auto scene = vtkSmartPointer<vtkMedialScene>::New();
  scene->SetSkeletonRadiusScale(skeletonScale);
  scene->SetMeshOpacity(meshOpacity);
  scene->SetVolumeStyle(static_cast<int>(volumeStyle));
  std::map<std::string, vtkProp3D*> propOfFile;
  auto addFile = [&](const std::string& input) {
    const vtkSmartPointer<vtkDataObject> data = command.read(input);
    command.timings().start("scene");
    auto sceneErrors = medial::ErrorCollector::Watch(scene);
    vtkProp3D* prop = scene->AddData(data);
    if (!prop) throw Failure(input + ": " + sceneErrors->Joined());
    propOfFile.emplace(sameFileKey(input), prop);
    return prop;
  };
  for (const std::string& input : parsed.positional) addFile(input);
  for (size_t i = 0; i < ghost.inputs.size(); ++i) {
    const auto known = propOfFile.find(sameFileKey(ghost.inputs[i]));
    vtkProp3D* prop = known != propOfFile.end() ? known->second : addFile(ghost.inputs[i]);
    scene->SetImportance(prop, ghost.importance[i]);
  }
  if (!ghost.inputs.empty()) {
    vtkMedialGhostPass* pass = scene->GetGhostPass();
    pass->SetMode(ghost.cutaway ? vtkMedialGhostPass::Cutaway : vtkMedialGhostPass::Ghost);
    pass->SetGhostOpacity(ghost.opacity);
    pass->SetConflict(ghost.depthSorting ? vtkMedialGhostPass::DepthSorting
                                         : vtkMedialGhostPass::GradualImportance);
    pass->SetMapScale(ghost.mapScale);
    pass->SetLayeredGhosts(ghost.layers);
    pass->SetKeepImportanceMap(!ghost.importanceMap.empty());
  }

  command.timings().start("display");
  PrivateDisplay display;
  std::string error;
  if (!display.ensure(error)) throw Failure(error);
  scene->SetDisplayId(display.displayId());

  command.timings().start("render");
  command.progress().show("rendering " + output, 0.0);
  scene->ResetCamera(static_cast<double>(width) / height, camera[0], camera[1]);
  auto renderErrors = medial::ErrorCollector::Watch(scene);
  if (!scene->RenderToImage(output.c_str(), width, height)) throw Failure(renderErrors->Joined());
  if (!ghost.importanceMap.empty())
    writeImportanceMap(scene->GetGhostPass()->GetImportanceMap(), ghost.importanceMap);
  command.progress().finish();
  return command.finish();
}

}  // namespace medial::cli
