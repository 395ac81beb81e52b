// `medial sqm SKELETON.vtp|.swc -o MESH.vtp|.obj|.ply [--smoothing NAME] [--pairing NAME] [--capsule]
//              [--triangle-fans] [--ring-vertices N] [--subdivide K] [--sharp-scale S] [--no-fold-repair]`
#include "Commands.h"
#include "CommandLine.h"
#include "Progress.h"
#include "ReadInput.h"
#include "RunFilter.h"
#include "Timings.h"
#include "WriteOutput.h"

#include "MedialErrorCollector.h"
#include "vtkMedialSQM.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdio>

namespace medial::cli {

int runSqm(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(
      args, {{"-o", "--output", "--smoothing", "--pairing", "--ring-vertices", "--subdivide", "--sharp-scale"},
             {"--capsule", "--triangle-fans", "--no-fold-repair", "--quiet", "--timings"}});
  if (parsed.positional.size() != 1) throw UsageError("sqm needs exactly one SKELETON file");
  const std::string input = parsed.positional[0];
  const std::string output = parsed.value("-o", parsed.value("--output"));
  if (output.empty()) throw UsageError("sqm needs -o MESH.vtp|.obj|.ply");
  requireWritableExtension(output, "-o");

  auto filter = vtkSmartPointer<vtkMedialSQM>::New();
  {
    auto errors = medial::ErrorCollector::Watch(filter);
    if (parsed.has("--smoothing")) filter->SetSmoothing(parsed.value("--smoothing"));
    if (parsed.has("--pairing")) filter->SetPairing(parsed.value("--pairing"));
    if (errors->HasErrors()) throw UsageError(errors->Joined());
  }
  if (parsed.has("--ring-vertices")) {
    const double n = parseNumbers(parsed.value("--ring-vertices"), 1, "--ring-vertices")[0];
    if (!(n >= 3) || n != int(n)) throw UsageError("--ring-vertices must be a whole number >= 3");
    filter->SetLinearRingVertices(int(n));
  }
  if (parsed.has("--subdivide")) {
    const double k = parseNumbers(parsed.value("--subdivide"), 1, "--subdivide")[0];
    if (!(k >= 0 && k <= 6) || k != int(k)) throw UsageError("--subdivide must be a whole number from 0 to 6");
    filter->SetSubdivisionLevels(int(k));
  }
  if (parsed.has("--sharp-scale")) {
    const double s = parseNumbers(parsed.value("--sharp-scale"), 1, "--sharp-scale")[0];
    if (!(s >= 0.05 && s <= 1)) throw UsageError("--sharp-scale must be a number from 0.05 to 1");
    filter->SetSharpMinimumScale(s);
    filter->SetSharpScaling(true);
  }
  filter->SetCapsules(parsed.has("--capsule"));
  filter->SetPairTriangles(!parsed.has("--triangle-fans"));
  filter->SetFoldRepair(!parsed.has("--no-fold-repair"));

  Timings timings;
  ProgressLine progress(parsed.has("--quiet"));
  timings.start("read");
  const vtkSmartPointer<vtkDataObject> data = readInput(input, progress);
  vtkPolyData* skeleton = vtkPolyData::SafeDownCast(data);
  if (!skeleton || skeleton->GetNumberOfPoints() == 0) throw Failure(input + ": not a skeleton (no nodes)");

  timings.start("sqm");
  runFilter(filter, skeleton, input, "tube mesh of " + input, progress);

  if (filter->GetMergedNodes() > 0)
    std::fprintf(stderr, "medial sqm: note: %d node%s inside a neighbouring branch node's sphere merged into it\n",
                 filter->GetMergedNodes(), filter->GetMergedNodes() == 1 ? "" : "s");
  if (filter->GetFoldRepairedVertices() > 0)
    std::fprintf(stderr, "medial sqm: note: %d refined vert%s moved off the cones, where faces cut each other\n",
                 filter->GetFoldRepairedVertices(), filter->GetFoldRepairedVertices() == 1 ? "ex" : "ices");

  timings.start("write");
  writePolyData(filter->GetOutput(), output);
  timings.stop();
  if (parsed.has("--timings")) std::printf("%s\n", timings.json().c_str());
  return kSuccess;
}

}  // namespace medial::cli
