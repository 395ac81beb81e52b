#include "StartupActions.h"

#include "FilterPanel.h"
#include "MainWindow.h"
#include "ObjectList.h"
#include "SkeletonEditor.h"

#include <QTabWidget>
#include <QTimer>

#include <cstdio>

namespace medial::gui {

namespace {

// Brings the tab holding `widget` to the front.
void showTabOf(QTabWidget* tabs, QWidget* widget) {
  for (int tab = 0; tab < tabs->count(); ++tab)
    if (tabs->widget(tab)->isAncestorOf(widget)) tabs->setCurrentIndex(tab);
}

}  // namespace

StartupActions::StartupActions(MainWindow* window, QStringList filters, bool edit,
                               std::function<void(bool ok)> done)
    : QObject(window), window_(window), filters_(std::move(filters)), edit_(edit), done_(std::move(done)) {}

void StartupActions::start() {
  QTimer::singleShot(0, this, [this] { runNext(); });
}

void StartupActions::runNext() {
  if (filters_.isEmpty()) {
    if (edit_) {
      const auto skeletons = window_->objects()->ofKind(SceneObject::Kind::Skeleton);
      if (skeletons.empty() || !window_->skeletonEditor()->begin(skeletons.back())) {
        std::fprintf(stderr, "medial-gui: --edit: no skeleton to edit\n");
        return finish(false);
      }
      showTabOf(window_->filterTabs(), window_->skeletonEditor());
    }
    return finish(true);
  }
  const QString name = filters_.takeFirst();
  FilterPanel* panel = window_->panel(name);
  if (!panel) {
    std::fprintf(stderr, "medial-gui: --run %s: no such filter\n", name.toLocal8Bit().constData());
    return finish(false);
  }
  showTabOf(window_->filterTabs(), panel);
  auto connection = std::make_shared<QMetaObject::Connection>();
  *connection = connect(panel, &FilterPanel::completed, this, [this, name, connection](bool ok) {
    disconnect(*connection);
    if (!ok) {
      std::fprintf(stderr, "medial-gui: --run %s failed; log:\n%s\n", name.toLocal8Bit().constData(),
                   window_->logText().toLocal8Bit().constData());
      return finish(false);
    }
    runNext();
  });
  if (!panel->run()) {  // the panel's error handler has reported why
    disconnect(*connection);
    finish(false);
  }
}

void StartupActions::finish(bool ok) {
  if (done_) done_(ok);
  done_ = nullptr;
}

}  // namespace medial::gui
