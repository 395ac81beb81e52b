// `medial rig SKELETON MESH -o RIG.glb|RIG.fbx [--weights MESH_OUT] [--root N] [--heat C]
//              [--max-influences N] [--quiet] [--timings]`: binds any mesh to any skeleton with the
// heat-diffusion weights (vtkMedialSkinBinding) and writes the rig (vtkMedialRigWriter).
#include "Commands.h"
#include "CommandLine.h"
#include "FilterOptions.h"
#include "Progress.h"
#include "ReadInput.h"
#include "RunFilter.h"
#include "Timings.h"
#include "WriteOutput.h"

#include "vtkMedialRigWriter.h"
#include "vtkMedialSkinBinding.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdio>

namespace medial::cli {

int runRig(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(
      args,
      {{"-o", "--output", "--weights", "--root", "--heat", "--max-influences"}, {"--quiet", "--timings"}});
  if (parsed.positional.size() != 2) throw UsageError("rig needs a SKELETON file and a MESH file");
  const std::string skeletonFile = parsed.positional[0], meshFile = parsed.positional[1];
  const std::string output = parsed.value("-o", parsed.value("--output"));
  if (output.empty()) throw UsageError("rig needs -o RIG.glb|RIG.fbx");
  if (!vtkMedialRigWriter::CanWriteFile(output.c_str()))
    throw UsageError(std::string("-o must end in one of ") + vtkMedialRigWriter::GetExtensions() + ": " +
                     output);
  const std::string weights = parsed.value("--weights");
  if (parsed.has("--weights")) requireWritableExtension(weights, "--weights");

  auto binding = vtkSmartPointer<vtkMedialSkinBinding>::New();
  auto writer = vtkSmartPointer<vtkMedialRigWriter>::New();
  MEDIAL_OPTION(parsed, "--root", binding, Root);
  MEDIAL_OPTION(parsed, "--heat", binding, HeatConstant);
  MEDIAL_OPTION(parsed, "--max-influences", writer, MaxInfluences);

  Timings timings;
  ProgressLine progress(parsed.has("--quiet"));
  timings.start("read");
  const vtkSmartPointer<vtkDataObject> skeletonData = readInput(skeletonFile, progress);
  vtkPolyData* skeleton = vtkPolyData::SafeDownCast(skeletonData);
  if (!skeleton || skeleton->GetNumberOfLines() == 0)
    throw Failure(skeletonFile + ": not a skeleton (no edges)");
  const vtkSmartPointer<vtkDataObject> meshData = readInput(meshFile, progress);
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(meshData);
  if (!mesh || mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() == 0)
    throw Failure(meshFile + ": not a surface mesh (no polygons)");

  timings.start("weights");
  binding->SetSkeletonData(skeleton);
  runFilter(binding, mesh, meshFile + " with " + skeletonFile, "skinning weights of " + meshFile, progress);
  if (binding->GetNodesOutside() > 0)
    std::fprintf(stderr,
                 "medial rig: note: %d skeleton node%s outside the mesh (weighted by diffusion alone)\n",
                 binding->GetNodesOutside(), binding->GetNodesOutside() == 1 ? " lies" : "s lie");

  timings.start("write");
  if (!weights.empty()) writePolyData(binding->GetOutput(0), weights);
  writeRig(writer, binding->GetOutput(0), binding->GetOutput(1), output);
  timings.stop();
  if (parsed.has("--timings")) std::printf("%s\n", timings.json().c_str());
  return kSuccess;
}

}  // namespace medial::cli
