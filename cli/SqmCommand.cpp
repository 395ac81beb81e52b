// `medial sqm SKELETON.vtp|.swc -o MESH.vtp|.obj|.ply [--smoothing NAME] [--pairing NAME] [--capsule]
//              [--triangle-fans] [--ring-vertices N] [--subdivide K] [--sharp-scale S] [--no-fold-repair]
//              [--no-merge] [--union] [--stages DIR]`
#include "CommandRun.h"
#include "Commands.h"
#include "HelpText.h"
#include "CommandLine.h"
#include "FilterOptions.h"
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
  // Past the count's limit the figures are lower bounds.
  const char* atLeast = filter->GetOverlapCountComplete() ? "" : "at least ";
  if (filter->GetUnion())
    std::fprintf(
        stderr,
        "medial sqm: note: tubes overlapped at %s%d pair%s of nodes (%s%d pairs of faces cutting each "
        "other); the union cut %d polygons along the intersection curves and removed %d inside it\n",
        atLeast, nodes, nodes == 1 ? "" : "s", atLeast, faces, filter->GetUnionCutPolygons(),
        filter->GetUnionRemovedPolygons());
  else
    std::fprintf(stderr,
                 "medial sqm: note: tubes overlap at %s%d pair%s of nodes (%s%d pairs of faces cut each "
                 "other): the mesh bounds no volume; --union makes it one closed surface without "
                 "self-intersections\n",
                 atLeast, nodes, nodes == 1 ? "" : "s", atLeast, faces);
}

}  // namespace

// The options of `medial sqm`: those that take a value, and the flags (medial sqm --list-options).
const OptionSpec& sqmOptions() {
  static const OptionSpec spec = {
      {"-o", "--output", "--smoothing", "--pairing", "--ring-vertices", "--capsule-steps", "--subdivide",
       "--sharp-scale", "--stages"},
      {"--capsule", "--triangle-fans", "--no-fold-repair", "--no-merge", "--union", "--quiet", "--timings"}};
  return spec;
}

// The --help text of `medial sqm`, built once; its defaults and names are a fresh filter's.
const std::string& sqmUsage() {
  static const std::string text = [] {
    const auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
    return std::string() +
           "usage: medial sqm SKELETON.vtp|SKELETON.swc -o MESH.vtp|.obj|.ply [--smoothing NAME] [--pairing "
           "NAME]\n"
           "                  [--capsule] [--capsule-steps N] [--triangle-fans] [--ring-vertices N]\n"
           "                  [--subdivide K] [--sharp-scale S] [--no-fold-repair] [--no-merge] [--union]\n"
           "                  [--stages DIR] [--quiet] [--timings]\n\n"
           "Turns a skeleton with a Radius per node into a closed manifold mesh of quads (a triangle only "
           "where\n"
           "a leaf's or a cycle's ring is odd), by SQM with the extensions of the CESCG 2014 paper "
           "(re-rooting,\n"
           "linear skeletons, ellipsoid nodes from EllipsoidAxes, capsules, cycles). Every component is "
           "meshed.\n"
           "  -o, --output MESH         the mesh (.vtp .vtk .obj .ply .stl), with point data SkeletonNode\n" +
           namesHelp("--smoothing NAME", "LIE smoothing:", vtkMedialSQM::GetSmoothingNames(),
                     sqm->GetSmoothing()) +
           namesHelp("--pairing NAME", "ring pairing at branch nodes:", vtkMedialSQM::GetPairingNames(),
                     sqm->GetPairing()) +
           "  --capsule                 close leaves with capsules instead of cones to their node\n"
           "  --capsule-steps N         with --capsule: rings added beyond each leaf to close it (default " +
           number(sqm->GetCapsuleSteps()) +
           ")\n"
           "  --triangle-fans           keep the papers' triangle fans at leaves and bands at cycles (by\n"
           "                            default their triangles are joined in pairs into quads)\n"
           "  --ring-vertices N         vertices around a skeleton without branch nodes (default " +
           number(sqm->GetLinearRingVertices()) +
           ")\n"
           "  --subdivide K             K levels of tessellation, projected on the spheres swept along the\n"
           "                            skeleton's edges (0-6)\n"
           "  --sharp-scale S           with --subdivide: scale the cone radius near a sharp vertex (two "
           "faces\n"
           "                            at an acute angle) by a Bezier curve from S (0.05-1) there to 1 one\n"
           "                            radius away (the paper's radius scaling; off without this option)\n"
           "  --no-fold-repair          with --subdivide: keep every refined vertex on its cone even where\n"
           "                            faces then cut each other (by default their vertices move back "
           "towards\n"
           "                            the base mesh until none do)\n"
           "  --no-merge                do not merge a node lying inside a neighbouring branch node's\n"
           "                            sphere into it: such a skeleton is then an error naming the node\n"
           "  --union                   where tubes of parts that are not neighbours overlap, output the\n"
           "                            boundary of their union: one closed surface without self-\n"
           "                            intersections, triangles along the intersection curves (without\n"
           "                            it, overlaps are counted and noted on stderr)\n"
           "  --stages DIR              the papers' intermediate meshes in DIR: polyhedra.vtp (every branch\n"
           "                            node polyhedron as generated), refined-polyhedra.vtp (after the LIE\n"
           "                            refinement; both in the straightened bind pose), base.vtp (joined,\n"
           "                            before subdivision); point data SkeletonNode\n"
           "  --quiet                   no progress line\n"
           "  --timings                 print stage times (straightening, generation, refinement, joining,\n"
           "                            skinning, subdivision, repairs, union) and the paper's Table 1\n"
           "                            counts (branch, connection, leaf and merged nodes, quads, "
           "triangles,\n"
           "                            irregular vertices; overlapping face and node pairs) as JSON on "
           "stdout\n";
  }();
  return text;
}

int runSqm(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, sqmOptions());
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
  MEDIAL_OPTION(parsed, "--capsule-steps", filter, CapsuleSteps);
  if (parsed.has("--capsule")) filter->CapsulesOn();
  if (parsed.has("--triangle-fans")) filter->PairTrianglesOff();
  if (parsed.has("--no-fold-repair")) filter->FoldRepairOff();
  if (parsed.has("--no-merge")) filter->MergeNodesOff();
  filter->CountOverlapsOn();
  if (parsed.has("--union")) filter->UnionOn();
  CommandRun command(parsed);
  const std::string stages = command.stagesFolder(filter.Get());
  const vtkSmartPointer<vtkPolyData> skeleton = vtkPolyData::SafeDownCast(command.read(input));
  if (!skeleton || skeleton->GetNumberOfPoints() == 0) throw Failure(input + ": not a skeleton (no nodes)");
  command.run(filter, skeleton, input, "sqm", "tube mesh of " + input);
  for (const std::string& stage : vtkMedialSQM::GetStageNames())
    command.timings().detail("sqm", stage, filter->GetStageSeconds(stage));
  countTable1(filter, command.timings());

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

  command.timings().start("write");
  writePolyData(filter->GetOutput(), output);
  for (const std::string& stage : vtkMedialSQM::GetStageMeshNames())  // --stages: the papers' figures
    if (!stages.empty()) writePolyData(filter->GetStageMesh(stage), stages + "/" + stage + ".vtp");
  return command.finish();
}

}  // namespace medial::cli
