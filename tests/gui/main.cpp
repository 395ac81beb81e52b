// main of the GUI tests: one QApplication for the whole run, destroyed before the process's statics
// (a function-local static one crashed at exit). Without an X display Qt's offscreen platform is used,
// and the tests that need OpenGL skip themselves.
#include "TestPaths.h"
#include "VtkView.h"

#include <QApplication>

#include <cstdlib>

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (!medial::test::hasDisplay()) ::setenv("QT_QPA_PLATFORM", "offscreen", 1);
  medial::gui::VtkView::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  return RUN_ALL_TESTS();
}
