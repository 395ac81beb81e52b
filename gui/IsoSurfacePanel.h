// IsoSurfacePanel: an iso-surface of a volume (VTK's flying edges) as a mesh object: the 3-D picture of a
// CT (bone at 300 HU, skin at -400 HU) or of a label image, and a mesh the skeleton filter can take.
#pragma once

#include "FilterPanel.h"

namespace medial::gui {

class IsoSurfacePanel : public FilterPanel {
  Q_OBJECT

 public:
  IsoSurfacePanel(ObjectList* objects, QWidget* parent = nullptr);

 protected:
  vtkSmartPointer<vtkAlgorithm> makeFilter(SceneObject* input, QString& error) override;
  void collect(vtkAlgorithm* filter, SceneObject* input, double seconds) override;
  // CT (values below -500 HU): bone at 300 HU; anything else (labels, masks): the middle of its range.
  void inputChanged(SceneObject* input) override;
};

}  // namespace medial::gui
