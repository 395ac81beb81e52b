// `medial skeleton MESH -o SKELETON.vtp [--segmentation MESH_OUT.vtp] [--nodes N] [--rig RIG.glb|RIG.fbx]
//                  [--weights] [--solver NAME] [--iterations N] [--contraction-vertices N] [--no-refine]`
#include "CommandRun.h"
#include "Commands.h"
#include "HelpText.h"
#include "CommandLine.h"
#include "FilterOptions.h"
#include "RigOptions.h"
#include "WriteOutput.h"

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

// The options of `medial skeleton`: those that take a value, and the flags (medial skeleton --list-options).
const OptionSpec& skeletonOptions() {
  static const OptionSpec spec = {{"-o",
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
                                  {"--no-refine", "--no-cycle-repair", "--no-centering", "--no-centring",
                                   "--weights", "--quiet", "--timings"}};
  static const OptionSpec withRig = [] {
    OptionSpec options = spec;
    for (const std::string& name : rigWriterOptionNames()) options.withValue.insert(name);
    return options;
  }();
  return withRig;
}

// The --help text of `medial skeleton`, built once; its defaults and names are a fresh filter's.
const std::string& skeletonUsage() {
  static const std::string text = [] {
    const auto contraction = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
    return std::string() +
           "usage: medial skeleton MESH -o SKELETON.vtp [--segmentation MESH_OUT.vtp] [--nodes N] [--rig "
           "RIG.glb|RIG.fbx]\n"
           "                       [--weights] [--solver NAME] [--iterations N] [--contraction-vertices N]\n"
           "                       [--reference-vertices N] [--wl0 F] [--sl S] [--wh0 W] [--max-wl W]\n"
           "                       [--max-wh W] [--shape-weight A] [--sampling-weight B] [--collapse-length "
           "D]\n"
           "                       [--heat C] [--contracted MESH] [--no-refine] [--no-cycle-repair]\n"
           "                       [--no-centering] [--contraction-steps DIR] [--up-axis AXIS] [--scale F]\n"
           "                       [--max-influences N] [--quiet] [--timings]\n\n"
           "Contracts MESH (.off .obj .ply .stl .vtp .vtk; polygons are triangulated) by constrained "
           "Laplacian\n"
           "smoothing and collapses it into a curve skeleton with a Radius per node (the contraction paper, "
           "III.A-D);\n"
           "with --rig, also computes heat-diffusion skinning weights (III.E) and writes a rig (III.F).\n"
           "  -o, --output SKELETON     the skeleton: .vtp (nodes, edges, Radius, Root) or .vtk .obj .ply\n"
           "  --segmentation MESH_OUT   the triangulated mesh with point data SkeletonNode (vertex -> "
           "node),\n"
           "                            and SkinWeights (one component per bone) with --rig or --weights\n"
           "  --nodes N                 the skeleton's node count (default " +
           number(contraction->GetTargetNodes()) +
           "; 0 keeps all): exactly N,\n"
           "                            or more where fewer would take a bone out of the mesh, or fewer\n"
           "                            where the curve skeleton has fewer (a note on stderr says so)\n" +
           namesHelp("--solver NAME", "", vtkMedialContractionSkeleton::GetSolverNames(),
                     contraction->GetSolver()) +
           "  --iterations N            maximum contraction iterations (default " +
           number(contraction->GetMaxIterations()) +
           ")\n"
           "  --contraction-vertices N  a mesh with more vertices is decimated to N (quadric error, "
           "topology\n"
           "                            kept) before the contraction; the outputs still cover every input\n"
           "                            vertex (default " +
           number(contraction->GetContractionVertices()) +
           "; 0 contracts the mesh as it is)\n"
           "  --wl0 F, --sl S, --wh0 W  the paper's W_L0 = F sqrt(mean face area) (default " +
           number(contraction->GetInitialContractionFactor()) + "), s_L (" +
           number(contraction->GetContractionScale()) + "), W_H0 (" +
           number(contraction->GetInitialAttractionWeight()) +
           ")\n"
           "  --reference-vertices N    a mesh contracted with n > N vertices starts with W_L0\n"
           "                            x (n / N)^1.5, so that its first iterations contract as an\n"
           "                            N-vertex mesh's do (default " +
           number(contraction->GetReferenceVertices()) +
           "; 0: the paper's\n"
           "                            W_L0 at any size)\n"
           "  --max-wl W, --max-wh W    caps on W_L and W_H (defaults " +
           number(contraction->GetMaxContractionWeight()) + ", " +
           number(contraction->GetMaxAttractionWeight()) +
           ")\n"
           "  --shape-weight A          w_a and w_b of the surgery's cost (defaults " +
           number(contraction->GetShapeWeight()) + ", " + number(contraction->GetSamplingWeight()) +
           ")\n"
           "  --sampling-weight B\n"
           "  --collapse-length D       delta: edges shorter than D x the contracted mesh's size collapse\n"
           "                            first (default " +
           number(contraction->GetCollapseLengthFraction()) +
           ")\n"
           "  --heat C                  c of the heat weights' H = c / d^2 (default " +
           number(contraction->GetHeatConstant()) +
           ")\n"
           "  --no-refine               keep the nodes where the contraction put them (no III.C refinement)\n"
           "  --no-cycle-repair         leave out the cycles surgery lost (by default they are put back, so\n"
           "                            that the skeleton has as many cycles as the closed mesh has genus)\n"
           "  --no-centering            keep the refined nodes where they are (by default a node of one or\n"
           "                            two edges moves to the centroid of the mesh's cross-section through\n"
           "                            it)\n"
           "  --contraction-steps DIR   the paper's intermediate results in DIR: contraction_NNN.vtp, the "
           "mesh\n"
           "                            after each iteration (Fig. 5) with point data Laplacian (|L V|) and\n"
           "                            AttractionWeight (W_H), field ContractionWeight (W_L) (Fig. 7);\n"
           "                            contraction.pvd (the steps as a time series for ParaView); the "
           "curve\n"
           "                            skeleton after the surgery and before the selection\n"
           "  --rig RIG.glb|RIG.fbx     the skinned mesh and its bones (one per skeleton edge) as glTF 2.0 "
           "or FBX\n"
           "  --weights                 compute the skinning weights without writing a rig\n"
           "with --rig:\n" +
           rigWriterHelp() +
           "  --quiet                   no progress line\n"
           "  --timings                 print stage times as JSON on stdout\n";
  }();
  return text;
}

int runSkeleton(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, skeletonOptions());
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

  auto rigWriter = vtkSmartPointer<vtkMedialRigWriter>::New();
  applyRigWriterOptions(parsed, rigWriter);
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
  // --no-centring: the British spelling, deprecated, accepted until the next release.
  if (parsed.has("--no-centering") || parsed.has("--no-centring")) filter->CenterNodesOff();
  if (parsed.has("--rig") || parsed.has("--weights")) filter->ComputeWeightsOn();
  CommandRun command(parsed);
  const std::string stepsDir = command.stagesFolder(filter.Get(), "--contraction-steps");
  const vtkSmartPointer<vtkPolyData> mesh = command.readSurface(input);
  command.run(filter, mesh, input, "skeleton", "skeleton of " + input);
  for (const std::string& stage : vtkMedialContractionSkeleton::GetStageNames())
    command.timings().detail("skeleton", stage, filter->GetStageSeconds(stage));

  if (filter->GetRestoredCycles() > 0)
    std::fprintf(
        stderr, "medial skeleton: note: %d cycle%s that surgery lost put back (the mesh has genus %d)\n",
        filter->GetRestoredCycles(), filter->GetRestoredCycles() == 1 ? "" : "s", filter->GetGenus());
  if (!filter->GetSelectionNote().empty())
    std::fprintf(stderr, "medial skeleton: note: %s\n", filter->GetSelectionNote().c_str());
  command.timings().start("write");
  writePolyData(filter->GetOutput(0), output);
  if (!segmentation.empty()) writePolyData(filter->GetOutput(1), segmentation);
  if (!contracted.empty()) writePolyData(contractedMesh(filter->GetOutput(1)), contracted);
  if (!stepsDir.empty()) writeStages(filter, stepsDir);
  if (!rig.empty()) writeRig(rigWriter, filter->GetOutput(1), filter->GetOutput(0), rig);
  return command.finish();
}

}  // namespace medial::cli
