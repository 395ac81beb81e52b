#include "ParameterForm.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>

#include <utility>

namespace medial::gui {

Parameter Parameter::integer(QString name, QString label, int value, int minimum, int maximum,
                             QString tooltip) {
  Parameter p;
  p.name = std::move(name), p.label = std::move(label), p.tooltip = std::move(tooltip);
  p.type = Type::Integer, p.value = value, p.minimum = minimum, p.maximum = maximum;
  return p;
}

Parameter Parameter::real(QString name, QString label, double value, double minimum, double maximum,
                          int decimals, QString tooltip) {
  Parameter p;
  p.name = std::move(name), p.label = std::move(label), p.tooltip = std::move(tooltip);
  p.type = Type::Real, p.value = value, p.minimum = minimum, p.maximum = maximum, p.decimals = decimals;
  return p;
}

Parameter Parameter::toggle(QString name, QString label, bool value, QString tooltip) {
  Parameter p;
  p.name = std::move(name), p.label = std::move(label), p.tooltip = std::move(tooltip);
  p.type = Type::Switch, p.value = value ? 1 : 0;
  return p;
}

Parameter Parameter::choice(QString name, QString label, QStringList choices, QString tooltip) {
  Parameter p;
  p.name = std::move(name), p.label = std::move(label), p.tooltip = std::move(tooltip);
  p.type = Type::Choice, p.choices = std::move(choices);
  return p;
}

ParameterForm::ParameterForm(std::vector<Parameter> parameters, QWidget* parent)
    : QWidget(parent), parameters_(std::move(parameters)) {
  auto* layout = new QFormLayout(this);
  layout->setRowWrapPolicy(QFormLayout::WrapLongRows);  // a narrow dock puts fields under their labels
  layout->setContentsMargins(0, 0, 0, 0);
  for (const Parameter& p : parameters_) {
    QWidget* editor = nullptr;
    const QString name = p.name;
    switch (p.type) {
      case Parameter::Type::Integer: {
        auto* box = new QSpinBox(this);
        box->setRange(static_cast<int>(p.minimum), static_cast<int>(p.maximum));
        connect(box, &QSpinBox::valueChanged, this, [this, name] { emit valueChanged(name); });
        editor = box;
        break;
      }
      case Parameter::Type::Real: {
        auto* box = new QDoubleSpinBox(this);
        box->setDecimals(p.decimals);
        box->setRange(p.minimum, p.maximum);
        box->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, name] { emit valueChanged(name); });
        editor = box;
        break;
      }
      case Parameter::Type::Switch: {
        auto* box = new QCheckBox(this);
        connect(box, &QCheckBox::toggled, this, [this, name] { emit valueChanged(name); });
        editor = box;
        break;
      }
      case Parameter::Type::Choice: {
        auto* box = new QComboBox(this);
        box->addItems(p.choices);
        connect(box, &QComboBox::currentIndexChanged, this, [this, name] { emit valueChanged(name); });
        editor = box;
        break;
      }
    }
    editor->setObjectName(p.name);
    editor->setToolTip(p.tooltip);
    editors_[p.name] = editor;
    layout->addRow(p.label, editor);
  }
  restoreDefaults();
}

QWidget* ParameterForm::editor(const QString& name) const {
  auto it = editors_.find(name);
  return it == editors_.end() ? nullptr : it->second;
}

double ParameterForm::value(const QString& name) const {
  QWidget* editor = this->editor(name);
  if (auto* box = qobject_cast<QSpinBox*>(editor)) return box->value();
  if (auto* box = qobject_cast<QDoubleSpinBox*>(editor)) return box->value();
  if (auto* box = qobject_cast<QCheckBox*>(editor)) return box->isChecked() ? 1 : 0;
  if (auto* box = qobject_cast<QComboBox*>(editor)) return box->currentIndex();
  return 0;
}

QString ParameterForm::choice(const QString& name) const {
  auto* box = qobject_cast<QComboBox*>(editor(name));
  return box ? box->currentText() : QString();
}

void ParameterForm::setValue(const QString& name, double value) {
  QWidget* editor = this->editor(name);
  if (auto* box = qobject_cast<QSpinBox*>(editor)) box->setValue(static_cast<int>(value));
  if (auto* box = qobject_cast<QDoubleSpinBox*>(editor)) box->setValue(value);
  if (auto* box = qobject_cast<QCheckBox*>(editor)) box->setChecked(value != 0);
  if (auto* box = qobject_cast<QComboBox*>(editor)) box->setCurrentIndex(static_cast<int>(value));
}

void ParameterForm::restoreDefaults() {
  for (const Parameter& p : parameters_) setValue(p.name, p.value);
}

}  // namespace medial::gui
