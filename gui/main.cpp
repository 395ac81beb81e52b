// medial-gui: Medial's Qt6 application.
//   medial-gui [FILE...]                         open the files in the window
//   medial-gui --screenshot IMAGE.png [FILE...]  open, render, save the 3-D view (--window: the whole
//                                                window), quit (for tests);
//                                                errors go to stderr and the exit code is 1
//   medial-gui --screenshot IMAGE.png --edit SKELETON   the skeleton in the editor with its live mesh
#include "FilterPanel.h"
#include "MainWindow.h"
#include "ObjectList.h"
#include "SkeletonEditor.h"
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
  if (!batch) return app.exec();

  if (failed) return 1;
  QTimer::singleShot(0, &window, [&] {
    for (const QString& name : parser.values(run)) {
      medial::gui::FilterPanel* panel = window.panel(name);
      if (!panel) {
        std::fprintf(stderr, "medial-gui: --run %s: no such filter\n", name.toLocal8Bit().constData());
        failed = true;
        break;
      }
      for (int tab = 0; tab < window.filterTabs()->count(); ++tab)  // show the panel that runs
        if (window.filterTabs()->widget(tab)->isAncestorOf(panel)) window.filterTabs()->setCurrentIndex(tab);
      if (!panel->run()) break;  // the error handler has reported why
      panel->wait();
      if (!panel->lastRunSucceeded()) {
        std::fprintf(stderr, "medial-gui: --run %s failed; log:\n%s\n", name.toLocal8Bit().constData(),
                     window.logText().toLocal8Bit().constData());
        failed = true;
        break;
      }
    }
    if (!failed && parser.isSet(edit)) {
      const auto skeletons = window.objects()->ofKind(medial::gui::SceneObject::Kind::Skeleton);
      failed = skeletons.empty() || !window.skeletonEditor()->begin(skeletons.back());
      for (int tab = 0; tab < window.filterTabs()->count(); ++tab)
        if (window.filterTabs()->widget(tab)->isAncestorOf(window.skeletonEditor()))
          window.filterTabs()->setCurrentIndex(tab);
    }
    if (failed) {
      app.quit();
      return;
    }
    window.resetCamera();
    failed = parser.isSet(whole) ? !window.grab().save(parser.value(screenshot))
                                 : !window.saveScreenshot(parser.value(screenshot));
    app.quit();
  });
  app.exec();
  return failed ? 1 : 0;
}
