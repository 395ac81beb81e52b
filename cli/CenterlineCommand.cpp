// `medial centerline VOLUME -o CENTERLINE.vtp [--label L | --threshold LO:HI] [--seed X,Y,Z] [--fill-holes]
//  [--profile PROFILE.csv] [--terrain TERRAIN.png] [--section-spacing K] [--section-rays N]`
#include "Commands.h"
#include "CommandLine.h"
#include "Progress.h"
#include "ReadInput.h"
#include "RunFilter.h"
#include "Timings.h"
#include "WriteOutput.h"
#include "WriteSections.h"

#include "MedialFileNames.h"
#include "vtkMedialTskCenterline.h"

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>

#include <cstdio>

namespace medial::cli {

int runCenterline(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(
      args, {{"-o", "--output", "--label", "--threshold", "--seed", "--profile", "--terrain", "--section-spacing",
              "--section-rays", "--antecedent-width", "--centering"},
             {"--fill-holes", "--keep-border-parts", "--branches", "--quiet", "--timings"}});
  if (parsed.positional.size() != 1) throw UsageError("centerline needs exactly one VOLUME (file or DICOM folder)");
  const std::string input = parsed.positional[0];
  const std::string output = parsed.value("-o", parsed.value("--output"));
  if (output.empty()) throw UsageError("centerline needs -o CENTERLINE.vtp");
  requireWritableExtension(output, "-o");
  if (parsed.has("--label") && parsed.has("--threshold")) throw UsageError("give --label or --threshold, not both");

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
  if (parsed.has("--keep-border-parts")) filter->DropBorderPartsOff();
  filter->SetFillHoles(parsed.has("--fill-holes"));
  if (parsed.has("--seed")) {
    const auto seed = parseNumbers(parsed.value("--seed"), 3, "--seed");
    filter->SetSeed(seed[0], seed[1], seed[2]);
  }
  if (parsed.has("--antecedent-width")) {
    const double width = parseNumbers(parsed.value("--antecedent-width"), 1, "--antecedent-width")[0];
    if (!(width > 0)) throw UsageError("--antecedent-width must be positive");
    filter->SetAntecedentWidth(width);
  }
  filter->SetDetectBranches(parsed.has("--branches"));
  if (parsed.has("--centering")) {
    const double passes = parseNumbers(parsed.value("--centering"), 1, "--centering")[0];
    if (!(passes >= 0 && passes <= 20 && passes == double(int(passes))))
      throw UsageError("--centering must be a whole number in 0..20");
    filter->SetCenteringIterations(int(passes));
  }
  const std::string profile = parsed.value("--profile"), terrain = parsed.value("--terrain");
  if (parsed.has("--profile") && profile.empty()) throw UsageError("--profile needs a file name");
  if (parsed.has("--terrain") && terrain.empty()) throw UsageError("--terrain needs a file name");
  if (!terrain.empty() && fileExtension(terrain) != ".png") throw UsageError("--terrain must end in .png: " + terrain);
  filter->SetComputeSections(!profile.empty() || !terrain.empty());
  if (parsed.has("--section-spacing")) {
    const double k = parseNumbers(parsed.value("--section-spacing"), 1, "--section-spacing")[0];
    if (!(k > 0)) throw UsageError("--section-spacing must be positive (mm)");
    filter->SetSectionSpacing(k);
  }
  if (parsed.has("--section-rays")) {
    const double n = parseNumbers(parsed.value("--section-rays"), 1, "--section-rays")[0];
    if (!(n >= 4 && n <= 3600 && n == double(int(n)))) throw UsageError("--section-rays must be a whole number in 4..3600");
    filter->SetSectionRays(int(n));
  }

  Timings timings;
  ProgressLine progress(parsed.has("--quiet"));
  timings.start("read");
  const vtkSmartPointer<vtkDataObject> data = readInput(input, progress);
  vtkImageData* image = vtkImageData::SafeDownCast(data);
  if (!image) throw Failure(input + ": not a volume");

  timings.start("centerline");
  runFilter(filter, image, input, "centerline of " + input, progress);

  timings.start("write");
  writePolyData(filter->GetOutput(), output);
  if (!profile.empty()) writeProfileCsv(vtkTable::SafeDownCast(filter->GetOutputDataObject(1)), profile);
  if (!terrain.empty()) writeTerrainPng(vtkImageData::SafeDownCast(filter->GetOutputDataObject(2)), terrain);
  timings.stop();
  if (parsed.has("--timings")) std::printf("%s\n", timings.json().c_str());
  return kSuccess;
}

}  // namespace medial::cli
