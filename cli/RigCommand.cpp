// `medial rig SKELETON MESH -o RIG.glb|RIG.fbx [--weights MESH_OUT] [--root N] [--heat C]
//              [--up-axis AXIS] [--scale F] [--max-influences N] [--quiet] [--timings]`: binds any mesh to
//              any skeleton with the
// heat-diffusion weights (vtkMedialSkinBinding) and writes the rig (vtkMedialRigWriter).
#include "CommandRun.h"
#include "Commands.h"
#include "HelpText.h"
#include "CommandLine.h"
#include "FilterOptions.h"
#include "RigOptions.h"
#include "WriteOutput.h"

#include "vtkMedialRigWriter.h"
#include "vtkMedialSkinBinding.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdio>

namespace medial::cli {

// The options of `medial rig`: those that take a value, and the flags (medial rig --list-options).
const OptionSpec& rigOptions() {
  static const OptionSpec spec = [] {
    OptionSpec options = {{"-o", "--output", "--weights", "--root", "--heat"}, {"--quiet", "--timings"}};
    for (const std::string& name : rigWriterOptionNames()) options.withValue.insert(name);
    return options;
  }();
  return spec;
}

// The --help text of `medial rig`, built once; its defaults and names are a fresh filter's.
const std::string& rigUsage() {
  static const std::string text = [] {
    const auto binding = vtkSmartPointer<vtkMedialSkinBinding>::New();
    return std::string() +
           "usage: medial rig SKELETON MESH (-o RIG.glb|RIG.fbx | --weights MESH_OUT) [--root N] [--heat C]\n"
           "                  [--up-axis AXIS] [--scale F] [--max-influences N] [--quiet] [--timings]\n\n"
           "Binds MESH (.off .obj .ply .stl .vtp .vtk) to SKELETON (.vtp .swc ...) with heat-diffusion "
           "skinning\n"
           "weights (Baran and Popovic 2007, as the contraction paper's III.E) and writes the rig (III.F): "
           "one\n"
           "bone per skeleton edge, at most four per vertex. For a sketch (medial sketch --mesh), an SQM "
           "mesh\n"
           "and the skeleton it was made from, or a mesh and a skeleton drawn for it.\n"
           "  -o, --output RIG          the rig as glTF 2.0 (.glb) or FBX (.fbx)\n"
           "  --weights MESH_OUT        also the mesh with point data SkinWeights (a component per bone) "
           "and\n"
           "                            Bone (the strongest); without -o, the weights alone (no rig)\n"
           "  --root N                  the root node (default: the skeleton's Root, else its body centre: "
           "the\n"
           "                            branch node nearest the mesh's middle among the central ones, the "
           "hips)\n"
           "  --heat C                  c of the heat weights' H = c / d^2, as Blender's bone heat "
           "(default " +
           number(binding->GetHeatConstant()) + ")\n" + rigWriterHelp() +
           "  --quiet                   no progress line\n"
           "  --timings                 print stage times as JSON on stdout\n";
  }();
  return text;
}

int runRig(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, rigOptions());
  if (parsed.positional.size() != 2) throw UsageError("rig needs a SKELETON file and a MESH file");
  const std::string skeletonFile = parsed.positional[0], meshFile = parsed.positional[1];
  const std::string output = parsed.value("-o", parsed.value("--output"));
  const std::string weights = parsed.value("--weights");
  if (output.empty() && weights.empty())
    throw UsageError("rig needs -o RIG.glb|RIG.fbx or --weights MESH_OUT");
  if (!output.empty() && !vtkMedialRigWriter::CanWriteFile(output.c_str()))
    throw UsageError(std::string("-o must end in one of ") + vtkMedialRigWriter::GetExtensions() + ": " +
                     output);
  if (parsed.has("--weights")) requireWritableExtension(weights, "--weights");

  auto binding = vtkSmartPointer<vtkMedialSkinBinding>::New();
  auto writer = vtkSmartPointer<vtkMedialRigWriter>::New();
  MEDIAL_OPTION(parsed, "--root", binding, Root);
  MEDIAL_OPTION(parsed, "--heat", binding, HeatConstant);
  applyRigWriterOptions(parsed, writer);

  CommandRun command(parsed);
  const vtkSmartPointer<vtkPolyData> skeleton = vtkPolyData::SafeDownCast(command.read(skeletonFile));
  if (!skeleton || skeleton->GetNumberOfLines() == 0)
    throw Failure(skeletonFile + ": not a skeleton (no edges)");
  const vtkSmartPointer<vtkPolyData> mesh = command.readSurface(meshFile);
  binding->SetSkeletonData(skeleton);
  command.run(binding, mesh, meshFile + " with " + skeletonFile, "weights",
              "skinning weights of " + meshFile);
  if (binding->GetNodesOutside() > 0)
    std::fprintf(stderr,
                 "medial rig: note: %d skeleton node%s outside the mesh (weighted by diffusion alone)\n",
                 binding->GetNodesOutside(), binding->GetNodesOutside() == 1 ? " lies" : "s lie");

  command.timings().start("write");
  if (!weights.empty()) writePolyData(binding->GetOutput(0), weights);
  if (!output.empty()) writeRig(writer, binding->GetOutput(0), binding->GetOutput(1), output);
  return command.finish();
}

}  // namespace medial::cli
