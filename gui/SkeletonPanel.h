// SkeletonPanel: skeleton by mesh contraction (vtkMedialContractionSkeleton) from a mesh. The result is
// the skeleton and the mesh colored by `SkeletonNode` (the segmentation); selectBone() colors that mesh
// by one bone's skinning weight instead; the skeleton's context menu exports the rig.
#pragma once

#include "FilterPanel.h"

class QSpinBox;
class vtkScalarsToColors;

namespace medial::gui {

class SkeletonPanel : public FilterPanel {
  Q_OBJECT

 public:
  SkeletonPanel(ObjectList* objects, QWidget* parent = nullptr);

  // Colors the segmentation mesh of `skeleton` by the weight of bone `bone` (its line cell), or by
  // SkeletonNode when bone < 0. False when the skeleton has no such mesh or bone.
  bool selectBone(SceneObject* skeleton, int bone);
  // The bone (line cell) of `skeleton` nearest to a world point, or -1.
  static int nearestBone(SceneObject* skeleton, const double point[3]);
  // The segmentation mesh computed with `skeleton`, if it is still in the list.
  SceneObject* segmentationOf(SceneObject* skeleton) const;

 signals:
  void sceneChanged();
  // The mesh is colored by a bone's weight with `table` (a legend is due), or by segments (table null).
  void legendChanged(vtkScalarsToColors* table, const QString& title);

 protected:
  vtkSmartPointer<vtkAlgorithm> makeFilter(SceneObject* input, QString& error) override;
  void collect(vtkAlgorithm* filter, SceneObject* input, double seconds) override;
  Steps steps(vtkAlgorithm* filter) override;

 private:
  QSpinBox* bone_ = nullptr;
  SceneObject* lastSkeleton_ = nullptr;
};

}  // namespace medial::gui
