// SketchPanel: sketch skeletonization (vtkMedialSketchSkeleton) of a sketch (strokes read from a .txt
// file, or drawn in the 3-D view with "Draw strokes"). The four refinement thresholds are sliders; with
// "Update live" each change, and each new stroke, re-runs the filter and replaces skeleton and mesh.
#pragma once

#include "FilterPanel.h"
#include "MedialSketchData.h"

#include <QPointF>
#include <QVector>

#include <array>
#include <map>
#include <utility>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;

namespace medial::gui {

class SketchPanel : public FilterPanel {
  Q_OBJECT

 public:
  SketchPanel(ObjectList* objects, QWidget* parent = nullptr);

  // The four thresholds of §3.1 and §3.3 in sketch pixels (ES, EM, ET, EC).
  QSlider* thresholdSlider(int index) const { return thresholds_[index]; }
  // Adds a closed stroke to the drawn sketch (creating it if needed) and runs the filter: `points` in the
  // stroke's own plane, which `placement` (row-major 4x4; default the z = 0 plane) puts in 3-D. False when
  // the stroke has fewer than 3 points.
  bool addStroke(const QVector<QPointF>& points,
                 const Placement& placement = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  bool isDrawing() const;
  // Which thresholds the sliders set: -1 the global ones, k those of part k (0-based).
  void setThresholdScope(int part);
  // Makes the simplification slider set epsilon_s of one branch (the `Branch` cell value) of one part.
  void selectBranch(int part, int branch);
  void setDrawing(bool on);

 signals:
  void drawingToggled(bool on);

 protected:
  vtkSmartPointer<vtkAlgorithm> makeFilter(SceneObject* input, QString& error) override;
  void collect(vtkAlgorithm* filter, SceneObject* input, double seconds) override;
  void inputChanged(SceneObject* input) override;

 private:
  using Thresholds = std::array<double, 4>;  // ES, EM, ET, EC in sketch pixels

  void parameterChanged();
  void showScope(int index);

  QSlider* thresholds_[4] = {};
  QComboBox* scope_ = nullptr;
  Thresholds global_;  // the filter's defaults at first
  std::map<int, Thresholds> partThresholds_;
  std::map<std::pair<int, int>, double> branchSimplification_;  // (part, branch) -> epsilon_s
  QLabel* values_[4] = {};
  QString scopeName_;
  QCheckBox* live_ = nullptr;
  QCheckBox* draw_ = nullptr;
};

}  // namespace medial::gui
