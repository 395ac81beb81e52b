// main of the GUI tests: one QApplication for the whole run, destroyed before the process's statics
// (a function-local static one crashed at exit). Without an X display Qt's offscreen platform is used,
// and the tests that need OpenGL skip themselves.
#include "TestPaths.h"
#include "VtkView.h"

#include <QApplication>

#include <gtest/gtest.h>

#include <X11/Xlib.h>  // after Qt and gtest: its macros (None, Bool, Status) would clash with them

#include <chrono>
#include <cstdlib>
#include <thread>

// Under xvfb-run a test process now and then found the X server not taking its connection (Qt then
// aborts: "could not connect to display"), once in about ten full runs. Wait until a connection is taken,
// up to ten seconds, before Qt tries.
namespace {

void waitForDisplay() {
  for (int attempt = 0; attempt < 100; ++attempt) {
    if (Display* display = XOpenDisplay(nullptr)) {
      XCloseDisplay(display);
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (!medial::test::hasDisplay())
    ::setenv("QT_QPA_PLATFORM", "offscreen", 1);
  else
    waitForDisplay();
  medial::gui::VtkView::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  return RUN_ALL_TESTS();
}
