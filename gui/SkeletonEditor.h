// SkeletonEditor: the skeleton editor of the SQM paper (§6), whose tube mesh follows every edit. A panel
// picks the skeleton; with "Edit in the 3-D view" on, the view's mouse edits it:
//   drag a node                 move it in the plane facing the viewer
//   Shift + drag from a node    a new branch from it, its leaf following the pointer
//   Ctrl + click on an edge     a new node there
//   wheel over a node           its radius (10 % a notch)
//   Delete / Backspace          delete the selected node (a chain node's neighbours are joined)
// elsewhere the mouse turns the camera as usual. Every edit is undoable (QUndoStack). The SQM mesh is
// rebuilt at every change: while dragging at the panel's level without the fold repair (the repair's exact
// self-intersection test is most of K = 2's time), with it when the button is released. "Done" adds the
// edited skeleton and its mesh to the object list.
#pragma once

#include "VtkView.h"

#include "skeleton/Skeleton.h"

#include <QWidget>

#include <vtkSmartPointer.h>

class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;
class QUndoStack;
class vtkActor;
class vtkMedialScene;
class vtkPolyData;

namespace medial::gui {

class ObjectList;
struct SceneObject;

class SkeletonEditor : public QWidget, public ViewInteraction {
  Q_OBJECT

 public:
  SkeletonEditor(ObjectList* objects, vtkMedialScene* scene, VtkView* view, QWidget* parent = nullptr);
  ~SkeletonEditor() override;

  // Starts editing `skeleton` (a skeleton object); false (and a message) when it is not one.
  bool begin(SceneObject* skeleton);
  // Ends editing: the edited skeleton and its mesh become objects ("<name> edited", "... SQM").
  void finish();
  bool editing() const { return editing_; }

  const Skeleton& skeleton() const { return skeleton_; }
  vtkPolyData* mesh() const;  // the live SQM mesh
  int selectedNode() const { return selected_; }
  void selectNode(int node);
  QUndoStack* undoStack() const { return undo_; }
  double lastMeshMilliseconds() const { return meshMilliseconds_; }
  // Writes the edited skeleton (.vtp, .swc, ...). False (and a message) on failure.
  bool save(const QString& path);

  bool mousePress(QMouseEvent* event) override;
  bool mouseMove(QMouseEvent* event) override;
  bool mouseRelease(QMouseEvent* event) override;
  bool wheel(QWheelEvent* event) override;
  bool keyPress(QKeyEvent* event) override;

  // The skeleton as an undo step sets it (and the one that started a drag).
  void setSkeleton(const Skeleton& skeleton);

 signals:
  void sceneChanged();
  void message(const QString& text);
  void failed(const QString& title, const QString& text);

 private:
  void refreshChoices();
  void rebuild(bool final);
  void commit(const Skeleton& before, const QString& what);
  int nodeAt(const QPointF& position) const;
  void showSelection();

  ObjectList* objects_;
  vtkMedialScene* scene_;
  VtkView* view_;
  QComboBox* choice_ = nullptr;
  QCheckBox* edit_ = nullptr;
  QSpinBox* levels_ = nullptr;
  QLabel* status_ = nullptr;
  QUndoStack* undo_ = nullptr;

  bool editing_ = false;
  SceneObject* source_ = nullptr;
  QString sourceName_;
  Skeleton skeleton_;
  int selected_ = -1;
  // A drag: the node moved, the plane it moves in, the skeleton before it.
  int dragged_ = -1;
  Eigen::Vector3d dragOrigin_ = Eigen::Vector3d::Zero();
  Skeleton beforeDrag_;
  QString dragWhat_;
  double meshMilliseconds_ = 0;

  vtkSmartPointer<vtkPolyData> skeletonShown_, meshShown_, selectionShown_;
  vtkSmartPointer<vtkActor> skeletonActor_, meshActor_, selectionActor_;
};

}  // namespace medial::gui
