// `medial sketch POLYGON.txt -o SKELETON.vtp [--mesh MESH.vtp] [--simplify ES] [--merge EM] [--prune ET]
//                [--collapse EC] [--part K:ES,EM,ET,EC]... [--unit U] [--thickness C] [--separate-parts]
//                [--stages DIR]`
#include "Commands.h"
#include "CommandLine.h"
#include "FilterOptions.h"
#include "Progress.h"
#include "ReadInput.h"
#include "RunFilter.h"
#include "Timings.h"
#include "WriteOutput.h"

#include "MedialSketchData.h"
#include "vtkMedialSketchSkeleton.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdio>

namespace medial::cli {
int runSketch(const std::vector<std::string>& args) {
  const ParsedArgs parsed =
      parseArgs(args, {{"-o", "--output", "--mesh", "--simplify", "--merge", "--prune", "--collapse",
                        "--part", "--unit", "--thickness", "--resample", "--stages"},
                       {"--separate-parts", "--quiet", "--timings"}});
  if (parsed.positional.size() != 1) throw UsageError("sketch needs exactly one POLYGON file");
  const std::string input = parsed.positional[0];
  const std::string output = parsed.value("-o", parsed.value("--output"));
  if (output.empty()) throw UsageError("sketch needs -o SKELETON.vtp");
  requireWritableExtension(output, "-o");
  const std::string meshOutput = parsed.value("--mesh");
  if (!meshOutput.empty()) requireWritableExtension(meshOutput, "--mesh");

  auto filter = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
  MEDIAL_OPTION(parsed, "--simplify", filter, SimplificationThreshold);
  MEDIAL_OPTION(parsed, "--merge", filter, MergingThreshold);
  MEDIAL_OPTION(parsed, "--prune", filter, PruningThreshold);
  MEDIAL_OPTION(parsed, "--collapse", filter, CollapsingThreshold);
  MEDIAL_OPTION(parsed, "--unit", filter, UnitLength);
  MEDIAL_OPTION(parsed, "--thickness", filter, Thickness);
  MEDIAL_OPTION(parsed, "--resample", filter, ResampleStep);
  for (const std::string& text : parsed.all("--part")) {
    const size_t colon = text.find(':');
    if (colon == std::string::npos)
      throw UsageError("--part takes K:ES,EM,ET,EC (part number from 1, four thresholds)");
    const double k = parseNumbers(text.substr(0, colon), 1, "--part")[0];
    const std::vector<double> t = parseNumbers(text.substr(colon + 1), 4, "--part");
    if (!(k >= 1) || k != int(k)) throw UsageError("--part: the part number must be a whole number >= 1");
    for (double v : t)
      if (!(v >= 0)) throw UsageError("--part: thresholds must be numbers >= 0");
    filter->SetPartThresholds(int(k) - 1, t[0], t[1], t[2], t[3]);
  }
  if (meshOutput.empty()) filter->InflateOff();
  if (parsed.has("--separate-parts")) filter->MergePartsOff();
  const std::string stages = parsed.value("--stages");
  if (parsed.has("--stages")) {
    makeOutputDirectory(stages, "--stages");
    filter->RecordStagesOn();
  }

  Timings timings;
  ProgressLine progress(parsed.has("--quiet"));
  timings.start("read");
  const vtkSmartPointer<vtkDataObject> data = readInput(input, progress);
  vtkPolyData* strokes = vtkPolyData::SafeDownCast(data);
  if (!medial::isSketch(strokes)) throw Failure(input + ": not a sketch (no strokes)");
  timings.start("sketch");
  runFilter(filter, strokes, input, "skeleton of " + input, progress);

  timings.start("write");
  writePolyData(filter->GetOutput(0), output);
  if (!meshOutput.empty()) writePolyData(filter->GetOutput(1), meshOutput);
  for (const std::string& stage : vtkMedialSketchSkeleton::GetStageSkeletonNames())  // --stages
    if (!stages.empty()) writePolyData(filter->GetStageSkeleton(stage), stages + "/" + stage + ".vtp");
  timings.stop();
  if (parsed.has("--timings")) std::printf("%s\n", timings.json().c_str());
  return kSuccess;
}

}  // namespace medial::cli
