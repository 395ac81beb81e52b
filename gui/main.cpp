// medial-gui: Medial's Qt6 application.
//   medial-gui [FILE...]                         open the files in the window
//   medial-gui [--run FILTER]... [--edit] [FILE...]   and run the filters, open the last skeleton in the
//                                                editor (gui/StartupActions.h)
//   medial-gui --screenshot IMAGE.png [FILE...]  open, render, save the 3-D view (--window: the whole
//                                                window), quit (for tests);
//                                                errors go to stderr and the exit code is 1
//   medial-gui --screenshot IMAGE.png --edit SKELETON   the skeleton in the editor with its live mesh
#include "FilterPanel.h"
#include "MainWindow.h"
#include "ObjectList.h"
#include "SkeletonEditor.h"
#include "StartupActions.h"
#include "VtkView.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTabWidget>
#include <QTimer>

#include <cstdio>

int main(int argc, char** argv) {
  medial::gui::VtkView::setDefaultSurfaceFormat();  // before QApplication
  QApplication app(argc, argv);
  QApplication::setApplicationName("medial-gui");
  QApplication::setApplicationVersion(MEDIAL_VERSION);

  QCommandLineParser parser;
  parser.setApplicationDescription("Medial: skeletons, centerlines, tube meshes and ghost views");
  parser.addHelpOption();
  parser.addVersionOption();
  QCommandLineOption screenshot("screenshot", "Open FILEs, save the 3-D view to IMAGE and quit.", "IMAGE");
  QCommandLineOption size("size", "Window size for --screenshot (default 1024x768).", "WxH", "1024x768");
  QCommandLineOption whole("window", "With --screenshot: the whole window, not only the 3-D view.");
  QCommandLineOption run("run",
                         "Run a filter panel with its defaults on the last suitable object, before the "
                         "screenshot (repeatable, in order): skeleton, sqm, centerline, sketch, iso-surface.",
                         "FILTER");
  QCommandLineOption edit("edit", "Open the last skeleton in the skeleton editor (with its live SQM mesh).");
  parser.addOption(run);
  parser.addOption(edit);
  parser.addOption(screenshot);
  parser.addOption(whole);
  parser.addOption(size);
  parser.addPositionalArgument("files", "Meshes, skeletons or volumes to open.", "[FILE...]");
  parser.process(app);

  medial::gui::MainWindow window;
  const bool batch = parser.isSet(screenshot);
  bool failed = false;
  if (batch) {
    window.setErrorHandler([&failed](const QString&, const QString& message) {
      std::fprintf(stderr, "medial-gui: %s\n", message.toLocal8Bit().constData());
      failed = true;
    });
    const QStringList wh = parser.value(size).split('x');
    if (wh.size() == 2 && wh[0].toInt() > 0 && wh[1].toInt() > 0) window.resize(wh[0].toInt(), wh[1].toInt());
  }
  if (!batch) window.restoreLayout();
  for (const QString& file : parser.positionalArguments()) window.openFile(file);
  window.show();
  if (failed) return 1;
  // --run and --edit, in the window a user keeps open or before the --screenshot.
  auto* actions =
      new medial::gui::StartupActions(&window, parser.values(run), parser.isSet(edit), [&](bool ok) {
        if (!batch) return;
        failed = !ok;
        if (ok) {
          window.resetCamera();
          failed = parser.isSet(whole) ? !window.grab().save(parser.value(screenshot))
                                       : !window.saveScreenshot(parser.value(screenshot));
        }
        app.quit();
      });
  actions->start();
  const int status = app.exec();
  return batch ? (failed ? 1 : 0) : status;
}
