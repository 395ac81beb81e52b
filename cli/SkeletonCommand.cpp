// `medial skeleton MESH -o SKELETON.vtp [--segmentation MESH_OUT.vtp] [--nodes N] [--rig RIG.glb|RIG.fbx]
//                  [--weights] [--solver NAME] [--iterations N] [--contraction-vertices N] [--no-refine]`
#include "Commands.h"
#include "CommandLine.h"
#include "FilterOptions.h"
#include "Progress.h"
#include "ReadInput.h"
#include "RunFilter.h"
#include "WriteOutput.h"
#include "Timings.h"

#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialRigWriter.h"

#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdio>

namespace medial::cli {

namespace {

// The contracted mesh (paper Fig. 5): the triangulated input with its points where the contraction took
// them (the segmentation's ContractedPosition), its point data kept.
vtkSmartPointer<vtkPolyData> contractedMesh(vtkPolyData* segmentation) {
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(segmentation);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetData(segmentation->GetPointData()->GetArray("ContractedPosition"));
  mesh->SetPoints(points);
  return mesh;
}

// --contraction-steps DIR: the paper's intermediate results. contraction_NNN.vtp per step (Fig. 5, with
// the weights of Fig. 7), contraction.pvd (the steps as a time series that ParaView plays), and the curve
// skeleton after the surgery and before the selection.
void writeStages(vtkMedialContractionSkeleton* filter, const std::string& dir) {
  std::string collection =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (int step = 0; step < filter->GetNumberOfContractionSteps(); ++step) {
    char name[32];
    std::snprintf(name, sizeof name, "contraction_%03d.vtp", step);
    writePolyData(filter->GetContractionStep(step), dir + "/" + name);
    collection += "    <DataSet timestep=\"" + std::to_string(step) + "\" file=\"" + name + "\"/>\n";
  }
  collection += "  </Collection>\n</VTKFile>\n";
  writeText(collection, dir + "/contraction.pvd");
  writePolyData(filter->GetSurgerySkeleton(), dir + "/surgery-skeleton.vtp");
  writePolyData(filter->GetUnselectedSkeleton(), dir + "/unselected-skeleton.vtp");
}

}  // namespace

int runSkeleton(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(
      args, {{"-o",
              "--output",
              "--segmentation",
              "--nodes",
              "--rig",
              "--solver",
              "--iterations",
              "--contraction-vertices",
              "--reference-vertices",
              "--wl0",
              "--sl",
              "--wh0",
              "--max-wl",
              "--max-wh",
              "--shape-weight",
              "--sampling-weight",
              "--collapse-length",
              "--heat",
              "--contracted",
              "--contraction-steps"},
             {"--no-refine", "--no-cycle-repair", "--no-centring", "--weights", "--quiet", "--timings"}});
  if (parsed.positional.size() != 1) throw UsageError("skeleton needs exactly one MESH file");
  const std::string input = parsed.positional[0];
  const std::string output = parsed.value("-o", parsed.value("--output"));
  if (output.empty()) throw UsageError("skeleton needs -o SKELETON.vtp");
  requireWritableExtension(output, "-o");
  const std::string segmentation = parsed.value("--segmentation");
  if (!segmentation.empty()) requireWritableExtension(segmentation, "--segmentation");
  const std::string contracted = parsed.value("--contracted");
  if (parsed.has("--contracted")) requireWritableExtension(contracted, "--contracted");
  const std::string rig = parsed.value("--rig");
  if (parsed.has("--rig") && !vtkMedialRigWriter::CanWriteFile(rig.c_str()))
    throw UsageError(std::string("--rig must end in one of ") + vtkMedialRigWriter::GetExtensions() + ": " +
                     rig);

  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  MEDIAL_OPTION(parsed, "--nodes", filter, TargetNodes);
  MEDIAL_OPTION(parsed, "--contraction-vertices", filter, ContractionVertices);
  MEDIAL_OPTION(parsed, "--iterations", filter, MaxIterations);
  // The paper's constants (§III): W_L0 factor, s_L, W_H0, the W_L and W_H caps, w_a, w_b, delta, heat c.
  MEDIAL_OPTION(parsed, "--reference-vertices", filter, ReferenceVertices);
  MEDIAL_OPTION(parsed, "--wl0", filter, InitialContractionFactor);
  MEDIAL_OPTION(parsed, "--sl", filter, ContractionScale);
  MEDIAL_OPTION(parsed, "--wh0", filter, InitialAttractionWeight);
  MEDIAL_OPTION(parsed, "--max-wl", filter, MaxContractionWeight);
  MEDIAL_OPTION(parsed, "--max-wh", filter, MaxAttractionWeight);
  MEDIAL_OPTION(parsed, "--shape-weight", filter, ShapeWeight);
  MEDIAL_OPTION(parsed, "--sampling-weight", filter, SamplingWeight);
  MEDIAL_OPTION(parsed, "--collapse-length", filter, CollapseLengthFraction);
  MEDIAL_OPTION(parsed, "--heat", filter, HeatConstant);
  setNameFromOption(parsed, "--solver", filter, [&](const std::string& name) { filter->SetSolver(name); });
  if (parsed.has("--no-refine")) filter->RefineEmbeddingOff();
  if (parsed.has("--no-cycle-repair")) filter->RestoreCyclesOff();
  if (parsed.has("--no-centring")) filter->CentreNodesOff();
  if (parsed.has("--rig") || parsed.has("--weights")) filter->ComputeWeightsOn();
  const std::string stepsDir = parsed.value("--contraction-steps");
  if (parsed.has("--contraction-steps")) {
    makeOutputDirectory(stepsDir, "--contraction-steps");
    filter->RecordStagesOn();
  }

  Timings timings;
  ProgressLine progress(parsed.has("--quiet"));
  timings.start("read");
  const vtkSmartPointer<vtkDataObject> data = readInput(input, progress);
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(data);
  if (!mesh || mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() == 0)
    throw Failure(input + ": not a surface mesh (no polygons)");

  timings.start("skeleton");
  runFilter(filter, mesh, input, "skeleton of " + input, progress);
  for (const std::string& stage : vtkMedialContractionSkeleton::GetStageNames())
    timings.detail("skeleton", stage, filter->GetStageSeconds(stage));

  if (filter->GetRestoredCycles() > 0)
    std::fprintf(
        stderr, "medial skeleton: note: %d cycle%s that surgery lost put back (the mesh has genus %d)\n",
        filter->GetRestoredCycles(), filter->GetRestoredCycles() == 1 ? "" : "s", filter->GetGenus());
  timings.start("write");
  writePolyData(filter->GetOutput(0), output);
  if (!segmentation.empty()) writePolyData(filter->GetOutput(1), segmentation);
  if (!contracted.empty()) writePolyData(contractedMesh(filter->GetOutput(1)), contracted);
  if (!stepsDir.empty()) writeStages(filter, stepsDir);
  if (!rig.empty())
    writeRig(vtkSmartPointer<vtkMedialRigWriter>::New(), filter->GetOutput(1), filter->GetOutput(0), rig);
  timings.stop();
  if (parsed.has("--timings")) std::printf("%s\n", timings.json().c_str());
  return kSuccess;
}

}  // namespace medial::cli
