#include "SampleMenu.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QProcess>
#include <QTemporaryDir>

namespace medial::gui {

const QList<Sample>& bundledSamples() {
  static const QList<Sample> samples = {
      {"Torus (mesh, genus 1): Skeleton tab", "meshes/torus.off"},
      {"Capsule (mesh): Skeleton tab", "meshes/capsule.vtp"},
      {"Figure (skeleton with radii): SQM or Edit tab", "skeletons/figure.vtp"},
      {"Octopus (skeleton): SQM tab", "skeletons/sqm/octopus.vtp"},
      {"Humanoid (skeleton): SQM or Edit tab", "skeletons/sqm/humanoid.vtp"},
      {"Hand (sketch): Sketch tab", "sketches/hand.txt"},
      {"Noisy CT spiral (Hounsfield units): Centerline tab", "volumes/tubes/ct-spiral.nii.gz"},
      {"Branching tubes (labels): Centerline tab", "volumes/tubes/tree.nii.gz"},
  };
  return samples;
}

QString sampleDirectory() {
  const QString installed = QApplication::applicationDirPath() + "/../share/medial/samples";
  if (QFileInfo(installed).isDir()) return QDir(installed).canonicalPath();
#ifdef MEDIAL_SOURCE_DATA_DIR
  if (QFileInfo(MEDIAL_SOURCE_DATA_DIR).isDir()) return MEDIAL_SOURCE_DATA_DIR;
#endif
  return {};
}

namespace {

// The colon phantom is made, not bundled (a DICOM series of 187 slices): made once per session.
bool openColonPhantom(QWidget* parent, const std::function<bool(const QString&)>& open) {
  static QTemporaryDir folder;
  const QString series = folder.path() + "/colon-dicom";
  if (!QFileInfo(series).isDir()) {
    const QString maker = QApplication::applicationDirPath() + "/medial-make-colon-phantom";
    QApplication::setOverrideCursor(Qt::WaitCursor);
    QProcess process;
    process.start(maker, {series});
    const bool made = process.waitForFinished(120000) && process.exitStatus() == QProcess::NormalExit &&
                      process.exitCode() == 0;
    QApplication::restoreOverrideCursor();
    if (!made) {
      QMessageBox::warning(parent, "Open a Sample",
                           "Could not make the colon phantom with " + maker + ": " +
                               QString::fromUtf8(process.readAllStandardError()).trimmed());
      return false;
    }
  }
  return open(series);
}

}  // namespace

void fillSampleMenu(QMenu* menu, QWidget* parent, std::function<bool(const QString&)> open) {
  const QString folder = sampleDirectory();
  for (const Sample& sample : bundledSamples()) {
    const QString path = folder + "/" + sample.path;
    if (folder.isEmpty() || !QFileInfo::exists(path)) continue;
    menu->addAction(sample.label, parent, [open, path] { open(path); });
  }
  menu->addAction("Colon CT phantom (made on the spot): Centerline tab", parent,
                  [parent, open] { openColonPhantom(parent, open); });
}

}  // namespace medial::gui
