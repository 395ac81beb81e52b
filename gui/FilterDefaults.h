// Parameter forms built from a fresh filter: each editor's default, minimum and maximum are the filter's
// own (its constructor's value from the src/ parameters struct, its vtkSetClampMacro range), so the GUI
// cannot drift from the filter, the command line and Python (docs/ARCHITECTURE.md §3). The GUI adds only
// the label, the tooltip naming the paper's symbol, and the decimals shown.
#pragma once

#include "ParameterForm.h"

#include <QString>
#include <QStringList>

#include <string>

namespace medial::gui {

// A choice among a filter's comma-separated names, the filter's current one selected.
inline Parameter choiceOf(const QString& name, const QString& label, const std::string& names,
                          const std::string& current, const QString& tooltip) {
  QStringList choices = QString::fromStdString(names).split(',');
  for (QString& c : choices) c = c.trimmed();
  Parameter p = Parameter::choice(name, label, choices, tooltip);
  p.value = std::max(0, static_cast<int>(choices.indexOf(QString::fromStdString(current))));
  return p;
}

}  // namespace medial::gui

// Form rows of property `Property` of `filter` (a fresh vtkSmartPointer of the filter class).
#define MEDIAL_INTEGER_PARAMETER(filter, Property, label, tooltip)               \
  ::medial::gui::Parameter::integer(#Property, label, (filter)->Get##Property(), \
                                    (filter)->Get##Property##MinValue(),         \
                                    (filter)->Get##Property##MaxValue(), tooltip)
#define MEDIAL_REAL_PARAMETER(filter, Property, label, decimals, tooltip)                                  \
  ::medial::gui::Parameter::real(#Property, label, (filter)->Get##Property(),                              \
                                 (filter)->Get##Property##MinValue(), (filter)->Get##Property##MaxValue(), \
                                 decimals, tooltip)
#define MEDIAL_TOGGLE_PARAMETER(filter, Property, label, tooltip) \
  ::medial::gui::Parameter::toggle(#Property, label, (filter)->Get##Property(), tooltip)
