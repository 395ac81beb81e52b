// ObjectList: the dock listing every loaded or computed object, with visibility (the check box), object
// of interest for the ghost view (second column), color, opacity, save as, rig export and delete.
#pragma once

#include "RigExportDialog.h"
#include "SceneObject.h"

#include <QWidget>

#include <array>
#include <functional>
#include <memory>
#include <vector>

class QSlider;
class QTreeWidget;
class QTreeWidgetItem;
class vtkMedialScene;

namespace medial::gui {

// Computed skeletons are drawn at this fraction of their `Radius`, so that they show inside their mesh.
constexpr double kComputedRadiusScale = 0.3;

class ObjectList : public QWidget {
  Q_OBJECT

 public:
  ObjectList(vtkMedialScene* scene, QWidget* parent = nullptr);
  ~ObjectList() override;

  // Shows `data` in the scene and adds a row; returns null (and reports why) when the scene cannot show it.
  // A skeleton's tubes are drawn at radiusScale x `Radius` (a centerline: thin, to fly inside its tube).
  SceneObject* add(const QString& name, vtkDataObject* data, const QString& path = QString(),
                   double radiusScale = 1.0);
  // Adds a polyline drawn as a plain line of `width` pixels in `rgb` (a centerline), not as tubes and balls.
  SceneObject* addLine(const QString& name, vtkPolyData* line, const std::array<double, 3>& rgb,
                       double width);
  void remove(SceneObject* object);
  int count() const { return static_cast<int>(objects_.size()); }
  SceneObject* at(int row) const { return objects_[row].get(); }
  SceneObject* current() const;
  void setCurrent(SceneObject* object);
  SceneObject* findByName(const QString& name) const;
  std::vector<SceneObject*> ofKind(SceneObject::Kind kind) const;

  void setVisible(SceneObject* object, bool visible);
  void setInterest(SceneObject* object, bool interest);  // importance 1 or 0
  // The object's importance in the ghost view, 0 (context) to 1; above 0 it is an object of interest.
  void setImportance(SceneObject* object, double importance);
  void setColor(SceneObject* object, double r, double g, double b);
  void setOpacity(SceneObject* object, double opacity);
  // Writes the object (mesh: VTP VTK OBJ PLY STL; skeleton also SWC; a centerline also 3D Slicer markups
  // curves, .mrk.json; volume VTI). False on failure.
  bool save(SceneObject* object, const QString& path);
  // Writes a skeleton's rig (GLB, FBX): a contraction skeleton's own weights, or those bindMesh made,
  // rooted, turned and scaled as `settings` say; logs what it wrote. False on failure.
  bool exportRig(SceneObject* object, const QString& path, const RigExportSettings& settings = {});
  // Binds `mesh` to the skeleton `skeleton` with heat-diffusion weights (vtkMedialSkinBinding): its
  // skinnedMesh for Export Rig, and its Root when it had none. False (with a dialog) on failure.
  bool bindMesh(SceneObject* skeleton, SceneObject* mesh);

  // Where errors go (MainWindow shows a dialog, or its own handler).
  void setErrorReporter(std::function<void(const QString& title, const QString& message)> report);

 signals:
  void sceneChanged();    // something visible changed: render again
  void objectsChanged();  // rows added or removed (panels refresh their input lists)
  void currentChanged(SceneObject* object);
  void logged(const QString& text);  // a line for the log (what Export Rig wrote)

 private:
  void onItemChanged(QTreeWidgetItem* item, int column);
  void showMenu(const QPoint& position);
  void chooseColor();
  void saveDialog();
  void rigDialog();
  QTreeWidgetItem* itemOf(const SceneObject* object) const;
  int rowOf(const SceneObject* object) const;
  void fail(const QString& title, const QString& message);
  // Adds the row of an object the scene already shows as `prop`.
  SceneObject* adopt(const QString& name, vtkDataObject* data, const QString& path, vtkProp3D* prop);

  vtkMedialScene* scene_;
  QTreeWidget* tree_ = nullptr;
  QSlider* importance_ = nullptr;
  QSlider* opacity_ = nullptr;
  std::vector<std::unique_ptr<SceneObject>> objects_;
  std::function<void(const QString&, const QString&)> report_;
};

}  // namespace medial::gui
