// MainWindow: medial-gui: the 3-D view (ghost view, picking, sketch drawing), slice views for volumes,
// the object list, one panel per filter, a log, recent files, drag and drop and screenshots.
#pragma once

#include "SliceViews.h"

#include <QImage>
#include <QMainWindow>

#include <vtkSmartPointer.h>

#include <functional>
#include <vector>

class QComboBox;
class QMenu;
class QPlainTextEdit;
class QProgressBar;
class QSlider;
class QSplitter;
class QTabWidget;
class vtkMedialScene;
class vtkImageSlice;
class vtkVolume;
class vtkScalarBarActor;
class QActionGroup;

namespace medial::gui {

class CenterlinePanel;
class FilterPanel;
class IsoSurfacePanel;
class ObjectList;
class SceneObject;
class SkeletonEditor;
class SketchPanel;
class SkeletonPanel;
class SqmPanel;
class VtkView;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  // The window's size, position and docks as the user left them (interactive sessions: restored at start,
  // saved when the window closes; screenshots and tests keep the default layout).
  void restoreLayout();
  void saveLayout();
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens a mesh, skeleton, volume (file or DICOM folder) or sketch (.txt) and adds it. On failure,
  // reports the error (a dialog, or the handler set with setErrorHandler) and returns false; the session
  // is left as it was.
  bool openFile(const QString& path);
  // Saves what the 3-D view shows as an image (PNG, JPEG, ...). Returns false on failure.
  bool saveScreenshot(const QString& path);
  void resetCamera();
  int objectCount() const;
  VtkView* view() const { return view_; }
  vtkMedialScene* scene() const;
  // The ghost view's importance map over the 3-D view (toolbar "Map"), and the last frame's map as an
  // image (null when none was kept or no object of interest was in view).
  void setImportanceMapShown(bool shown);
  QImage importanceMapImage() const;
  ObjectList* objects() const { return objects_; }
  SliceViews* sliceViews() const { return slices_; }
  SkeletonPanel* skeletonPanel() const { return skeleton_; }
  SqmPanel* sqmPanel() const { return sqm_; }
  CenterlinePanel* centerlinePanel() const { return centerline_; }
  SketchPanel* sketchPanel() const { return sketch_; }
  IsoSurfacePanel* isoSurfacePanel() const { return iso_; }
  SkeletonEditor* skeletonEditor() const { return editor_; }
  QTabWidget* filterTabs() const { return tabs_; }
  // The filter panel titled `name` (case-insensitive: skeleton, sqm, centerline, sketch, iso-surface).
  FilterPanel* panel(const QString& name) const;
  QString logText() const;
  // Ghost view: 0 off, 1 ghost, 2 cutaway.
  void setGhostMode(int mode);
  void setGhostOpacity(double opacity);
  QStringList recentFiles() const;
  // Ray-cast rendering of the shown volume in 3-D with a preset (VolumePreset), or none (-1). False when
  // no volume is shown.
  bool setVolumeRendering(int preset);
  bool hasVolumeRendering() const { return volumeRendering_ != nullptr; }
  bool legendShown() const;

  // Replaces the error dialog (the --screenshot mode prints to stderr instead).
  void setErrorHandler(std::function<void(const QString& title, const QString& message)> handler);

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;
  void closeEvent(QCloseEvent* event) override;
  bool layoutRestored_ = false;
  void showEvent(QShowEvent* event) override;

 private:
  // A rig (.fbx, .glb, .gltf with joints) also shows its skeleton, as a second object "<title> skeleton".
  void addRigSkeleton(const QString& path, const QString& title);
  void buildMenus();
  void buildGhostToolBar();
  void buildPanels();
  void openDialog();
  void openDicomDialog();
  void saveScreenshotDialog();
  void about();
  void reportError(const QString& title, const QString& message);
  void log(const QString& text);
  void addRecent(const QString& path);
  void updateRecentMenu();
  void onObjectsChanged();
  void onCursorChanged(const SliceViews::Point& cursor);
  void onWindowLevelChanged(double window, double level);
  void onViewClicked(const QPointF& position, Qt::KeyboardModifiers modifiers);
  void onStrokeDrawn(const QVector<QPointF>& positions);
  void onFlyTo(const std::array<double, 3>& eye, const std::array<double, 3>& focal,
               const std::array<double, 3>& up);
  void showVolume(SceneObject* volume);
  std::vector<vtkImageSlice*> shownVolumeSlices() const;
  void render();

  VtkView* view_ = nullptr;
  SliceViews* slices_ = nullptr;
  QSplitter* splitter_ = nullptr;
  ObjectList* objects_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  QPlainTextEdit* log_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QComboBox* ghostConflict_ = nullptr;
  QComboBox* ghostMode_ = nullptr;
  QSlider* ghostOpacity_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  SkeletonPanel* skeleton_ = nullptr;
  SqmPanel* sqm_ = nullptr;
  CenterlinePanel* centerline_ = nullptr;
  SketchPanel* sketch_ = nullptr;
  IsoSurfacePanel* iso_ = nullptr;
  SkeletonEditor* editor_ = nullptr;
  std::vector<FilterPanel*> panels_;
  vtkSmartPointer<vtkMedialScene> scene_;
  SceneObject* shownVolume_ = nullptr;
  vtkSmartPointer<vtkVolume> volumeRendering_;  // of shownVolume_
  vtkSmartPointer<vtkScalarBarActor> legend_;   // the color scale of a mesh colored by bone weights
  QActionGroup* volumeRenderingActions_ = nullptr;
  bool shownOnce_ = false;
  bool reading_ = false;  // a file is being read (openFile waits for it with the event loop running)
  std::function<void(const QString&, const QString&)> errorHandler_;
};

}  // namespace medial::gui
