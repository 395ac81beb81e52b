// ParameterForm: a form of typed parameters (numbers, switches, choices) built from a list of
// descriptions, each with the paper's default and a tooltip naming the paper's symbol. Filter panels
// read the values back by name.
#pragma once

#include <QString>
#include <QStringList>
#include <QWidget>

#include <map>
#include <vector>

class QFormLayout;

namespace medial::gui {

struct Parameter {
  enum class Type { Integer, Real, Switch, Choice };
  QString name;     // key for value()
  QString label;    // shown left of the editor
  QString tooltip;  // the paper's symbol and section
  Type type = Type::Real;
  double value = 0;  // default (a Switch: 0/1; a Choice: the index)
  double minimum = 0, maximum = 1e9;
  int decimals = 3;
  QStringList choices;

  static Parameter integer(QString name, QString label, int value, int minimum, int maximum, QString tooltip);
  static Parameter real(QString name, QString label, double value, double minimum, double maximum,
                        int decimals, QString tooltip);
  static Parameter toggle(QString name, QString label, bool value, QString tooltip);
  static Parameter choice(QString name, QString label, QStringList choices, QString tooltip);
};

class ParameterForm : public QWidget {
  Q_OBJECT

 public:
  explicit ParameterForm(std::vector<Parameter> parameters, QWidget* parent = nullptr);

  double value(const QString& name) const;
  bool isOn(const QString& name) const { return value(name) != 0; }
  QString choice(const QString& name) const;
  void setValue(const QString& name, double value);
  QWidget* editor(const QString& name) const;
  // Puts every editor back to its default.
  void restoreDefaults();

 signals:
  void valueChanged(const QString& name);

 private:
  std::vector<Parameter> parameters_;
  std::map<QString, QWidget*> editors_;
};

}  // namespace medial::gui
