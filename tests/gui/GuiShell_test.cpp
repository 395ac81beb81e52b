// medial-gui's shell: --screenshot renders what was opened; unreadable files give a message and a clean
// exit. Runs the built application under the X server of xvfb-run.
#include "ImageComparison.h"
#include "RunCommand.h"
#include "TestPaths.h"

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <fstream>

namespace {

using namespace medial::test;

}  // namespace

TEST(GuiShell, ScreenshotShowsMeshSkeletonAndSwc) {
  MEDIAL_REQUIRE_DISPLAY();
  const std::string dir = scratchDir("gui-screenshot");
  for (const char* input : {"meshes/torus.off", "skeletons/figure.vtp", "skeletons/hand.swc"}) {
    const std::string png = dir + "/" + std::filesystem::path(input).stem().string() + ".png";
    auto r = runCommand(medialGuiExe() + " --screenshot " + png + " --size 640x480 " + dataPath(input));
    ASSERT_EQ(r.exitCode, 0) << input << ": " << r.err;
    EXPECT_GT(foregroundFractionOfPng(png), 0.03) << input << ": the screenshot is blank";
  }
}

TEST(GuiShell, ScreenshotOfSeveralObjects) {
  MEDIAL_REQUIRE_DISPLAY();
  const std::string png = scratchDir("gui-several") + "/both.png";
  auto r = runCommand(medialGuiExe() + " --screenshot " + png + " " + dataPath("meshes/capsule.vtp") + " " +
                      dataPath("skeletons/figure.vtp"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(foregroundFractionOfPng(png), 0.05);
}

TEST(GuiShell, UnreadableFileGivesMessageAndCleanExit) {
  MEDIAL_REQUIRE_DISPLAY();
  const std::string dir = scratchDir("gui-unreadable");
  std::ofstream(dir + "/broken.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n";
  const std::string png = dir + "/never.png";
  for (const std::string& bad : {dir + "/broken.off", dir + "/missing.vtp", dir + "/notes.txt"}) {
    auto r = runCommand(medialGuiExe() + " --screenshot " + png + " " + bad);
    EXPECT_EQ(r.exitCode, 1) << bad;
    EXPECT_NE(r.err.find("medial-gui: " + bad), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(png));
  }
}

TEST(GuiShell, HelpAndVersion) {
  auto help = runCommand("QT_QPA_PLATFORM=offscreen " + medialGuiExe() + " --help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("--screenshot"), std::string::npos) << help.out;
  auto version = runCommand("QT_QPA_PLATFORM=offscreen " + medialGuiExe() + " --version");
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_NE(version.out.find("0."), std::string::npos);
}
