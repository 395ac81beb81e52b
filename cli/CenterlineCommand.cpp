// `medial centerline VOLUME -o CENTERLINE.vtp [--label L | --threshold LO:HI] [--seed X,Y,Z] [--fill-holes]
//  [--max-gap MM] [--min-part-volume MM3]
//  [--profile PROFILE.csv] [--terrain TERRAIN.png] [--section-spacing K] [--section-rays N] [--stages DIR]`
#include "Commands.h"
#include "CommandLine.h"
#include "FilterOptions.h"
#include "Progress.h"
#include "ReadInput.h"
#include "RunFilter.h"
#include "Timings.h"
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

int runCenterline(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(
      args,
      {{"-o", "--output", "--label", "--threshold", "--seed", "--profile", "--terrain", "--section-spacing",
        "--section-rays", "--antecedent-width", "--centering", "--max-gap", "--min-part-volume", "--stages"},
       {"--fill-holes", "--keep-border-parts", "--branches", "--quiet", "--timings"}});
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
  MEDIAL_OPTION(parsed, "--section-spacing", filter, SectionSpacing);
  MEDIAL_OPTION(parsed, "--section-rays", filter, SectionRays);
  const std::string stages = parsed.value("--stages");
  if (parsed.has("--stages")) {
    if (parsed.has("--branches")) throw UsageError("--stages follows one tube: not with --branches");
    makeOutputDirectory(stages, "--stages");
    filter->RecordStagesOn();
  }

  Timings timings;
  ProgressLine progress(parsed.has("--quiet"));
  timings.start("read");
  const vtkSmartPointer<vtkDataObject> data = readInput(input, progress);
  vtkImageData* image = vtkImageData::SafeDownCast(data);
  if (!image) throw Failure(input + ": not a volume");

  timings.start("centerline");
  runFilter(filter, image, input, "centerline of " + input, progress);

  for (int i = 0; i < filter->GetNumberOfNotes(); ++i) std::fprintf(stderr, "note: %s\n", filter->GetNote(i));

  timings.start("write");
  writePolyData(filter->GetOutput(), output);
  if (!profile.empty()) writeProfileCsv(vtkTable::SafeDownCast(filter->GetOutputDataObject(1)), profile);
  if (!terrain.empty()) writeTerrainPng(vtkImageData::SafeDownCast(filter->GetOutputDataObject(2)), terrain);
  if (!stages.empty()) writeStages(filter, stages);
  timings.stop();
  for (const std::string& stage : vtkMedialTskCenterline::GetStageNames())
    if (filter->GetStageSeconds(stage) > 0)
      timings.detail("centerline", stage, filter->GetStageSeconds(stage));
  if (parsed.has("--timings")) std::printf("%s\n", timings.json().c_str());
  return kSuccess;
}

}  // namespace medial::cli
