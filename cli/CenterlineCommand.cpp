// `medial centerline VOLUME -o CENTERLINE.vtp [--label L | --threshold LO:HI] [--seed X,Y,Z] [--fill-holes]
//  [--max-gap MM] [--min-part-volume MM3]
//  [--markups CURVE.mrk.json] [--profile PROFILE.csv] [--terrain TERRAIN.png] [--section-spacing K]
//  [--section-rays N] [--stages DIR]`
#include "CommandRun.h"
#include "Commands.h"
#include "HelpText.h"
#include "CommandLine.h"
#include "FilterOptions.h"
#include "WriteOutput.h"
#include "WriteSections.h"

#include "MedialFileNames.h"
#include "vtkMedialTskCenterline.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkXMLImageDataWriter.h>

#include <cstdio>

namespace medial::cli {

namespace {

// --stages DIR: the paper's intermediate results: voxels.vtp (Layer, Cluster, T), labels.vti (the same as
// label volumes), primitive.vtp, the TSK models as tsk-model.vtp (the curve before centring) and
// tsk-fits.csv (t, x, y, z).
void writeStages(vtkMedialTskCenterline* filter, const std::string& dir) {
  for (const std::string& name : vtkMedialTskCenterline::GetStageDataNames())
    if (vtkPolyData* stage = filter->GetStageData(name)) writePolyData(stage, dir + "/" + name + ".vtp");
  if (vtkImageData* labels = filter->GetStageLabels()) {
    std::string error;
    const auto write = [labels](const std::string& temporary, std::string& why) {
      auto writer = vtkSmartPointer<vtkXMLImageDataWriter>::New();
      writer->SetFileName(temporary.c_str());
      writer->SetInputData(labels);
      if (writer->Write() != 1) why = "cannot write the file";
      return why.empty();
    };
    if (!medial::writeAtomically(dir + "/labels.vti", write, error))
      throw Failure(dir + "/labels.vti: " + error);
  }
  vtkPolyData* model = filter->GetStageData("tsk-model");
  if (!model) return;
  std::string csv = "t,x_mm,y_mm,z_mm\n";
  vtkDataArray* t = model->GetPointData()->GetArray("T");
  for (vtkIdType k = 0; k < model->GetNumberOfPoints(); ++k) {
    double p[3];
    model->GetPoint(k, p);
    char row[160];
    std::snprintf(row, sizeof row, "%.6f,%.4f,%.4f,%.4f\n", t->GetComponent(k, 0), p[0], p[1], p[2]);
    csv += row;
  }
  writeText(csv, dir + "/tsk-fits.csv");
}

}  // namespace

// The options of `medial centerline`: those that take a value, and the flags (medial centerline
// --list-options).
const OptionSpec& centerlineOptions() {
  static const OptionSpec spec = {
      {"-o", "--output", "--label", "--threshold", "--seed", "--profile", "--terrain", "--section-spacing",
       "--section-rays", "--antecedent-width", "--centering", "--max-gap", "--min-part-volume", "--stages",
       "--markups", "--surface"},
      {"--fill-holes", "--keep-border-parts", "--branches", "--quiet", "--timings"}};
  return spec;
}

// The --help text of `medial centerline`, built once; its defaults and names are a fresh filter's.
const std::string& centerlineUsage() {
  static const std::string text = [] {
    const auto tsk = vtkSmartPointer<vtkMedialTskCenterline>::New();
    return std::string() +
           "usage: medial centerline VOLUME -o CENTERLINE.vtp [--label L | --threshold LO:HI] [--seed "
           "X,Y,Z]\n"
           "                         [--fill-holes] [--keep-border-parts] [--max-gap MM] [--min-part-volume "
           "MM3]\n"
           "                         [--branches] [--antecedent-width W] [--centering N]\n"
           "                         [--markups C.mrk.json] [--surface LUMEN.vtp] [--profile P.csv]\n"
           "                         [--terrain T.png] [--section-spacing K] [--section-rays N]\n"
           "                         [--stages DIR] [--quiet] [--timings]\n\n"
           "Follows a tube (colon, vessel) in VOLUME (.nii .nii.gz .mha .mhd .nrrd .inr .vti or a DICOM "
           "folder) "
           "by\n"
           "the TSK method (WSCG 2008): layers and cylindrical clusters from P0, then three "
           "Takagi-Sugeno-Kang\n"
           "models. The structure: voxels equal to L, or within LO..HI (parts touching the volume's border "
           "are\n"
           "dropped: the air outside the body); without either, a CT in Hounsfield units gives its air "
           "(up to -600,\n"
           "with a note) and any other volume its non-zero voxels. A structure in several parts (a "
           "colon\n"
           "split by collapsed or fluid-filled segments) is followed part by part and chained from the "
           "lowest\n"
           "end across each gap by the least-cost path through the volume (point data Bridged = 1 there).\n"
           "  -o, --output CENTERLINE   one polyline in mm with Radius and ArcLength (.vtp .vtk ...)\n"
           "  --label L                 the structure is the voxels of label L\n"
           "  --threshold LO:HI         the structure is the voxels in LO..HI (e.g. -1024:-600 for colon "
           "air)\n"
           "  --seed X,Y,Z              P0 in mm (default: the lowest end of the structure)\n"
           "  --fill-holes              fill cavities of the structure first\n"
           "  --keep-border-parts       keep thresholded parts that touch the volume's border\n"
           "  --max-gap MM              longest gap bridged between parts (default " +
           number(tsk->GetMaxGap()) +
           "; a longer one starts another\n"
           "                            polyline, with a note; 0 = the largest part only)\n"
           "  --min-part-volume MM3     smaller parts are left out (default " +
           number(tsk->GetMinimumPartVolume()) +
           ")\n"
           "  --antecedent-width W      TSK Gaussian width relative to a cluster (default " +
           number(tsk->GetAntecedentWidth()) +
           ")\n"
           "  --branches                a branching structure (vessels, airways): one polyline per branch,\n"
           "                            cell data Branch and ParentBranch (sections follow the first one)\n"
           "  --centering N             passes moving the axis to the centre of its sections (the paper's\n"
           "                            centricity criterion; default " +
           number(tsk->GetCenteringIterations()) +
           ", 0 = the TSK curve as is)\n"
           "  --markups CURVE.mrk.json  the centerline as 3D Slicer markups curves (one per branch, LPS, "
           "mm),\n"
           "                            with Radius per control point (Slicer: drag the file in)\n"
           "  --surface LUMEN.vtp       the closed surface of the followed lumen (smoothed, at most 100,000\n"
           "                            triangles), the centerline inside it: for fly-throughs and ghost "
           "views\n"
           "  --profile PROFILE.csv     perpendicular sections every K mm: arc length, min/max diameter,\n"
           "                            perimeter (mm) and area (mm2) per row (paper section 4, Fig. 14)\n"
           "  --terrain TERRAIN.png     the unfolded wall: distance from the axis over angle (x) and arc\n"
           "                            length (y, from the top), white = far (Fig. 15)\n"
           "  --section-spacing K       mm between sections (default " +
           number(tsk->GetSectionSpacing()) +
           ")\n"
           "  --section-rays N          angles per section (default " +
           number(tsk->GetSectionRays()) +
           ")\n"
           "  --stages DIR              the paper's intermediate results in DIR: voxels.vtp (the "
           "structure's\n"
           "                            voxels with Layer, Cluster and the order T: Figs. 3, 7-8), "
           "labels.vti\n"
           "                            (the same as label volumes),\n"
           "                            primitive.vtp (the primitive centerline, Figs. 4-6), tsk-model.vtp\n"
           "                            (the curve before centring) and tsk-fits.csv (x, y, z over t, Figs.\n"
           "                            9-10)\n"
           "  --quiet                   no progress line\n"
           "  --timings                 print stage times as JSON on stdout\n";
  }();
  return text;
}

int runCenterline(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, centerlineOptions());
  if (parsed.positional.size() != 1)
    throw UsageError("centerline needs exactly one VOLUME (file or DICOM folder)");
  const std::string input = parsed.positional[0];
  const std::string output = parsed.value("-o", parsed.value("--output"));
  if (output.empty()) throw UsageError("centerline needs -o CENTERLINE.vtp");
  requireWritableExtension(output, "-o");
  if (parsed.has("--label") && parsed.has("--threshold"))
    throw UsageError("give --label or --threshold, not both");

  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  if (parsed.has("--label")) {
    const double label = parseNumbers(parsed.value("--label"), 1, "--label")[0];
    if (label != double(int(label))) throw UsageError("--label must be a whole number");
    filter->SetLabel(int(label));
  }
  if (parsed.has("--threshold")) {
    std::string range = parsed.value("--threshold");
    const size_t colon = range.find(':', 1);  // LO may be negative: -1024:-600
    if (colon == std::string::npos) throw UsageError("--threshold expects LO:HI, got '" + range + "'");
    const double low = parseNumbers(range.substr(0, colon), 1, "--threshold")[0];
    const double high = parseNumbers(range.substr(colon + 1), 1, "--threshold")[0];
    if (!(low <= high)) throw UsageError("--threshold expects LO <= HI");
    filter->SetThreshold(low, high);
  }
  if (parsed.has("--keep-border-parts")) filter->SetBorderParts(vtkMedialTskCenterline::BORDER_PARTS_KEEP);
  if (parsed.has("--fill-holes")) filter->FillHolesOn();
  if (parsed.has("--seed")) {
    const auto seed = parseNumbers(parsed.value("--seed"), 3, "--seed");
    filter->SetSeed(seed[0], seed[1], seed[2]);
  }
  MEDIAL_OPTION(parsed, "--max-gap", filter, MaxGap);
  MEDIAL_OPTION(parsed, "--min-part-volume", filter, MinimumPartVolume);
  MEDIAL_OPTION(parsed, "--antecedent-width", filter, AntecedentWidth);
  if (parsed.has("--branches")) filter->DetectBranchesOn();
  MEDIAL_OPTION(parsed, "--centering", filter, CenteringIterations);
  const std::string profile = parsed.value("--profile"), terrain = parsed.value("--terrain");
  if (parsed.has("--profile") && profile.empty()) throw UsageError("--profile needs a file name");
  if (parsed.has("--terrain") && terrain.empty()) throw UsageError("--terrain needs a file name");
  if (!terrain.empty() && fileExtension(terrain) != ".png")
    throw UsageError("--terrain must end in .png: " + terrain);
  if (!profile.empty() || !terrain.empty()) filter->ComputeSectionsOn();
  const std::string surface = parsed.value("--surface");
  if (parsed.has("--surface")) requireWritableExtension(surface, "--surface");
  if (!surface.empty()) filter->ComputeSurfaceOn();
  const std::string markups = parsed.value("--markups");
  if (parsed.has("--markups") && fileExtension(markups) != ".json" && fileExtension(markups) != ".mrk.json")
    throw UsageError("--markups must end in .mrk.json: " + markups);
  MEDIAL_OPTION(parsed, "--section-spacing", filter, SectionSpacing);
  MEDIAL_OPTION(parsed, "--section-rays", filter, SectionRays);
  if (parsed.has("--stages") && parsed.has("--branches"))
    throw UsageError("--stages follows one tube: not with --branches");
  CommandRun command(parsed);
  const std::string stages = command.stagesFolder(filter.Get());
  const vtkSmartPointer<vtkImageData> image = vtkImageData::SafeDownCast(command.read(input));
  if (!image) throw Failure(input + ": not a volume");
  command.run(filter, image, input, "centerline", "centerline of " + input);

  for (int i = 0; i < filter->GetNumberOfNotes(); ++i) std::fprintf(stderr, "note: %s\n", filter->GetNote(i));

  command.timings().start("write");
  writePolyData(filter->GetOutput(), output);
  if (!markups.empty()) writeMarkups(filter->GetOutput(), markups);
  if (!surface.empty()) writePolyData(vtkPolyData::SafeDownCast(filter->GetOutputDataObject(3)), surface);
  if (!profile.empty()) writeProfileCsv(vtkTable::SafeDownCast(filter->GetOutputDataObject(1)), profile);
  if (!terrain.empty()) writeTerrainPng(vtkImageData::SafeDownCast(filter->GetOutputDataObject(2)), terrain);
  if (!stages.empty()) writeStages(filter, stages);
  for (const std::string& stage : vtkMedialTskCenterline::GetStageNames())
    if (filter->GetStageSeconds(stage) > 0)
      command.timings().detail("centerline", stage, filter->GetStageSeconds(stage));
  return command.finish();
}

}  // namespace medial::cli
