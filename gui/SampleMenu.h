// File > Open a Sample: the bundled samples (data/ in a build, share/medial/samples when installed) and a
// colon CT phantom made on the spot, so that a first run has something to open.
#pragma once

#include <QString>
#include <QStringList>
#include <functional>

class QMenu;
class QWidget;

namespace medial::gui {

struct Sample {
  QString label;  // what the menu shows
  QString path;   // relative to the sample folder
};

/// The samples the menu offers, in the order shown.
const QList<Sample>& bundledSamples();

/// The folder holding the samples: `<bin>/../share/medial/samples` when installed, else the source tree's
/// `data/`; empty when neither exists.
QString sampleDirectory();

/// Fills \p menu with one entry per sample found in sampleDirectory() and a colon CT phantom made by
/// medial-make-colon-phantom into a temporary folder; \p open opens a path and returns false on failure.
void fillSampleMenu(QMenu* menu, QWidget* parent, std::function<bool(const QString&)> open);

}  // namespace medial::gui
