// `medial sqm SKELETON.vtp|.swc -o MESH.vtp|.obj|.ply [--smoothing NAME] [--pairing NAME] [--capsule]
//              [--triangle-fans] [--ring-vertices N] [--subdivide K] [--sharp-scale S] [--no-fold-repair]
//              [--no-merge] [--union] [--stages DIR]`
#include "Commands.h"
#include "CommandLine.h"
#include "FilterOptions.h"
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

namespace {

// The paper's Table 1 counts beside the stage times: node kinds, merged nodes, faces by kind, irregular
// vertices.
void countTable1(vtkMedialSQM* filter, Timings& timings) {
  timings.count("sqm", "branch_nodes", filter->GetBranchNodes());
  timings.count("sqm", "connection_nodes", filter->GetConnectionNodes());
  timings.count("sqm", "leaf_nodes", filter->GetLeafNodes());
  timings.count("sqm", "merged_nodes", filter->GetMergedNodes());
  timings.count("sqm", "quads", filter->GetQuads());
  timings.count("sqm", "triangles", filter->GetTriangles());
  timings.count("sqm", "irregular_vertices", filter->GetIrregularVertices());
  timings.count("sqm", "overlapping_face_pairs", filter->GetOverlappingFacePairs());
  timings.count("sqm", "overlapping_node_pairs", filter->GetOverlappingNodePairs());
}

// Overlapping tubes make a mesh that bounds no volume: say so, and what --union did or would do.
void noteOverlaps(vtkMedialSQM* filter) {
  const int nodes = filter->GetOverlappingNodePairs(), faces = filter->GetOverlappingFacePairs();
  if (faces == 0) return;
  if (filter->GetUnion())
    std::fprintf(
        stderr,
        "medial sqm: note: tubes overlapped at %d pair%s of nodes (%d pairs of faces cutting each other); "
        "the union cut %d polygons along the intersection curves and removed %d inside it\n",
        nodes, nodes == 1 ? "" : "s", faces, filter->GetUnionCutPolygons(),
        filter->GetUnionRemovedPolygons());
  else
    std::fprintf(
        stderr,
        "medial sqm: note: tubes overlap at %d pair%s of nodes (%d pairs of faces cut each other): the "
        "mesh bounds no volume; --union makes it one closed surface without self-intersections\n",
        nodes, nodes == 1 ? "" : "s", faces);
}

}  // namespace

int runSqm(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, {{"-o", "--output", "--smoothing", "--pairing", "--ring-vertices",
                                              "--subdivide", "--sharp-scale", "--stages"},
                                             {"--capsule", "--triangle-fans", "--no-fold-repair",
                                              "--no-merge", "--union", "--quiet", "--timings"}});
  if (parsed.positional.size() != 1) throw UsageError("sqm needs exactly one SKELETON file");
  const std::string input = parsed.positional[0];
  const std::string output = parsed.value("-o", parsed.value("--output"));
  if (output.empty()) throw UsageError("sqm needs -o MESH.vtp|.obj|.ply");
  requireWritableExtension(output, "-o");

  auto filter = vtkSmartPointer<vtkMedialSQM>::New();
  setNameFromOption(parsed, "--smoothing", filter,
                    [&](const std::string& name) { filter->SetSmoothing(name); });
  setNameFromOption(parsed, "--pairing", filter, [&](const std::string& name) { filter->SetPairing(name); });
  MEDIAL_OPTION(parsed, "--ring-vertices", filter, LinearRingVertices);
  MEDIAL_OPTION(parsed, "--subdivide", filter, SubdivisionLevels);
  MEDIAL_OPTION(parsed, "--sharp-scale", filter, SharpMinimumScale);
  if (parsed.has("--sharp-scale")) filter->SharpScalingOn();
  if (parsed.has("--capsule")) filter->CapsulesOn();
  if (parsed.has("--triangle-fans")) filter->PairTrianglesOff();
  if (parsed.has("--no-fold-repair")) filter->FoldRepairOff();
  if (parsed.has("--no-merge")) filter->MergeNodesOff();
  filter->CountOverlapsOn();
  if (parsed.has("--union")) filter->UnionOn();
  const std::string stages = parsed.value("--stages");
  if (parsed.has("--stages")) {
    makeOutputDirectory(stages, "--stages");
    filter->RecordStagesOn();
  }

  Timings timings;
  ProgressLine progress(parsed.has("--quiet"));
  timings.start("read");
  const vtkSmartPointer<vtkDataObject> data = readInput(input, progress);
  vtkPolyData* skeleton = vtkPolyData::SafeDownCast(data);
  if (!skeleton || skeleton->GetNumberOfPoints() == 0) throw Failure(input + ": not a skeleton (no nodes)");

  timings.start("sqm");
  runFilter(filter, skeleton, input, "tube mesh of " + input, progress);
  for (const std::string& stage : vtkMedialSQM::GetStageNames())
    timings.detail("sqm", stage, filter->GetStageSeconds(stage));
  countTable1(filter, timings);

  if (filter->GetMergedNodes() > 0)
    std::fprintf(stderr,
                 "medial sqm: note: %d node%s inside a neighbouring branch node's sphere merged into it\n",
                 filter->GetMergedNodes(), filter->GetMergedNodes() == 1 ? "" : "s");
  if (filter->GetFoldRepairedVertices() > 0)
    std::fprintf(
        stderr,
        "medial sqm: note: %d refined vert%s moved off the swept spheres, where faces cut each other\n",
        filter->GetFoldRepairedVertices(), filter->GetFoldRepairedVertices() == 1 ? "ex" : "ices");

  noteOverlaps(filter);

  timings.start("write");
  writePolyData(filter->GetOutput(), output);
  for (const std::string& stage : vtkMedialSQM::GetStageMeshNames())  // --stages: the papers' figures
    if (!stages.empty()) writePolyData(filter->GetStageMesh(stage), stages + "/" + stage + ".vtp");
  timings.stop();
  if (parsed.has("--timings")) std::printf("%s\n", timings.json().c_str());
  return kSuccess;
}

}  // namespace medial::cli
