// SketchPanel: sketch skeletonization (vtkMedialSketchSkeleton) of a sketch (strokes read from a .txt
// file, or drawn in the 3-D view with "Draw strokes"). The four refinement thresholds are sliders; with
// "Update live" each change, and each new stroke, re-runs the filter and replaces skeleton and mesh.
#pragma once

#include "FilterPanel.h"
#include "MedialSketchData.h"

#include <QPointF>
#include <QVector>

#include <array>
#include <functional>
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

  // Part modelling (§3.2, §4.1) on the part the scope names (from 0): each changes the sketch, and with
  // "Update live" the parts reconnect by the connection rule as the filter runs again. False without a
  // sketch or such a part. Steps: 2 % of the sketch's size, 15 degrees, 10 %.
  bool movePart(int part, double alongU, double alongV);  // in steps, along the part's own plane
  bool turnPart(int part, double steps);
  bool scalePart(int part, double steps);
  // Adds the part mirrored across the first part's drawing plane (draw one half, get both).
  bool mirrorPart(int part);
  // Binds the sketch's mesh to its skeleton and writes the rig (.glb, .fbx): the animatable character.
  bool exportCharacter(const QString& path);

 signals:
  void drawingToggled(bool on);

 protected:
  vtkSmartPointer<vtkAlgorithm> makeFilter(SceneObject* input, QString& error) override;
  void collect(vtkAlgorithm* filter, SceneObject* input, double seconds) override;
  Steps steps(vtkAlgorithm* filter) override;
  void inputChanged(SceneObject* input) override;

 private:
  using Thresholds = std::array<double, 4>;  // ES, EM, ET, EC in sketch pixels

  void parameterChanged();
  void showScope(int index);
  // Applies `edit` to a copy of the sketch, which replaces it (same name), then runs again if live.
  bool editSketch(const std::function<bool(vtkPolyData*)>& edit);
  int scopePart() const;

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
