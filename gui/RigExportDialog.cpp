#include "RigExportDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>

namespace medial::gui {

RigExportDialog::RigExportDialog(int nodes, int root, QWidget* parent) : QDialog(parent) {
  setWindowTitle("Export rig");
  auto* form = new QFormLayout(this);
  root_ = new QSpinBox(this);
  root_->setObjectName("rigRoot");
  root_->setRange(-1, std::max(0, nodes - 1));
  root_->setSpecialValueText(root >= 0 ? QString("body centre (node %1)").arg(root) : QString("body centre"));
  root_->setValue(-1);
  root_->setToolTip(
      "The node the rig hangs from; by default the skeleton's Root, its body centre (the hips)");
  form->addRow("Root node", root_);
  upAxis_ = new QComboBox(this);
  upAxis_->setObjectName("rigUpAxis");
  upAxis_->addItems({"y", "z", "x", "-y", "-z", "-x"});
  upAxis_->setToolTip("The mesh's up axis: y for glTF and most game assets, z for most scans and CAD");
  form->addRow("Up axis", upAxis_);
  scale_ = new QDoubleSpinBox(this);
  scale_->setObjectName("rigScale");
  scale_->setDecimals(6);
  scale_->setRange(1e-6, 1e6);
  scale_->setValue(1.0);
  scale_->setToolTip("Mesh units to metres: 0.01 for a mesh in centimetres, 0.001 for millimetres");
  form->addRow("Scale to metres", scale_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

RigExportSettings RigExportDialog::settings() const {
  return {root_->value(), upAxis_->currentText(), scale_->value()};
}

}  // namespace medial::gui
