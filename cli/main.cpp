// `medial`: Medial's batch command (docs/ARCHITECTURE.md §6). Dispatches to one subcommand per algorithm.
#include "Commands.h"
#include "CommandLine.h"

#include "vtkMedialContractionSkeleton.h"
#include "vtkMedialRigWriter.h"
#include "vtkMedialSQM.h"
#include "vtkMedialSkinBinding.h"
#include "vtkMedialSketchSkeleton.h"
#include "vtkMedialTskCenterline.h"

#include <vtkSmartPointer.h>

#include <vtkLogger.h>
#include <vtkOutputWindow.h>
#include <vtkVersion.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#ifndef MEDIAL_VERSION
#define MEDIAL_VERSION "unknown"
#endif

namespace medial::cli {

namespace {

// A help line for an option that takes one of a filter's names: "  OPTION   [lead ]a (default), b, c",
// wrapped under the description column. The names and the default are the filter's.
std::string namesHelp(const std::string& option, const std::string& lead, const std::string& names,
                      const std::string& defaultName) {
  const std::string column(28, ' ');
  std::string text = "  " + option + std::string(26 - option.size(), ' ') + lead, line;
  size_t start = 0;
  while (start <= names.size()) {
    size_t comma = names.find(',', start);
    if (comma == std::string::npos) comma = names.size();
    std::string name = names.substr(start, comma - start);
    name.erase(0, name.find_first_not_of(' '));
    std::string item = name + (name == defaultName ? " (default)" : "") + (comma < names.size() ? "," : "");
    if (text.size() + 1 + item.size() > 100) {
      line += text + "\n";
      text = column;
    } else if (text.back() != ' ') {
      text += ' ';
    }
    text += item;
    start = comma + 1;
  }
  return line + text + "\n";
}

// A default in the help, as short as it prints.
std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

// The help texts take every default and every list of names from a fresh filter, so they cannot drift.
const std::vector<Command>& commands() {
  const auto contraction = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  const auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
  const auto tsk = vtkSmartPointer<vtkMedialTskCenterline>::New();
  const auto sketch = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
  const auto binding = vtkSmartPointer<vtkMedialSkinBinding>::New();
  const auto writer = vtkSmartPointer<vtkMedialRigWriter>::New();
  static const std::vector<Command> all = {
      {"skeleton", "curve skeleton of a surface mesh by mesh contraction",
       "usage: medial skeleton MESH -o SKELETON.vtp [--segmentation MESH_OUT.vtp] [--nodes N] [--rig "
       "RIG.glb|RIG.fbx]\n"
       "                       [--weights] [--solver NAME] [--iterations N] [--contraction-vertices N]\n"
       "                       [--reference-vertices N] [--wl0 F] [--sl S] [--wh0 W] [--max-wl W]\n"
       "                       [--max-wh W] [--shape-weight A] [--sampling-weight B] [--collapse-length D]\n"
       "                       [--heat C] [--contracted MESH] [--no-refine] [--no-cycle-repair]\n"
       "                       [--no-centring] [--contraction-steps DIR] [--quiet] [--timings]\n\n"
       "Contracts MESH (.off .obj .ply .stl .vtp .vtk; polygons are triangulated) by constrained Laplacian\n"
       "smoothing and collapses it into a curve skeleton with a Radius per node (the contraction paper, "
       "III.A-D);\n"
       "with --rig, also computes heat-diffusion skinning weights (III.E) and writes a rig (III.F).\n"
       "  -o, --output SKELETON     the skeleton: .vtp (nodes, edges, Radius, Root) or .vtk .obj .ply\n"
       "  --segmentation MESH_OUT   the triangulated mesh with point data SkeletonNode (vertex -> node),\n"
       "                            and SkinWeights (one component per bone) with --rig or --weights\n"
       "  --nodes N                 nodes kept by the selection stage (default " +
           number(contraction->GetTargetNodes()) + "; 0 keeps all)\n" +
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
           "  --no-centring             keep the refined nodes where they are (by default a node of one or\n"
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
           "  --quiet                   no progress line\n"
           "  --timings                 print stage times as JSON on stdout\n",
       runSkeleton},
      {"centerline", "TSK centerline of a tubular structure in a CT or label volume",
       "usage: medial centerline VOLUME -o CENTERLINE.vtp [--label L | --threshold LO:HI] [--seed X,Y,Z]\n"
       "                         [--fill-holes] [--keep-border-parts] [--max-gap MM] [--min-part-volume "
       "MM3]\n"
       "                         [--branches] [--antecedent-width W] [--centering N]\n"
       "                         [--profile P.csv] [--terrain T.png] [--section-spacing K] [--section-rays "
       "N]\n"
       "                         [--stages DIR] [--quiet] [--timings]\n\n"
       "Follows a tube (colon, vessel) in VOLUME (.nii .nii.gz .mha .mhd .nrrd .inr .vti or a DICOM folder) "
       "by\n"
       "the TSK method (WSCG 2008): layers and cylindrical clusters from P0, then three Takagi-Sugeno-Kang\n"
       "models. The structure: voxels equal to L, or within LO..HI (parts touching the volume's border are\n"
       "dropped: the air outside the body), else the non-zero voxels. A structure in several parts (a colon\n"
       "split by collapsed or fluid-filled segments) is followed part by part and chained from the lowest\n"
       "end across each gap by the least-cost path through the volume (point data Bridged = 1 there).\n"
       "  -o, --output CENTERLINE   one polyline in mm with Radius and ArcLength (.vtp .vtk ...)\n"
       "  --label L                 the structure is the voxels of label L\n"
       "  --threshold LO:HI         the structure is the voxels in LO..HI (e.g. -1024:-600 for colon air)\n"
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
           "  --timings                 print stage times as JSON on stdout\n",
       runCenterline},
      {"sqm", "quad-dominant tube mesh of a skeleton with radii (SQM)",
       "usage: medial sqm SKELETON.vtp|SKELETON.swc -o MESH.vtp|.obj|.ply [--smoothing NAME] [--pairing "
       "NAME]\n"
       "                  [--capsule] [--triangle-fans] [--ring-vertices N] [--subdivide K]\n"
       "                  [--sharp-scale S] [--no-fold-repair] [--no-merge] [--union] [--stages DIR]\n"
       "                  [--quiet] [--timings]\n\n"
       "Turns a skeleton with a Radius per node into a closed manifold mesh of quads (a triangle only where\n"
       "a leaf's or a cycle's ring is odd), by SQM with the extensions of the CESCG 2014 paper (re-rooting,\n"
       "linear skeletons, ellipsoid nodes from EllipsoidAxes, capsules, cycles). Every component is meshed.\n"
       "  -o, --output MESH         the mesh (.vtp .vtk .obj .ply .stl), with point data SkeletonNode\n" +
           namesHelp("--smoothing NAME", "LIE smoothing:", vtkMedialSQM::GetSmoothingNames(),
                     sqm->GetSmoothing()) +
           namesHelp("--pairing NAME", "ring pairing at branch nodes:", vtkMedialSQM::GetPairingNames(),
                     sqm->GetPairing()) +
           "  --capsule                 close leaves with capsules instead of cones to their node\n"
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
           "stdout\n",
       runSqm},
      {"sketch", "animatable skeleton and inflated mesh of closed 2-D strokes",
       "usage: medial sketch POLYGON.txt -o SKELETON.vtp [--mesh MESH.vtp] [--simplify ES] [--merge EM]\n"
       "                     [--prune ET] [--collapse EC] [--part K:ES,EM,ET,EC]... [--unit U]\n"
       "                     [--resample STEP] [--thickness C] [--separate-parts] [--stages DIR]\n"
       "                     [--quiet] [--timings]\n\n"
       "Skeletonizes sketched outlines (Ma et al. 2021): each closed stroke of POLYGON.txt ('x y' lines, "
       "parts\n"
       "separated by a blank line, each optionally followed by four rows of its 4x4 placement matrix) gets "
       "a\n"
       "straight skeleton simplified by BoundedDP; parts are joined in drawing order where they intersect "
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
           "  --timings                 print stage times as JSON on stdout\n",
       runSketch},
      {"rig", "skinning weights binding any mesh to any skeleton, written as a rig",
       "usage: medial rig SKELETON MESH -o RIG.glb|RIG.fbx [--weights MESH_OUT] [--root N] [--heat C]\n"
       "                  [--max-influences N] [--quiet] [--timings]\n\n"
       "Binds MESH (.off .obj .ply .stl .vtp .vtk) to SKELETON (.vtp .swc ...) with heat-diffusion skinning\n"
       "weights (Baran and Popovic 2007, as the contraction paper's III.E) and writes the rig (III.F): one\n"
       "bone per skeleton edge, at most four per vertex. For a sketch (medial sketch --mesh), an SQM mesh\n"
       "and the skeleton it was made from, or a mesh and a skeleton drawn for it.\n"
       "  -o, --output RIG          the rig as glTF 2.0 (.glb) or FBX (.fbx)\n"
       "  --weights MESH_OUT        also the mesh with point data SkinWeights (a component per bone) and\n"
       "                            Bone (the strongest)\n"
       "  --root N                  the root node (default: the skeleton's Root, else its central node,\n"
       "                            the middle of its longest path)\n"
       "  --heat C                  c of the heat weights' H = c / d^2 (default " +
           number(binding->GetHeatConstant()) +
           ")\n"
           "  --max-influences N        most bones per vertex (default " +
           number(writer->GetMaxInfluences()) +
           ")\n"
           "  --quiet                   no progress line\n"
           "  --timings                 print stage times as JSON on stdout\n",
       runRig},
      {"render", "render meshes, skeletons and volumes offscreen to a PNG",
       "usage: medial render INPUT... -o IMAGE.png [--size WxH] [--camera AZIMUTH,ELEVATION]\n"
       "                     [--skeleton-scale S] [--mesh-opacity A]\n"
       "                     [--ghost INPUT]... [--cutaway] [--ghost-opacity A] [--ghost-importance I,...]\n"
       "                     [--ghost-conflict gradual|depth] [--ghost-map-scale S] [--ghost-layers]\n"
       "                     [--importance-map MAP.png]\n"
       "                     [--volume-rendering STYLE] [--quiet] [--timings]\n"
       "\n"
       "Renders every INPUT (meshes: .vtp .vtk .vtu .obj .ply .stl .off; skeletons: .vtp .swc, drawn as\n"
       "tubes from their Radius; volumes: .nii .nii.gz .mha .mhd .nrrd .inr .inr.gz .vti .inv3 or a DICOM\n"
       "directory, drawn as three orthogonal slices) into one PNG.\n"
       "  -o, --output IMAGE.png   the image to write (written atomically)\n"
       "  --size WxH               image size in pixels (default 1024x768)\n"
       "  --camera AZ,EL           degrees around the front view (default 30,20)\n"
       "  --skeleton-scale S       scale of skeleton tube radii (default 1)\n"
       "  --mesh-opacity A         opacity of meshes in [0, 1] (default 1); below 1 shows skeletons inside\n"
       "  --ghost INPUT            an object of interest, kept visible through what hides it (ghost view,\n"
       "                           Hoffmann et al. 2008); repeat for several; an INPUT already listed is\n"
       "                           marked, another file is added\n"
       "  --cutaway                remove the occluders over the objects of interest instead of ghosting\n"
       "  --ghost-opacity A        opacity of a ghosted occluder, 0..1 (default 0.25)\n"
       "  --ghost-importance I,... importance of each --ghost object in order, (0, 1] (default all 1)\n"
       "  --ghost-conflict C       gradual: the more important object shows through the less (default);\n"
       "                           depth: the nearer object of interest wins\n"
       "  --ghost-map-scale S      importance-map resolution as a fraction of the image's (default 0.5)\n"
       "  --ghost-layers           every occluding layer in front of an object of interest shows, not\n"
       "                           only the one drawn last (slower: about 0.2 of a frame in software GL)\n"
       "  --importance-map MAP.png the ghost view's importance map as a grey image at the map's resolution\n"
       "                           (importance x coverage: where the objects of interest project)\n"
       "  --volume-rendering STYLE volumes as a ray-cast rendering instead of three slices: ct-bone,\n"
       "                           ct-soft-tissue or full-range (transfer-function presets); ghosted like\n"
       "                           any occluder in front of --ghost objects\n"
       "  --quiet                  no progress line\n"
       "  --timings                print stage times as JSON on stdout\n"
       "Without an X display, a private Xvfb is started (package xvfb).\n",
       runRender},
  };
  return all;
}

namespace {

void printHelp(FILE* out) {
  std::fprintf(out,
               "medial %s: skeletons, centerlines, tube meshes and ghost views\n\n"
               "usage: medial COMMAND [ARGS...]\n"
               "       medial COMMAND --help\n"
               "       medial --help | --version\n\ncommands:\n",
               MEDIAL_VERSION);
  for (const Command& c : commands()) std::fprintf(out, "  %-11s %s\n", c.name, c.summary);
  std::fprintf(out, "  %-11s %s\n", "batch",
               "any of these commands over many files, locally or on a Dask cluster");
  std::fprintf(out, "\nExit status: 0 success, 1 failure (one line on stderr), 2 usage error.\n");
}

}  // namespace
}  // namespace medial::cli

int main(int argc, char** argv) {
  using namespace medial::cli;
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    printHelp(stderr);
    return kUsageError;
  }
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    printHelp(stdout);
    return kSuccess;
  }
  if (args[0] == "--version") {
    std::printf("medial %s (VTK %s)\n", MEDIAL_VERSION, vtkVersion::GetVTKVersion());
    return kSuccess;
  }
  if (args[0] == "batch") return runBatch(argv[0], std::vector<std::string>(args.begin() + 1, args.end()));
  const Command* command = nullptr;
  for (const Command& c : commands())
    if (args[0] == c.name) command = &c;
  if (!command) {
    std::fprintf(stderr, "medial: unknown command '%s' (see medial --help)\n", args[0].c_str());
    return kUsageError;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  for (const std::string& a : rest)
    if (a == "--help" || a == "-h") {
      std::fputs(command->usage.c_str(), stdout);
      return kSuccess;
    }

  // Errors are reported once, by the command, in one line: VTK's own multi-line reports do not reach
  // the terminal. (GlobalWarningDisplayOff would also silence the ErrorEvent observers the command reads.)
  // MEDIAL_VTK_LOG=1 keeps them, for diagnosing VTK itself.
  const char* vtkLog = std::getenv("MEDIAL_VTK_LOG");
  if (!vtkLog || std::strcmp(vtkLog, "1") != 0) {
    vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);  // the executive's "returned failure" reports
  }
  try {
    return command->run(rest);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "medial %s: %s (see 'medial %s --help')\n", command->name, e.what(), command->name);
    return kUsageError;
  } catch (const Failure& e) {
    std::fprintf(stderr, "medial %s: %s\n", command->name, e.what());
    return kFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "medial %s: %s\n", command->name, e.what());
    return kFailure;
  }
}
