// `medial sketch POLYGON.txt -o SKELETON.vtp [--mesh MESH.vtp] [--simplify ES] [--merge EM] [--prune ET]
//                [--collapse EC] [--part K:ES,EM,ET,EC]... [--unit U] [--thickness C] [--no-mesh]`
#include "Commands.h"
#include "CommandLine.h"
#include "Progress.h"
#include "RunFilter.h"
#include "Timings.h"
#include "WriteOutput.h"

#include "MedialErrorCollector.h"
#include "vtkMedialSketchReader.h"
#include "vtkMedialSketchSkeleton.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdio>

namespace medial::cli {
namespace {

double nonNegative(const ParsedArgs& parsed, const char* option, double fallback) {
  if (!parsed.has(option)) return fallback;
  const double value = parseNumbers(parsed.value(option), 1, option)[0];
  if (!(value >= 0)) throw UsageError(std::string(option) + " must be a number >= 0");
  return value;
}

}  // namespace

int runSketch(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, {{"-o", "--output", "--mesh", "--simplify", "--merge", "--prune", "--collapse",
                                              "--part", "--unit", "--thickness", "--resample"},
                                             {"--quiet", "--timings"}});
  if (parsed.positional.size() != 1) throw UsageError("sketch needs exactly one POLYGON file");
  const std::string input = parsed.positional[0];
  const std::string output = parsed.value("-o", parsed.value("--output"));
  if (output.empty()) throw UsageError("sketch needs -o SKELETON.vtp");
  requireWritableExtension(output, "-o");
  const std::string meshOutput = parsed.value("--mesh");
  if (!meshOutput.empty()) requireWritableExtension(meshOutput, "--mesh");

  auto filter = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
  filter->SetSimplificationThreshold(nonNegative(parsed, "--simplify", 5));
  filter->SetMergingThreshold(nonNegative(parsed, "--merge", 30));
  filter->SetPruningThreshold(nonNegative(parsed, "--prune", 30));
  filter->SetCollapsingThreshold(nonNegative(parsed, "--collapse", 10));
  filter->SetUnitLength(nonNegative(parsed, "--unit", 0));
  if (parsed.has("--thickness")) {
    const double c = parseNumbers(parsed.value("--thickness"), 1, "--thickness")[0];
    if (!(c > 0)) throw UsageError("--thickness must be a number > 0");
    filter->SetThickness(c);
  }
  if (parsed.has("--resample")) {
    const double step = parseNumbers(parsed.value("--resample"), 1, "--resample")[0];
    if (!(step > 0)) throw UsageError("--resample must be a number > 0");
    filter->SetResampleStep(step);
  }
  for (const std::string& text : parsed.all("--part")) {
    const size_t colon = text.find(':');
    if (colon == std::string::npos) throw UsageError("--part takes K:ES,EM,ET,EC (part number from 1, four thresholds)");
    const double k = parseNumbers(text.substr(0, colon), 1, "--part")[0];
    const std::vector<double> t = parseNumbers(text.substr(colon + 1), 4, "--part");
    if (!(k >= 1) || k != int(k)) throw UsageError("--part: the part number must be a whole number >= 1");
    for (double v : t)
      if (!(v >= 0)) throw UsageError("--part: thresholds must be numbers >= 0");
    filter->SetPartThresholds(int(k) - 1, t[0], t[1], t[2], t[3]);
  }
  filter->SetInflate(!meshOutput.empty());

  Timings timings;
  ProgressLine progress(parsed.has("--quiet"));
  timings.start("read");
  auto reader = vtkSmartPointer<vtkMedialSketchReader>::New();
  {
    auto errors = medial::ErrorCollector::Watch(reader);
    reader->SetFileName(input.c_str());
    reader->Update();
    if (errors->HasErrors()) throw Failure(errors->Joined());
  }
  timings.start("sketch");
  runFilter(filter, reader->GetOutput(), input, "skeleton of " + input, progress);

  timings.start("write");
  writePolyData(filter->GetOutput(0), output);
  if (!meshOutput.empty()) writePolyData(filter->GetOutput(1), meshOutput);
  timings.stop();
  if (parsed.has("--timings")) std::printf("%s\n", timings.json().c_str());
  return kSuccess;
}

}  // namespace medial::cli
