// The `medial` command (docs/ARCHITECTURE.md §6): exit codes, help, atomic outputs, render, private Xvfb.
#include "ImageComparison.h"
#include "RunCommand.h"
#include "TestPaths.h"
#include "common/Stopwatch.h"
#include "centerline/StructureRuns.h"
#include "common/UnionFind.h"

#include <vtkCell.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>

namespace {

using namespace medial::test;

std::string medialCommand(const std::string& args) { return medialExe() + " " + args; }

int lineCount(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

}  // namespace

TEST(Cli, HelpAndVersionExitZero) {
  auto help = runCommand(medialCommand("--help"));
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("render"), std::string::npos);
  EXPECT_NE(help.out.find("skeleton"), std::string::npos);
  auto version = runCommand(medialCommand("--version"));
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_NE(version.out.find("medial 0."), std::string::npos) << version.out;
  auto commandHelp = runCommand(medialCommand("render --help"));
  EXPECT_EQ(commandHelp.exitCode, 0);
  EXPECT_NE(commandHelp.out.find("usage: medial render"), std::string::npos);
}

TEST(Cli, UsageErrorsExitTwo) {
  for (const char* args : {"",
                           "frobnicate",
                           "render",
                           "render in.off",
                           "render in.off -o out.png --size 12",
                           "render in.off -o out.png --bogus",
                           "render in.off -o out.jpg",
                           "render in.off -o out.png --camera 1",
                           "render in.off -o",
                           "skeleton in.off",
                           "skeleton in.off -o out.png",
                           "skeleton in.off -o s.vtp --nodes -3",
                           "skeleton in.off -o s.vtp --solver magic",
                           "skeleton a.off b.off -o s.vtp",
                           "sqm s.vtp",
                           "sqm s.vtp -o m.png",
                           "sqm s.vtp -o m.vtp --smoothing median",
                           "sqm s.vtp -o m.vtp --ring-vertices 2",
                           "sqm s.vtp -o m.vtp --subdivide 9",
                           "sqm s.vtp -o m.vtp --pairing best",
                           "sqm s.vtp -o m.vtp --sharp-scale 0",
                           "sqm s.vtp -o m.vtp --capsule-steps 0"}) {
    auto r = runCommand(medialCommand(args));
    EXPECT_EQ(r.exitCode, 2) << "medial " << args << "\n" << r.err;
    EXPECT_FALSE(r.err.empty()) << "medial " << args;
  }
}

TEST(Cli, SketchWritesSkeletonAndMeshThatSqmMeshes) {
  const std::string dir = scratchDir("cli-sketch");
  const std::string skeleton = dir + "/bird.vtp", mesh = dir + "/bird-mesh.vtp", tube = dir + "/bird-sqm.vtp";
  auto r =
      runCommand(medialCommand("sketch " + dataPath("sketches/bird.txt") + " -o " + skeleton + " --mesh " +
                               mesh + " --simplify 8 --part 2:5,30,30,10 --timings --quiet"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\"sketch\""), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(skeleton));
  EXPECT_TRUE(std::filesystem::exists(mesh));
  auto sqm = runCommand(medialCommand("sqm " + skeleton + " -o " + tube + " --quiet"));
  EXPECT_EQ(sqm.exitCode, 0) << sqm.err;
}

TEST(Cli, SketchUsageErrorsExitTwo) {
  for (const char* args :
       {"sketch", "sketch a.txt", "sketch a.txt -o s.png", "sketch a.txt -o s.vtp --mesh m.jpg",
        "sketch a.txt -o s.vtp --prune -1", "sketch a.txt -o s.vtp --part 2",
        "sketch a.txt -o s.vtp --part 0:1,2,3,4", "sketch a.txt -o s.vtp --part 1:1,2",
        "sketch a.txt -o s.vtp --thickness 0", "sketch a.txt b.txt -o s.vtp"}) {
    auto r = runCommand(medialCommand(args));
    EXPECT_EQ(r.exitCode, 2) << "medial " << args << "\n" << r.err;
    EXPECT_FALSE(r.err.empty()) << "medial " << args;
  }
}

TEST(Cli, SketchBadStrokesExitOneWithoutOutput) {
  const std::string dir = scratchDir("cli-sketch-bad");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0 0\n10 0\n", "at least 3"},        {"0 0\n100 100\n100 0\n0 60\n", "crosses itself"},
      {"0 0\n10 0\n20 0\n", "no area"},     {"0 0\n100 0\nnan 50\n0 100\n", "non-finite"},
      {"0 0\n100 0 7\n", "expected 'x y'"}, {"0 0\n100 0\n100 50\n1 0 0 0\n0 1 0 0\n", "rows instead of 4"},
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    const std::string input = dir + "/bad" + std::to_string(k) + ".txt",
                      output = dir + "/bad" + std::to_string(k) + ".vtp";
    std::ofstream(input) << cases[k].first;
    auto r = runCommand(medialCommand("sketch " + input + " -o " + output + " --quiet"));
    EXPECT_EQ(r.exitCode, 1) << cases[k].first << r.err;
    EXPECT_NE(r.err.find(cases[k].second), std::string::npos) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(output));
  }
  auto missing = runCommand(medialCommand("sketch " + dir + "/none.txt -o " + dir + "/none.vtp --quiet"));
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("none.txt: no such file or directory"), std::string::npos) << missing.err;
}

TEST(Cli, SkeletonOfTorusWritesSkeletonAndSegmentation) {
  const std::string dir = scratchDir("cli-skeleton");
  const std::string skeleton = dir + "/torus-skeleton.vtp", segmentation = dir + "/torus-segmentation.vtp";
  auto r = runCommand(medialCommand("skeleton " + dataPath("meshes/torus.off") + " -o " + skeleton +
                                    " --segmentation " + segmentation +
                                    " --nodes 12 --contraction-vertices 300 --timings --quiet"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\"skeleton\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"skeleton.decimation\""), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(skeleton));
  EXPECT_TRUE(std::filesystem::exists(segmentation));
  // The skeleton renders as a valid skeleton (Radius on every node).
  auto render = runCommand(medialCommand("render " + dataPath("meshes/torus.off") + " " + skeleton + " -o " +
                                         dir + "/torus-skeleton.png --size 320x240 --quiet"));
  EXPECT_EQ(render.exitCode, 0) << render.err;
}

// --no-centring, the British spelling, is kept for one release: the same skeleton as --no-centering.
TEST(Cli, NoCentringIsAnAliasOfNoCentering) {
  const std::string dir = scratchDir("cli-centering-alias");
  std::string written[2];
  int k = 0;
  for (const char* option : {"--no-centering", "--no-centring"}) {
    const std::string out = dir + "/" + std::to_string(k) + ".vtp";
    auto r = runCommand(medialCommand("skeleton " + dataPath("meshes/torus.off") + " -o " + out + " " +
                                      option + " --contraction-vertices 300 --quiet"));
    ASSERT_EQ(r.exitCode, 0) << option << ": " << r.err;
    std::ifstream file(out, std::ios::binary);
    written[k++].assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  }
  EXPECT_FALSE(written[0].empty());
  EXPECT_EQ(written[0], written[1]);
}

// medial COMMAND --list-options prints the command's own option table (what medial batch passes through).
TEST(Cli, ListOptionsPrintsTheCommandsOptionTable) {
  auto r = runCommand(medialCommand("sqm --list-options"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("values "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" --capsule-steps"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nflags "), std::string::npos) << r.out;
  const std::string flags = r.out.substr(r.out.find("\nflags "));
  EXPECT_NE(flags.find(" --union"), std::string::npos) << r.out;
  EXPECT_EQ(flags.find(" --subdivide"), std::string::npos) << "--subdivide takes a value: " << r.out;
}

// Ctrl-C stops the running filter at its next progress report: "cancelled", exit 130, no output written.
TEST(Cli, InterruptCancelsWithExitCode130AndNoOutput) {
  const std::string armadillo = medial::test::externalPath("cgal/meshes/armadillo.off");
  if (!std::filesystem::exists(armadillo)) GTEST_SKIP() << armadillo << " missing: run scripts/fetch-samples";
  const std::string dir = scratchDir("cli-interrupt");
  const std::string out = dir + "/skeleton.vtp";
  // At full resolution the contraction takes seconds; SIGINT arrives after one, once the command's
  // libraries are in the page cache (a first run), so that it reaches a running command, not its start;
  // --foreground: timeout sends it to the command alone, not once more to its process group.
  runCommand(medialCommand("--version"));
  auto r =
      runCommand("timeout --foreground --preserve-status -s INT 1 " +
                 medialCommand("skeleton " + armadillo + " -o " + out + " --contraction-vertices 30000"));
  EXPECT_EQ(r.exitCode, 130) << r.err;
  EXPECT_NE(r.err.find("medial skeleton: cancelled"), std::string::npos) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// The paper's constants from the command line, and the contracted mesh (Fig. 5): the input's faces at the
// contracted positions, close to the skeleton (a torus of tube radius 0.5 contracts to its core circle).
TEST(Cli, SkeletonTakesThePapersConstantsAndWritesTheContractedMesh) {
  const std::string dir = scratchDir("cli-skeleton-constants");
  const std::string contracted = dir + "/contracted.vtp";
  auto r = runCommand(medialCommand(
      "skeleton " + dataPath("meshes/torus.off") + " -o " + dir + "/s.vtp --contracted " + contracted +
      " --reference-vertices 500 --wl0 0.002 --sl 2.5 --wh0 1.5 --max-wl 1000 --max-wh 5000 --shape-weight 1 "
      "--sampling-weight 0.2 --collapse-length 0.002 --heat 2 --weights --quiet"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(contracted.c_str());
  reader->Update();
  vtkPolyData* mesh = reader->GetOutput();
  EXPECT_EQ(mesh->GetNumberOfPolys(), 1152) << "torus.off's faces";
  EXPECT_EQ(mesh->GetNumberOfPoints(), 576);
  // torus.off: R = 1, r = 0.35 about the z axis. Every input vertex lies 0.35 from the core circle; the
  // contracted ones lie near it.
  double farthest = 0, sum = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) {
    double p[3];
    mesh->GetPoint(i, p);
    const double d = std::hypot(std::hypot(p[0], p[1]) - 1.0, p[2]);
    farthest = std::max(farthest, d);
    sum += d;
  }
  EXPECT_LT(sum / double(mesh->GetNumberOfPoints()), 0.1) << "mean distance to the core circle (input: 0.35)";
  EXPECT_LT(farthest, 0.25);
  for (const char* bad :
       {"--wl0 -1", "--reference-vertices -1", "--sl 1", "--heat 0", "--collapse-length 2", "--wh0 x"}) {
    auto usage = runCommand(
        medialCommand("skeleton " + dataPath("meshes/torus.off") + " -o " + dir + "/bad.vtp --quiet " + bad));
    EXPECT_EQ(usage.exitCode, 2) << bad << ": " << usage.err;
  }
}

// Independent cycles of a skeleton file: lines - points + components.
long skeletonCycles(const std::string& path) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* skeleton = reader->GetOutput();
  medial::UnionFind sets{size_t(skeleton->GetNumberOfPoints())};
  long components = long(sets.size());
  for (vtkIdType c = 0; c < skeleton->GetNumberOfCells(); ++c)
    if (sets.join(int(skeleton->GetCell(c)->GetPointId(0)), int(skeleton->GetCell(c)->GetPointId(1))))
      --components;
  return long(skeleton->GetNumberOfCells()) - long(sets.size()) + components;
}

// --contraction-steps: one VTP per step, a .pvd that lists them in order, the two intermediate skeletons.
TEST(Cli, SkeletonWritesTheContractionStepsAsATimeSeries) {
  const std::string dir = scratchDir("cli-contraction-steps");
  auto r = runCommand(medialCommand("skeleton " + dataPath("meshes/torus.off") + " -o " + dir +
                                    "/torus.vtp --contraction-steps " + dir + "/steps --quiet"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream file(dir + "/steps/contraction.pvd");
  const std::string pvd((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  int listed = 0;
  for (size_t at = pvd.find("file=\""); at != std::string::npos; at = pvd.find("file=\"", at + 1)) {
    const std::string name = pvd.substr(at + 6, pvd.find('"', at + 6) - at - 6);
    char expected[32];
    std::snprintf(expected, sizeof expected, "contraction_%03d.vtp", listed++);
    EXPECT_EQ(name, expected);
    EXPECT_TRUE(std::filesystem::exists(dir + "/steps/" + name)) << name;
  }
  EXPECT_GE(listed, 3);
  EXPECT_TRUE(std::filesystem::exists(dir + "/steps/surgery-skeleton.vtp"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/steps/unselected-skeleton.vtp"));
  auto refused = runCommand(medialCommand("skeleton " + dataPath("meshes/torus.off") + " -o " + dir +
                                          "/t.vtp --contraction-steps /proc/no-such-dir --quiet"));
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_NE(refused.err.find("cannot create the directory"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/t.vtp")) << "refused before any output";
}

TEST(Cli, SqmWritesItsStagesAndRefusesAnUnmakeableDirectory) {
  const std::string dir = scratchDir("cli-sqm-stages");
  auto r = runCommand(medialCommand("sqm " + dataPath("skeletons/sqm/humanoid.vtp") + " -o " + dir +
                                    "/h.vtp --stages " + dir + "/stages --quiet"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"polyhedra.vtp", "refined-polyhedra.vtp", "base.vtp"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/stages/" + name)) << name;
  auto refused = runCommand(medialCommand("sqm " + dataPath("skeletons/sqm/humanoid.vtp") + " -o " + dir +
                                          "/x.vtp --stages /proc/no-such-dir --quiet"));
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.vtp"));
}

TEST(Cli, CenterlineWritesThePapersStages) {
  const std::string dir = scratchDir("cli-centerline-stages");
  const std::string volume = dataPath("volumes/tubes/u.nii.gz");
  auto r = runCommand(medialCommand("centerline " + volume + " -o " + dir + "/u.vtp --label 1 --stages " +
                                    dir + "/stages --quiet"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"voxels.vtp", "labels.vti", "primitive.vtp", "tsk-model.vtp", "tsk-fits.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/stages/" + name)) << name;
  std::ifstream csv(dir + "/stages/tsk-fits.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "t,x_mm,y_mm,z_mm");
  auto usage =
      runCommand(medialCommand("centerline " + volume + " -o " + dir + "/x.vtp --branches --stages " + dir));
  EXPECT_EQ(usage.exitCode, 2) << usage.err;
}

TEST(Cli, SkeletonPutsBackTheCyclesSurgeryLostAndSaysSo) {
  const std::string femur = medial::test::externalPath("cgal/meshes/femur.off");
  if (!std::filesystem::exists(femur)) GTEST_SKIP() << femur << " missing: run scripts/fetch-samples";
  const std::string dir = scratchDir("cli-skeleton-cycles");
  auto repaired = runCommand(medialCommand("skeleton " + femur + " -o " + dir + "/femur.vtp --quiet"));
  ASSERT_EQ(repaired.exitCode, 0) << repaired.err;
  EXPECT_NE(repaired.err.find("2 cycles that surgery lost put back (the mesh has genus 2)"),
            std::string::npos)
      << repaired.err;
  EXPECT_EQ(skeletonCycles(dir + "/femur.vtp"), 2);
  auto plain = runCommand(
      medialCommand("skeleton " + femur + " -o " + dir + "/femur-plain.vtp --no-cycle-repair --quiet"));
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_EQ(plain.err.find("put back"), std::string::npos) << plain.err;
  EXPECT_EQ(skeletonCycles(dir + "/femur-plain.vtp"), 0);  // surgery loses both of the femur's tiny handles
}

TEST(Cli, SkeletonOfBadInputFailsWithOneLine) {
  const std::string dir = scratchDir("cli-skeleton-bad");
  const std::string notMesh = dir + "/lines.obj";
  {
    std::ofstream out(notMesh);
    out << "v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3\n";
  }
  for (const std::string& input : {notMesh, dir + "/missing.off"}) {
    auto r = runCommand(medialCommand("skeleton " + input + " -o " + dir + "/out.vtp --quiet"));
    EXPECT_EQ(r.exitCode, 1) << input;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.vtp"));
  }
  auto badExtension = runCommand(medialCommand("skeleton " + dataPath("meshes/torus.off") + " -o " + dir +
                                               "/out.vtp --rig rig.obj --quiet"));
  EXPECT_EQ(badExtension.exitCode, 2) << badExtension.err;
  auto badBudget = runCommand(medialCommand("skeleton " + dataPath("meshes/torus.off") + " -o " + dir +
                                            "/out.vtp --contraction-vertices -5 --quiet"));
  EXPECT_EQ(badBudget.exitCode, 2) << badBudget.err;
  EXPECT_NE(badBudget.err.find("--contraction-vertices"), std::string::npos) << badBudget.err;
  auto noDirectory = runCommand(medialCommand("skeleton " + dataPath("meshes/torus.off") + " -o " + dir +
                                              "/out.vtp --rig " + dir + "/missing/rig.glb --quiet"));
  EXPECT_EQ(noDirectory.exitCode, 1);
  EXPECT_EQ(lineCount(noDirectory.err), 1) << noDirectory.err;
  EXPECT_NE(noDirectory.err.find("rig.glb"), std::string::npos) << noDirectory.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/missing/rig.glb"));
}

TEST(Cli, SkeletonWritesRigsAsGlbAndFbx) {
  const std::string dir = scratchDir("cli-rig");
  for (const auto& [name, magic] : {std::pair<std::string, std::string>{"torus.glb", "glTF"},
                                    std::pair<std::string, std::string>{"torus.fbx", "Kaydara FBX Binary"}}) {
    auto r = runCommand(medialCommand("skeleton " + dataPath("meshes/torus.off") + " -o " + dir +
                                      "/torus.vtp --nodes 8 --rig " + dir + "/" + name + " --quiet"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream file(dir + "/" + name, std::ios::binary);
    std::string head(magic.size(), '\0');
    file.read(head.data(), std::streamsize(head.size()));
    EXPECT_EQ(head, magic) << name;
  }
}

// `medial rig` binds a mesh made elsewhere: the sketch's inflated parts to its skeleton, an SQM mesh to the
// skeleton it was made from.
TEST(Cli, RigBindsSketchAndSqmMeshesToTheirSkeletons) {
  const std::string dir = scratchDir("cli-rig-any");
  ASSERT_EQ(runCommand(medialCommand("sketch " + dataPath("sketches/star.txt") + " -o " + dir +
                                     "/star.vtp --mesh " + dir + "/star-mesh.vtp --quiet"))
                .exitCode,
            0);
  auto sketch =
      runCommand(medialCommand("rig " + dir + "/star.vtp " + dir + "/star-mesh.vtp -o " + dir +
                               "/star.fbx --weights " + dir + "/star-weights.vtp --quiet --timings"));
  ASSERT_EQ(sketch.exitCode, 0) << sketch.err;
  EXPECT_NE(sketch.out.find("\"weights\""), std::string::npos) << sketch.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/star.fbx"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/star-weights.vtp"));

  const std::string skeleton = dataPath("skeletons/sqm/fish.vtp");
  ASSERT_EQ(runCommand(medialCommand("sqm " + skeleton + " -o " + dir + "/fish.obj --quiet")).exitCode, 0);
  auto sqm = runCommand(
      medialCommand("rig " + skeleton + " " + dir + "/fish.obj -o " + dir + "/fish.glb --root 0 --quiet"));
  ASSERT_EQ(sqm.exitCode, 0) << sqm.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/fish.glb"));

  // Weights alone (no rig file): what the Blender add-on's Bind runs.
  auto weightsOnly = runCommand(medialCommand("rig " + skeleton + " " + dir + "/fish.obj --weights " + dir +
                                              "/fish-weights.vtp --quiet"));
  ASSERT_EQ(weightsOnly.exitCode, 0) << weightsOnly.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/fish-weights.vtp"));
}

TEST(Cli, RigErrorsAreOneLineAndLeaveNoFile) {
  const std::string dir = scratchDir("cli-rig-errors");
  const std::string skeleton = dataPath("skeletons/sqm/fish.vtp"), torus = dataPath("meshes/torus.off");
  for (const std::string& args :
       {"rig " + skeleton, "rig " + skeleton + " " + torus, "rig " + skeleton + " " + torus + " -o rig.obj",
        "rig " + skeleton + " " + torus + " -o rig.glb --max-influences 0",
        "rig " + skeleton + " " + torus + " -o rig.glb --root -2"}) {
    auto r = runCommand(medialCommand(args));
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
  }
  const std::string rig = dir + "/rig.glb";
  const std::vector<std::pair<std::string, std::string>> failures = {
      {"rig " + torus + " " + torus, "not a skeleton"},
      {"rig " + skeleton + " " + skeleton, "not a surface mesh"},
      {"rig " + skeleton + " " + torus + " --root 999", "is not a node of the skeleton"},
      {"rig " + skeleton + " " + dir + "/none.off", "no such file"},
  };
  for (const auto& [args, reason] : failures) {
    auto r = runCommand(medialCommand(args + " -o " + rig + " --quiet"));
    EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(rig)) << args;
  }
}

// Overlapping tubes: without --union a note counts them and suggests it; with it the note says what the
// union did, and --timings has the counts and the union's time.
TEST(Cli, SqmNotesOverlapsAndUnitesThem) {
  const std::string dir = scratchDir("cli-sqm-union");
  const std::string crossing = dataPath("skeletons/overlapping/crossing.vtp");
  auto plain = runCommand(medialCommand("sqm " + crossing + " -o " + dir + "/plain.vtp --quiet --timings"));
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_NE(plain.err.find("tubes overlap at 6 pairs of nodes (32 pairs of faces cut each other)"),
            std::string::npos)
      << plain.err;
  EXPECT_NE(plain.err.find("--union makes it one closed surface"), std::string::npos) << plain.err;
  EXPECT_NE(plain.out.find("\"sqm.overlapping_face_pairs\": 32"), std::string::npos) << plain.out;
  auto united =
      runCommand(medialCommand("sqm " + crossing + " -o " + dir + "/united.obj --quiet --union --timings"));
  ASSERT_EQ(united.exitCode, 0) << united.err;
  EXPECT_NE(united.err.find("the union cut"), std::string::npos) << united.err;
  EXPECT_EQ(united.err.find("--union makes"), std::string::npos) << united.err;
  EXPECT_NE(united.out.find("\"sqm.union\""), std::string::npos) << united.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/united.obj"));
  // A skeleton without overlaps: no note.
  auto worm = runCommand(medialCommand("sqm " + dataPath("skeletons/sqm/worm.vtp") + " -o " + dir +
                                       "/worm.vtp --quiet --union"));
  ASSERT_EQ(worm.exitCode, 0) << worm.err;
  EXPECT_EQ(worm.err.find("overlap"), std::string::npos) << worm.err;
}

TEST(Cli, SqmWritesAQuadMeshAndFailsClearly) {
  const std::string dir = scratchDir("cli-sqm");
  auto r = runCommand(medialCommand("sqm " + dataPath("skeletons/hand.swc") + " -o " + dir +
                                    "/hand.obj --capsule --smoothing averaging --timings --quiet"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\"sqm\""), std::string::npos) << r.out;
  std::ifstream obj(dir + "/hand.obj");
  std::string line;
  int quads = 0;
  while (std::getline(obj, line))
    if (line.rfind("f ", 0) == 0 && std::count(line.begin(), line.end(), ' ') == 4) ++quads;
  EXPECT_GT(quads, 100);
  // A mesh is no skeleton; subdivision gives more faces, all quads.
  auto mesh =
      runCommand(medialCommand("sqm " + dataPath("meshes/torus.off") + " -o " + dir + "/t.vtp --quiet"));
  EXPECT_EQ(mesh.exitCode, 1);
  EXPECT_EQ(lineCount(mesh.err), 1) << mesh.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/t.vtp"));
  auto subdivide = runCommand(medialCommand("sqm " + dataPath("skeletons/hand.swc") + " -o " + dir +
                                            "/h.obj --subdivide 2 --sharp-scale 0.9 --quiet"));
  EXPECT_EQ(subdivide.exitCode, 0) << subdivide.err;
  std::ifstream fine(dir + "/h.obj");
  int fineQuads = 0, fineTriangles = 0;
  while (std::getline(fine, line)) {
    if (line.rfind("f ", 0) != 0) continue;
    const auto spaces = std::count(line.begin(), line.end(), ' ');
    fineQuads += spaces == 4;
    fineTriangles += spaces == 3;
  }
  EXPECT_EQ(fineTriangles, 0);
  EXPECT_GT(fineQuads, 16 * 100);
  // A repair is told on stderr: the quadruped's spine nodes inside its hips' spheres are merged.
  auto merged = runCommand(
      medialCommand("sqm " + dataPath("skeletons/sqm/quadruped.vtp") + " -o " + dir + "/q.vtp --quiet"));
  EXPECT_EQ(merged.exitCode, 0) << merged.err;
  EXPECT_NE(merged.err.find("merged into it"), std::string::npos) << merged.err;
  // Without the repair the same skeleton is an error naming a node, and no file is written.
  auto unmerged = runCommand(medialCommand("sqm " + dataPath("skeletons/sqm/quadruped.vtp") + " -o " + dir +
                                           "/unmerged.vtp --quiet --no-merge"));
  EXPECT_EQ(unmerged.exitCode, 1);
  EXPECT_EQ(lineCount(unmerged.err), 1) << unmerged.err;
  EXPECT_NE(unmerged.err.find("lies inside the sphere of a neighbouring branch node"), std::string::npos)
      << unmerged.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/unmerged.vtp"));
  // --timings has the paper's Table 1: stage times and counts (the hand: no merge needed, so --no-merge
  // changes nothing).
  auto table = runCommand(medialCommand("sqm " + dataPath("skeletons/sqm/quadruped.vtp") + " -o " + dir +
                                        "/q2.vtp --quiet --timings"));
  ASSERT_EQ(table.exitCode, 0) << table.err;
  for (const char* key :
       {"sqm.straightening", "sqm.generation", "sqm.refinement", "sqm.joining", "sqm.skinning",
        "sqm.subdivision", "sqm.repairs", "sqm.branch_nodes", "sqm.irregular_vertices"})
    EXPECT_NE(table.out.find(std::string("\"") + key + "\""), std::string::npos) << key << ": " << table.out;
  EXPECT_NE(table.out.find("\"sqm.merged_nodes\": 25"), std::string::npos) << table.out;
  auto hand = runCommand(medialCommand("sqm " + dataPath("skeletons/hand.swc") + " -o " + dir +
                                       "/hand-unmerged.vtp --quiet --no-merge"));
  EXPECT_EQ(hand.exitCode, 0) << hand.err;
  // The worm's two leaf fans of 8: four quads each by default, eight triangles with --triangle-fans.
  auto countTriangles = [&](const std::string& path) {
    std::ifstream in(path);
    int triangles = 0;
    while (std::getline(in, line))
      triangles += line.rfind("f ", 0) == 0 && std::count(line.begin(), line.end(), ' ') == 3;
    return triangles;
  };
  for (const char* option : {"", " --triangle-fans"}) {
    auto worm = runCommand(medialCommand("sqm " + dataPath("skeletons/sqm/worm.vtp") + " -o " + dir +
                                         "/w.obj --quiet" + option));
    ASSERT_EQ(worm.exitCode, 0) << worm.err;
    EXPECT_EQ(countTriangles(dir + "/w.obj"), *option ? 16 : 0) << option;
  }
}

TEST(Cli, CenterlineOfAPhantomAndItsErrors) {
  const std::string dir = scratchDir("cli-centerline");
  auto r = runCommand(medialCommand("centerline " + dataPath("volumes/tubes/helix.nii.gz") + " -o " + dir +
                                    "/helix.vtp --label 1 --timings --quiet"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\"centerline\""), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/helix.vtp"));
  auto missing = runCommand(medialCommand("centerline " + dataPath("volumes/tubes/helix.nii.gz") + " -o " +
                                          dir + "/x.vtp --label 9 --quiet"));
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_EQ(lineCount(missing.err), 1) << missing.err;
  EXPECT_NE(missing.err.find("no voxel has the label 9"), std::string::npos) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.vtp"));
  auto notVolume = runCommand(
      medialCommand("centerline " + dataPath("meshes/torus.off") + " -o " + dir + "/y.vtp --quiet"));
  EXPECT_EQ(notVolume.exitCode, 1);
  for (const char* bad : {"--threshold 5", "--label 1 --threshold 0:1", "--seed 1,2", "--label 1.5"}) {
    auto usage = runCommand(medialCommand("centerline " + dataPath("volumes/tubes/helix.nii.gz") + " -o " +
                                          dir + "/z.vtp " + bad));
    EXPECT_EQ(usage.exitCode, 2) << bad << ": " << usage.err;
  }
}

TEST(Cli, CenterlineProfileAndTerrainOfTheColonPhantom) {
  // The DICOM colon phantom: sections every 2 mm as CSV, the unfolded wall as PNG, the lumen's surface.
  const std::string dir = scratchDir("cli-colon");
  ASSERT_TRUE(medial::test::makeColonPhantom(dir + "/dicom"));
  auto r = runCommand(medialCommand("centerline " + dir + "/dicom -o " + dir +
                                    "/colon.vtp --threshold -1024:-600 " + "--profile " + dir +
                                    "/profile.csv --terrain " + dir + "/terrain.png " +
                                    "--section-spacing 2 --surface " + dir + "/lumen.vtp --quiet"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto lumen = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  lumen->SetFileName((dir + "/lumen.vtp").c_str());
  lumen->Update();
  EXPECT_GT(lumen->GetOutput()->GetNumberOfPolys(), 10000) << "--surface writes the lumen's surface";
  EXPECT_EQ(runCommand(medialCommand("centerline " + dir + "/dicom -o " + dir + "/x.vtp --surface " + dir +
                                     "/lumen.txt"))
                .exitCode,
            2);
  std::ifstream csv(dir + "/profile.csv");
  std::string header, row;
  std::getline(csv, header);
  EXPECT_EQ(header, "arc_length_mm,min_diameter_mm,max_diameter_mm,perimeter_mm,area_mm2,bridged");
  int rows = 0, plausible = 0;
  std::vector<double> arcs, minima;
  while (std::getline(csv, row)) {
    ++rows;
    double arc, low, high, perimeter, area;
    if (std::sscanf(row.c_str(), "%lf,%lf,%lf,%lf,%lf", &arc, &low, &high, &perimeter, &area) != 5) continue;
    arcs.push_back(arc);
    minima.push_back(low);
    if (low <= high && low > 10 && high < 40)
      ++plausible;  // the colon is 16 to 24 mm wide, folds 18 % narrower
  }
  // Each polyp narrows the section at its place: the min diameter there is at least half the polyp's radius
  // below the median of the sections within 12 mm.
  auto line = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  line->SetFileName((dir + "/colon.vtp").c_str());
  line->Update();
  vtkDataArray* arcLength = line->GetOutput()->GetPointData()->GetArray("ArcLength");
  ASSERT_NE(arcLength, nullptr);
  std::ifstream polyps(dir + "/dicom/polyps.txt");
  int polypCount = 0;
  while (std::getline(polyps, row)) {
    double p[3], radius;
    if (row.empty() || row[0] == '#' ||
        std::sscanf(row.c_str(), "%lf %lf %lf %lf", &p[0], &p[1], &p[2], &radius) != 4)
      continue;
    ++polypCount;
    vtkIdType nearest = 0;
    double best = 1e300;
    for (vtkIdType i = 0; i < line->GetOutput()->GetNumberOfPoints(); ++i) {
      double q[3];
      line->GetOutput()->GetPoint(i, q);
      const double d = std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]);
      if (d < best) best = d, nearest = i;
    }
    const double at = arcLength->GetComponent(nearest, 0);
    std::vector<double> around;
    double narrowest = 1e300;
    for (size_t k = 0; k < arcs.size(); ++k) {
      if (std::fabs(arcs[k] - at) <= 12 && std::isfinite(minima[k])) around.push_back(minima[k]);
      if (std::fabs(arcs[k] - at) <= 3 && std::isfinite(minima[k]))
        narrowest = std::min(narrowest, minima[k]);
    }
    ASSERT_FALSE(around.empty());
    std::nth_element(around.begin(), around.begin() + long(around.size() / 2), around.end());
    EXPECT_LT(narrowest, around[around.size() / 2] - 0.5 * radius) << "polyp at arc length " << at << " mm";
  }
  EXPECT_EQ(polypCount, 4);
  // Accuracy (the goal: mean distance to the true axis under 0.25 voxel = 0.175 mm here), leaving
  // out one radius (12 mm) at each end as for the tube phantoms. Measured 0.11 mm.
  std::vector<std::array<double, 3>> axis;
  std::ifstream axisFile(dir + "/dicom/axis.txt");
  while (std::getline(axisFile, row)) {
    std::array<double, 3> p;
    if (!row.empty() && row[0] != '#' && std::sscanf(row.c_str(), "%lf %lf %lf", &p[0], &p[1], &p[2]) == 3)
      axis.push_back(p);
  }
  ASSERT_GT(axis.size(), 100u);
  auto distance = [](const double* p, const std::array<double, 3>& q) {
    return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  };
  double sum = 0;
  int counted = 0;
  for (vtkIdType i = 0; i < line->GetOutput()->GetNumberOfPoints(); ++i) {
    double p[3];
    line->GetOutput()->GetPoint(i, p);
    if (distance(p, axis.front()) < 12 || distance(p, axis.back()) < 12) continue;
    double best = 1e300;
    for (size_t k = 0; k + 1 < axis.size(); ++k) {
      double ab[3], ap[3], t = 0, length2 = 0;
      for (int c = 0; c < 3; ++c)
        ab[c] = axis[k + 1][size_t(c)] - axis[k][size_t(c)], ap[c] = p[c] - axis[k][size_t(c)];
      for (int c = 0; c < 3; ++c) t += ab[c] * ap[c], length2 += ab[c] * ab[c];
      t = std::clamp(t / std::max(length2, 1e-300), 0.0, 1.0);
      best = std::min(best, std::hypot(ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]));
    }
    sum += best;
    ++counted;
  }
  ASSERT_GT(counted, 400);
  EXPECT_LT(sum / counted, 0.25 * 0.7) << "mean distance to the true axis, mm";
  EXPECT_GT(rows, 190) << "about 420 mm of centerline, a section every 2 mm";
  EXPECT_GT(plausible, 0.8 * rows);
  auto terrain = vtkSmartPointer<vtkPNGReader>::New();
  terrain->SetFileName((dir + "/terrain.png").c_str());
  terrain->Update();
  // A figure, not the raw 72-ray grid: the wall at least one pixel per section with axes and a colour bar
  // around it, in colour (viridis: green well above red and blue somewhere).
  vtkImageData* figure = terrain->GetOutput();
  EXPECT_GT(figure->GetDimensions()[0], 500);
  EXPECT_GT(figure->GetDimensions()[1], rows);
  int coloured = 0;
  for (int y = 0; y < figure->GetDimensions()[1]; y += 4)
    for (int x = 0; x < figure->GetDimensions()[0]; x += 4) {
      const auto* rgb = static_cast<unsigned char*>(figure->GetScalarPointer(x, y, 0));
      coloured += rgb[1] > rgb[0] + 40 && rgb[1] > rgb[2] - 20;
    }
  EXPECT_GT(coloured, 1000) << "the wall on a colour map";
  auto usage = runCommand(
      medialCommand("centerline " + dir + "/dicom -o " + dir + "/x.vtp --terrain " + dir + "/t.jpg"));
  EXPECT_EQ(usage.exitCode, 2) << usage.err;
  auto markups = runCommand(
      medialCommand("centerline " + dir + "/dicom -o " + dir + "/x.vtp --markups " + dir + "/c.txt"));
  EXPECT_EQ(markups.exitCode, 2) << markups.err;
  EXPECT_NE(markups.err.find("--markups must end in .mrk.json"), std::string::npos) << markups.err;
}

TEST(Cli, RenderWritesMeshSkeletonAndSwcPictures) {
  MEDIAL_REQUIRE_DISPLAY();
  const std::string dir = scratchDir("cli-render");
  for (const char* input :
       {"meshes/torus.off", "meshes/capsule.vtp", "skeletons/figure.vtp", "skeletons/hand.swc"}) {
    const std::string png = dir + "/" + std::filesystem::path(input).stem().string() + ".png";
    auto r =
        runCommand(medialCommand("render " + dataPath(input) + " -o " + png + " --size 200x150 --quiet"));
    ASSERT_EQ(r.exitCode, 0) << input << ": " << r.err;
    EXPECT_GT(foregroundFractionOfPng(png), 0.05) << input << " rendered blank";
  }
}

// --importance-map: the ghost view's map as a grey PNG at MapScale of the image, white where the ghosted
// skeleton projects and black around it.
TEST(Cli, RenderWritesTheImportanceMap) {
  MEDIAL_REQUIRE_DISPLAY();
  const std::string dir = scratchDir("cli-importance-map");
  const std::string skeleton = dataPath("skeletons/figure.vtp"), map = dir + "/map.png";
  auto r = runCommand(medialCommand("render " + skeleton + " --ghost " + skeleton + " -o " + dir +
                                    "/ghost.png --size 400x300 --importance-map " + map + " --quiet"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto png = vtkSmartPointer<vtkPNGReader>::New();
  png->SetFileName(map.c_str());
  png->Update();
  vtkImageData* image = png->GetOutput();
  EXPECT_EQ(image->GetDimensions()[0], 200);
  EXPECT_EQ(image->GetDimensions()[1], 150);
  double white = 0, black = 0;
  for (int y = 0; y < 150; ++y)
    for (int x = 0; x < 200; ++x) {
      const double v = image->GetScalarComponentAsDouble(x, y, 0, 0);
      white += v > 250;
      black += v < 5;
    }
  EXPECT_GT(white, 0.02 * 200 * 150);
  EXPECT_GT(black, 0.3 * 200 * 150);
  auto usage =
      runCommand(medialCommand("render " + skeleton + " -o " + dir + "/x.png --importance-map " + map));
  EXPECT_EQ(usage.exitCode, 2) << "needs --ghost";
}

TEST(Cli, RenderFailureIsOneLineAndLeavesNoFile) {
  MEDIAL_REQUIRE_DISPLAY();
  const std::string dir = scratchDir("cli-render-failure");
  const std::string png = dir + "/out.png";
  auto missing = runCommand(medialCommand("render " + dir + "/missing.off -o " + png));
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_EQ(lineCount(missing.err), 1) << missing.err;
  EXPECT_NE(missing.err.find(dir + "/missing.off"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("no such file"), std::string::npos) << missing.err;

  std::ofstream(dir + "/bad.swc") << "1 1 0 0 0 -3 -1\n";
  auto invalid = runCommand(medialCommand("render " + dir + "/bad.swc -o " + png));
  EXPECT_EQ(invalid.exitCode, 1);
  EXPECT_EQ(lineCount(invalid.err), 1) << invalid.err;
  EXPECT_NE(invalid.err.find("radius -3"), std::string::npos) << invalid.err;

  auto unwritable = runCommand(
      medialCommand("render " + dataPath("meshes/torus.off") + " -o " + dir + "/no/such/dir/x.png"));
  EXPECT_EQ(unwritable.exitCode, 1);
  EXPECT_EQ(lineCount(unwritable.err), 1) << unwritable.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir + "/") || !std::filesystem::exists(png));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().extension(), ".swc") << "left behind: " << entry.path();
}

TEST(Cli, RenderStartsPrivateXvfbWithoutDisplay) {
  if (std::system("command -v Xvfb >/dev/null") != 0) GTEST_SKIP() << "Xvfb is not installed";
  const std::string png = scratchDir("cli-private-xvfb") + "/torus.png";
  auto r = runCommand("env -u DISPLAY " + medialCommand("render " + dataPath("meshes/torus.off") + " -o " +
                                                        png + " --size 160x120"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(foregroundFractionOfPng(png), 0.05);
}

TEST(Cli, TimingsArePrintedAsJson) {
  MEDIAL_REQUIRE_DISPLAY();
  const std::string png = scratchDir("cli-timings") + "/t.png";
  auto r = runCommand(
      medialCommand("render " + dataPath("meshes/torus.off") + " -o " + png + " --size 64x48 --timings"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.front(), '{');
  EXPECT_NE(r.out.find("\"read\": "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"render\": "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"total\": "), std::string::npos) << r.out;
}

TEST(Cli, RenderGhostShowsTheSkeletonThroughItsMesh) {
  MEDIAL_REQUIRE_DISPLAY();
  const std::string dir = scratchDir("cli-ghost");
  const std::string mesh = dataPath("meshes/torus.off"), skeleton = dir + "/torus-skeleton.vtp";
  ASSERT_EQ(runCommand(medialCommand("skeleton " + mesh + " -o " + skeleton + " --quiet")).exitCode, 0);
  auto renderTo = [&](const std::string& name, const std::string& options) {
    const std::string png = dir + "/" + name;
    auto r = runCommand(medialCommand("render " + mesh + " " + options + " -o " + png +
                                      " --size 200x150 --skeleton-scale 0.3 --quiet"));
    EXPECT_EQ(r.exitCode, 0) << options << ": " << r.err;
    vtkSmartPointer<vtkImageData> image;
    image.TakeReference(loadPng(png));
    return image;
  };
  auto plain = renderTo("plain.png", skeleton);
  auto ghost = renderTo("ghost.png", skeleton + " --ghost " + skeleton);
  auto added = renderTo("added.png", "--ghost " + skeleton);  // a --ghost file not listed is added
  auto cutaway = renderTo("cutaway.png", skeleton + " --ghost " + skeleton + " --cutaway");
  auto faint = renderTo("faint.png", skeleton + " --ghost " + skeleton + " --ghost-opacity 0.8");
  auto layered = renderTo("layered.png", skeleton + " --ghost " + skeleton + " --ghost-layers");
  ASSERT_TRUE(plain && ghost && added && cutaway && faint && layered);
  EXPECT_FALSE(compareImages(layered, plain).passed) << "--ghost-layers lost the ghost";
  EXPECT_FALSE(compareImages(ghost, plain).passed) << "the ghost changed nothing";
  EXPECT_TRUE(compareImages(added, ghost, 8, 0.002).passed) << "--ghost of an unlisted file differs";
  EXPECT_FALSE(compareImages(cutaway, ghost, 15, 0.002).passed) << "cutaway looks like ghost";
  EXPECT_FALSE(compareImages(faint, ghost, 20, 0.002).passed) << "--ghost-opacity changed nothing";
}

TEST(Cli, RenderGhostsAVolumeRendering) {
  MEDIAL_REQUIRE_DISPLAY();
  // The helix phantom drawn by ray casting (full-range preset) hides its axis; the ghost shows it.
  const std::string dir = scratchDir("cli-ghost-volume");
  const std::string volume = dataPath("volumes/tubes/helix.nii.gz"),
                    axis = dataPath("volumes/tubes/helix-axis.vtp");
  auto renderTo = [&](const std::string& name, const std::string& options) {
    const std::string png = dir + "/" + name;
    auto r = runCommand(medialCommand("render " + volume + " " + axis + " --volume-rendering full-range " +
                                      options + " -o " + png + " --size 200x150 --quiet"));
    EXPECT_EQ(r.exitCode, 0) << options << ": " << r.err;
    vtkSmartPointer<vtkImageData> image;
    image.TakeReference(loadPng(png));
    return image;
  };
  auto plain = renderTo("plain.png", ""), ghost = renderTo("ghost.png", "--ghost " + axis);
  auto slices = renderTo("slices.png", "--volume-rendering slices");
  ASSERT_TRUE(plain && ghost && slices);
  EXPECT_FALSE(compareImages(ghost, plain, 15, 0.002).passed) << "the ghost changed nothing";
  EXPECT_FALSE(compareImages(slices, plain, 15, 0.002).passed) << "slices look like the volume rendering";
}

TEST(Cli, RenderGhostOptionErrors) {
  const std::string mesh = dataPath("meshes/torus.off");
  for (const char* bad :
       {"--ghost-importance 1", "--ghost x.vtp --ghost-importance 1,1", "--ghost x.vtp --ghost-importance 0",
        "--ghost x.vtp --ghost-opacity 2", "--ghost x.vtp --ghost-conflict closest",
        "--ghost x.vtp --ghost-map-scale 0", "--ghost", "--ghost-layers", "--volume-rendering mri"}) {
    auto r = runCommand(medialCommand("render " + mesh + " -o out.png " + bad));
    EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.err;
  }
  MEDIAL_REQUIRE_DISPLAY();
  const std::string png = scratchDir("cli-ghost-missing") + "/out.png";
  auto missing = runCommand(medialCommand("render " + mesh + " --ghost no-such-skeleton.vtp -o " + png));
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_EQ(lineCount(missing.err), 1) << missing.err;
  EXPECT_NE(missing.err.find("no-such-skeleton.vtp"), std::string::npos) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(png));
}

namespace {

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> tokens;
  std::istringstream in(text);
  for (std::string token; in >> token;) tokens.push_back(token);
  return tokens;
}

}  // namespace

// docs/cli.md's synopsis is every command's --help synopsis, word for word, so the two cannot drift.
TEST(Cli, CliPageUsageMatchesEveryCommandsHelp) {
  std::ifstream file(sourceDir() + "/docs/cli.md");
  const std::string page((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const size_t section = page.find("## Synopsis");
  ASSERT_NE(section, std::string::npos);
  const size_t open = page.find("```\n", section) + 4, close = page.find("```", open);
  std::istringstream block(page.substr(open, close - open));
  std::map<std::string, std::string> pageUsage;  // command -> its lines in the block
  std::string current;
  for (std::string line; std::getline(block, line);) {
    if (line.rfind("medial ", 0) == 0) current = words(line)[1];
    pageUsage[current] += line + "\n";
  }
  for (const char* command : {"render", "skeleton", "sqm", "centerline", "sketch", "rig"}) {
    const auto help = runCommand(medialCommand(std::string(command) + " --help"));
    ASSERT_EQ(help.exitCode, 0) << command;
    const size_t start = help.out.find("usage: ") + 7;
    const std::string synopsis = help.out.substr(start, help.out.find("\n\n", start) - start);
    EXPECT_EQ(words(pageUsage[command]), words(synopsis))
        << "docs/cli.md's usage of medial " << command << " differs from medial " << command << " --help";
  }
}

// A usage error is one line that says what is wrong and where to look, not the whole help.
TEST(Cli, UsageErrorIsOneLineWithAHint) {
  const auto r = runCommand(medialCommand("sqm s.vtp -o m.vtp --bogus"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("unknown option --bogus"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("see 'medial sqm --help'"), std::string::npos) << r.err;
  const auto range = runCommand(medialCommand("skeleton in.off -o s.vtp --iterations 5000"));
  EXPECT_EQ(range.exitCode, 2);
  EXPECT_NE(range.err.find("--iterations must be a whole number in 1..1000"), std::string::npos) << range.err;
}

// A write that fails midway (the disk fills up: here a file-size limit, with SIGXFSZ ignored so that
// write() returns an error) leaves neither the output nor a temporary file, and the command says which
// file failed in one line. The centerline's .vtp is about 13 kB; at 15 kB the .vtp fits and the profile
// (sections every 0.05 mm: about 140 kB) does not; at 2 kB the .vtp itself fails (VTK's XML writer
// crashed there before Medial wrote its bytes itself). `sh` counts the limit in blocks of 512 bytes.
TEST(Cli, AWriteThatFailsMidwayLeavesNoFileBehind) {
  const std::string dir = scratchDir("cli-disk-full");
  const std::string input = dataPath("volumes/tubes/helix.nii.gz");
  for (const auto& [blocks, failing] :
       {std::make_pair(30, std::string("profile.csv")), std::make_pair(4, std::string("helix.vtp"))}) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto r =
        runCommand("sh -c \"trap '' XFSZ; ulimit -f " + std::to_string(blocks) + "; exec " + medialExe() +
                   " centerline " + input + " -o " + dir + "/helix.vtp --label 1 --profile " + dir +
                   "/profile.csv --section-spacing 0.05 --quiet\"");
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(dir + "/" + failing), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/" + failing));
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      EXPECT_EQ(entry.path().filename().string().rfind(".tmp-", 0), std::string::npos)
          << "left behind: " << entry.path();
  }
}

// A DICOM folder holding a second series and a truncated slice of the first: the larger series is read,
// and the truncated slice (which GDCM reads as garbage without complaint) is an error naming it.
TEST(Cli, DicomFolderWithAnotherSeriesAndATruncatedSlice) {
  const std::string dir = scratchDir("cli-dicom-mixed");
  ASSERT_TRUE(medial::test::makeColonPhantom(dir + "/first"));
  ASSERT_TRUE(medial::test::makeColonPhantom(dir + "/second"));  // new UIDs: another series
  for (const char* slice : {"slice001.dcm", "slice002.dcm", "slice003.dcm"})
    std::filesystem::copy_file(dir + "/second/" + slice, dir + "/first/other-" + slice);
  const std::string command =
      "centerline " + dir + "/first -o " + dir + "/c.vtp --threshold -1024:-600 --quiet";
  const auto mixed = runCommand(medialCommand(command));
  EXPECT_EQ(mixed.exitCode, 0) << mixed.err;
  std::filesystem::resize_file(dir + "/first/slice100.dcm", 3000);
  std::filesystem::remove(dir + "/c.vtp");
  const auto truncated = runCommand(medialCommand(command));
  EXPECT_EQ(truncated.exitCode, 1);
  EXPECT_EQ(lineCount(truncated.err), 1) << truncated.err;
  EXPECT_NE(truncated.err.find("slice100.dcm: the slice is truncated"), std::string::npos) << truncated.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/c.vtp"));
}

// Hostile inputs of every kind end in one line that gives the right reason, exit 1 and no output file,
// within seconds; a face that repeats a vertex is only a degenerate face and the mesh is still used.
TEST(Cli, HostileInputsGiveOneLineWithTheRightReason) {
  const std::string dir = scratchDir("cli-hostile");
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + "/" + name) << text;
    return dir + "/" + name;
  };
  const std::string tetrahedron = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  std::string sameStroke;
  for (int i = 0; i < 40; ++i) sameStroke += "3 4\n";
  struct Case {
    std::string args, reason;
  };
  const std::vector<Case> cases = {
      {"skeleton " +
           write("nan.off", "OFF\n4 4 0\n0 0 nan\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"),
       "nan.off:3: the number nan is not finite"},
      {"skeleton " + write("huge.off", "OFF\n4 4 0\n0 0 1e300\n" + tetrahedron.substr(6)),
       "the number 1e300"},
      {"skeleton " + write("truncated.off", "OFF\n10000000 1 0\n0 0 0\n3 0 1 2\n"), "the file ends early"},
      {"skeleton " + write("bad-face.off", "OFF\n4 1 0\n" + tetrahedron.substr(0, 24) + "1000000000 0 1 2\n"),
       "face 0 does not list the 1000000000 corners"},
      {"sqm " + write("cycle.swc", "1 1 0 0 0 1 3\n2 3 1 0 0 1 1\n3 3 2 0 0 1 2\n"),
       "a cycle; SWC describes trees"},
      {"sqm " + write("zero-radius.swc", "1 1 0 0 0 0 -1\n2 3 1 0 0 1 1\n"), "radius 0"},
      {"sketch " + write("same.txt", sameStroke), "the strokes have no extent"},
      {"centerline " +
           write("claims-4gb.mha",
                 "ObjectType = Image\nNDims = 3\nElementType = MET_UCHAR\nDimSize = 2000 2000 1000\n"
                 "ElementDataFile = LOCAL\nxxxx"),
       "the header claims 4.0 GB of voxels"},
  };
  for (const Case& c : cases) {
    const medial::Stopwatch stopwatch;
    const auto r = runCommand(medialCommand(c.args + " -o " + dir + "/out.vtp --quiet"));
    EXPECT_EQ(r.exitCode, 1) << c.args << ": " << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.reason), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.vtp")) << c.args;
    EXPECT_LT(stopwatch.seconds(), 10.0) << c.args;
  }
  // Outputs where none can be written.
  for (const std::string& output : {std::string("/proc/medial-out.vtp"), dir + "/no-such-folder/out.vtp"}) {
    const auto r =
        runCommand(medialCommand("sqm " + dataPath("skeletons/hand.swc") + " -o " + output + " --quiet"));
    EXPECT_EQ(r.exitCode, 1) << output;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(output + ": cannot create the file"), std::string::npos) << r.err;
  }
  // A face that repeats a vertex is degenerate, not an error: the skeleton comes out.
  const auto repeated =
      runCommand(medialCommand("skeleton " +
                               write("repeated.off", "OFF\n4 4 0\n" + tetrahedron.substr(0, 24) +
                                                         "3 0 0 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n") +
                               " -o " + dir + "/repeated.vtp --quiet"));
  EXPECT_EQ(repeated.exitCode, 0) << repeated.err;
}

// The colon phantom's options: --collapse N leaves N stretches without air (N + 1 parts of colon air,
// their arc lengths in gaps.txt), --size scales the body and the colon, --help explains every option,
// usage errors (--fluid without --collapse among them) exit 2.
TEST(Cli, ColonPhantomCollapsedSegmentsAndSize) {
  const std::string dir = scratchDir("cli-phantom-options");
  const std::string phantom = binaryDir() + "/bin/medial-make-colon-phantom ";
  ASSERT_EQ(std::system((phantom + dir + "/collapsed " + dir +
                         "/collapsed.mha --collapse 2 --gap 12 --no-dicom"
                         " > /dev/null")
                            .c_str()),
            0);
  std::ifstream gaps(dir + "/collapsed/gaps.txt");
  std::string line;
  std::vector<std::pair<double, double>> stretches;
  while (std::getline(gaps, line))
    if (!line.empty() && line[0] != '#') {
      std::istringstream values(line);
      double start = 0, end = 0;
      values >> start >> end;
      stretches.push_back({start, end});
    }
  ASSERT_EQ(stretches.size(), 2u);
  for (const auto& [start, end] : stretches) EXPECT_NEAR(end - start, 12.0, 1e-9);
  EXPECT_FALSE(std::filesystem::exists(dir + "/collapsed/slice001.dcm")) << "--no-dicom writes no series";

  // The air inside the body (threshold, border air dropped) falls into three parts.
  auto readMha = [](const std::string& path, std::array<int, 3>& size) {  // uncompressed int16 MetaImage
    std::ifstream file(path, std::ios::binary);
    std::string header;
    while (std::getline(file, header) && header.rfind("ElementDataFile", 0) != 0)
      if (header.rfind("DimSize", 0) == 0)
        std::istringstream(header.substr(header.find('=') + 1)) >> size[0] >> size[1] >> size[2];
    std::vector<int16_t> voxels(size_t(size[0]) * size_t(size[1]) * size_t(size[2]));
    file.read(reinterpret_cast<char*>(voxels.data()), std::streamsize(voxels.size() * sizeof(int16_t)));
    return voxels;
  };
  std::array<int, 3> size{};
  const std::vector<int16_t> hu = readMha(dir + "/collapsed.mha", size);
  EXPECT_EQ(size, (std::array<int, 3>{206, 165, 187}));
  const auto runs = medial::selectedRuns(size, [&](int64_t i) { return hu[size_t(i)] <= -600; });
  medial::BinaryVolume frame;
  frame.size = size;
  EXPECT_EQ(medial::largestPart(frame, runs, true).parts - 1, 3)
      << "the air around the body, and the colon in three";

  ASSERT_EQ(
      std::system(
          (phantom + dir + "/big " + dir + "/big.mha --size 300x280x250 --no-dicom > /dev/null").c_str()),
      0);
  readMha(dir + "/big.mha", size);
  EXPECT_EQ(size, (std::array<int, 3>{300, 280, 250}));
  const auto help = runCommand(phantom + "--help");
  EXPECT_EQ(help.exitCode, 0);
  for (const char* option : {"--size", "--collapse", "--gap", "--fluid", "--no-dicom", "axis.txt"})
    EXPECT_NE(help.out.find(option), std::string::npos) << option << " is not explained:\n" << help.out;
  EXPECT_EQ(runCommand(phantom + dir + "/x --size 10").exitCode, 2);
  EXPECT_EQ(runCommand(phantom + dir + "/x --frobnicate").exitCode, 2);
  EXPECT_EQ(runCommand(phantom + dir + "/x --collapse two").exitCode, 2);
  const auto fluid = runCommand(phantom + dir + "/x --fluid");
  EXPECT_EQ(fluid.exitCode, 2) << "--fluid without --collapse changes nothing: a usage error";
  EXPECT_NE(fluid.err.find("--collapse"), std::string::npos) << fluid.err;
}

// A colon with a collapsed segment longer than --max-gap: two polylines and a note on stderr; a larger
// --max-gap bridges it (note, Bridged rows in the profile); bad values are usage errors.
TEST(Cli, CenterlineNotesGapsAndBridgesThem) {
  const std::string dir = scratchDir("cli-centerline-gaps");
  ASSERT_TRUE(
      medial::test::makeColonPhantom(dir + "/ct " + dir + "/ct.mha --collapse 1 --gap 50 --no-dicom"));
  const std::string base = "centerline " + dir + "/ct.mha --threshold -1024:-600 --quiet -o " + dir;
  auto split = runCommand(medialCommand(base + "/split.vtp"));
  ASSERT_EQ(split.exitCode, 0) << split.err;
  EXPECT_NE(split.err.find("note: a gap of"), std::string::npos) << split.err;
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName((dir + "/split.vtp").c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 2);

  auto joined = runCommand(medialCommand(base + "/joined.vtp --max-gap 70 --profile " + dir + "/p.csv"));
  ASSERT_EQ(joined.exitCode, 0) << joined.err;
  EXPECT_NE(joined.err.find("note: 2 parts of the structure joined across 1 gap"), std::string::npos)
      << joined.err;
  std::ifstream csv(dir + "/p.csv");
  std::string row;
  int bridgedRows = 0;
  std::getline(csv, row);
  while (std::getline(csv, row)) bridgedRows += row.size() > 2 && row.substr(row.size() - 2) == ",1";
  EXPECT_GE(bridgedRows, 20) << "50 mm without lumen, a section every mm";

  for (const char* bad : {"--max-gap -5", "--max-gap x", "--min-part-volume -1"}) {
    auto usage = runCommand(medialCommand(base + "/bad.vtp " + bad));
    EXPECT_EQ(usage.exitCode, 2) << bad << ": " << usage.err;
  }
}
