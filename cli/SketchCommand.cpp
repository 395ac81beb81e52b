// `medial sketch POLYGON.txt -o SKELETON.vtp [--mesh MESH.vtp] [--simplify ES] [--merge EM] [--prune ET]
//                [--collapse EC] [--part K:ES,EM,ET,EC]... [--unit U] [--thickness C] [--separate-parts]
//                [--stages DIR]`
#include "CommandRun.h"
#include "Commands.h"
#include "HelpText.h"
#include "CommandLine.h"
#include "FilterOptions.h"
#include "WriteOutput.h"

#include "MedialSketchData.h"
#include "vtkMedialSketchSkeleton.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdio>

namespace medial::cli {
// The options of `medial sketch`: those that take a value, and the flags (medial sketch --list-options).
const OptionSpec& sketchOptions() {
  static const OptionSpec spec = {{"-o", "--output", "--mesh", "--simplify", "--merge", "--prune",
                                   "--collapse", "--part", "--unit", "--thickness", "--resample", "--stages"},
                                  {"--separate-parts", "--quiet", "--timings"}};
  return spec;
}

// The --help text of `medial sketch`, built once; its defaults and names are a fresh filter's.
const std::string& sketchUsage() {
  static const std::string text = [] {
    const auto sketch = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
    return std::string() +
           "usage: medial sketch POLYGON.txt -o SKELETON.vtp [--mesh MESH.vtp] [--simplify ES] [--merge EM]\n"
           "                     [--prune ET] [--collapse EC] [--part K:ES,EM,ET,EC]... [--unit U]\n"
           "                     [--resample STEP] [--thickness C] [--separate-parts] [--stages DIR]\n"
           "                     [--quiet] [--timings]\n\n"
           "Skeletonizes sketched outlines (Ma et al. 2021): each closed stroke of POLYGON.txt ('x y' lines, "
           "parts\n"
           "separated by a blank line, each optionally followed by four rows of its 4x4 placement matrix) "
           "gets "
           "a\n"
           "straight skeleton simplified by BoundedDP; parts are joined in drawing order where they "
           "intersect "
           "and\n"
           "the whole is refined. Lengths are sketch pixels: a thousandth of the drawing's diagonal (see "
           "--unit).\n"
           "  -o, --output SKELETON     the skeleton (.vtp: Radius, NodeType, Root, Part, Branch; .vtk .obj "
           ".ply)\n"
           "  --mesh MESH               the inflated strokes joined into one watertight triangle mesh (the "
           "union\n"
           "                            of their volumes), point data Part\n"
           "  --separate-parts          with --mesh: one closed mesh per stroke, left overlapping\n"
           "  --simplify ES             branch simplification threshold epsilon_s (default " +
           number(sketch->GetSimplificationThreshold()) +
           ")\n"
           "  --merge EM                junction merging threshold epsilon_m (default " +
           number(sketch->GetMergingThreshold()) +
           ")\n"
           "  --prune ET                branch pruning threshold epsilon_t (default " +
           number(sketch->GetPruningThreshold()) +
           ")\n"
           "  --collapse EC             edge collapsing threshold epsilon_c (default " +
           number(sketch->GetCollapsingThreshold()) +
           ")\n"
           "  --part K:ES,EM,ET,EC      the four thresholds for part K only (from 1); repeatable\n"
           "  --unit U                  stroke units per sketch pixel (default: diagonal / 1000)\n"
           "  --resample STEP           stroke resampling step in sketch pixels (default " +
           number(sketch->GetResampleStep()) +
           ")\n"
           "  --thickness C             inflation thickness (default " +
           number(sketch->GetThickness()) +
           ": round tubes)\n"
           "  --stages DIR              the skeleton after each step in DIR: straight-skeleton.vtp, "
           "bounded-dp.vtp,\n"
           "                            connected.vtp, pruned.vtp, merged.vtp (with Part and Branch)\n"
           "  --quiet                   no progress line\n"
           "  --timings                 print stage times as JSON on stdout\n";
  }();
  return text;
}

int runSketch(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, sketchOptions());
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
  CommandRun command(parsed);
  const std::string stages = command.stagesFolder(filter.Get());
  const vtkSmartPointer<vtkPolyData> strokes = vtkPolyData::SafeDownCast(command.read(input));
  if (!medial::isSketch(strokes)) throw Failure(input + ": not a sketch (no strokes)");
  command.run(filter, strokes, input, "sketch", "skeleton of " + input);

  command.timings().start("write");
  writePolyData(filter->GetOutput(0), output);
  if (!meshOutput.empty()) writePolyData(filter->GetOutput(1), meshOutput);
  for (const std::string& stage : vtkMedialSketchSkeleton::GetStageSkeletonNames())  // --stages
    if (!stages.empty()) writePolyData(filter->GetStageSkeleton(stage), stages + "/" + stage + ".vtp");
  return command.finish();
}

}  // namespace medial::cli
