// RigExportDialog: what Export Rig asks before the file name - the root node (the skeleton's own, by
// default its body centre), the mesh's up axis and the scale to metres - as `medial rig` takes them in
// --root, --up-axis and --scale.
#pragma once

#include <QDialog>
#include <QString>

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace medial::gui {

struct RigExportSettings {
  int root = -1;         // a node of the skeleton; -1: the skeleton's Root
  QString upAxis = "y";  // the mesh's up axis (vtkMedialRigWriter::SetUpAxis)
  double scale = 1.0;    // mesh units to metres
};

class RigExportDialog : public QDialog {
  Q_OBJECT

 public:
  // `nodes`: the skeleton's node count; `root`: its Root (shown as the default choice).
  RigExportDialog(int nodes, int root, QWidget* parent = nullptr);
  RigExportSettings settings() const;

 private:
  QSpinBox* root_ = nullptr;
  QComboBox* upAxis_ = nullptr;
  QDoubleSpinBox* scale_ = nullptr;
};

}  // namespace medial::gui
