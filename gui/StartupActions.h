// StartupActions: what medial-gui's --run and --edit ask for once the files are open - the named filters
// run one after the other through their panels (each shown while it runs, the window responsive), then the
// last skeleton opened in the editor - in the window a user keeps open as in a --screenshot run.
#pragma once

#include <QObject>
#include <QStringList>

#include <functional>

namespace medial::gui {

class MainWindow;

class StartupActions : public QObject {
  Q_OBJECT

 public:
  // `filters`: panel names (skeleton, sqm, centerline, sketch, iso-surface), in order; `edit`: then the
  // editor. `done(ok)` is called once, when all have run or one has failed (its panel reported why).
  StartupActions(MainWindow* window, QStringList filters, bool edit, std::function<void(bool ok)> done);
  // Starts them (returns at once; the runs go on in the event loop).
  void start();

 private:
  void runNext();
  void finish(bool ok);

  MainWindow* window_;
  QStringList filters_;
  bool edit_;
  std::function<void(bool)> done_;
};

}  // namespace medial::gui
