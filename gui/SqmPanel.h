// SqmPanel: SQM tube mesh (vtkMedialSQM) from any skeleton. With "Update live" on, changing a parameter
// (e.g. the subdivision level slider) re-runs the filter and replaces the previous mesh of that skeleton.
#pragma once

#include "FilterPanel.h"

class QCheckBox;
class QSlider;

namespace medial::gui {

class SqmPanel : public FilterPanel {
  Q_OBJECT

 public:
  SqmPanel(ObjectList* objects, QWidget* parent = nullptr);
  QSlider* subdivisionSlider() const { return subdivision_; }

 protected:
  vtkSmartPointer<vtkAlgorithm> makeFilter(SceneObject* input, QString& error) override;
  void collect(vtkAlgorithm* filter, SceneObject* input, double seconds) override;
  Steps steps(vtkAlgorithm* filter) override;

 private:
  void parameterChanged();

  QSlider* subdivision_ = nullptr;
  QCheckBox* live_ = nullptr;
};

}  // namespace medial::gui
