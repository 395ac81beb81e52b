// MainWindow: the shell of medial-gui: a 3-D view, an object list with visibility, File > Open, a
// screenshot, and error dialogs for files that cannot be read.
#pragma once

#include <QMainWindow>

#include <vtkSmartPointer.h>

#include <functional>

class QListWidget;
class QListWidgetItem;
class QProgressBar;
class vtkMedialScene;
class vtkProp3D;

namespace medial::gui {

class VtkView;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens a mesh, skeleton or volume and adds it to the view. On failure, reports the error (a dialog,
  // or the handler set with setErrorHandler) and returns false; the session is left as it was.
  bool openFile(const QString& path);
  // Saves what the 3-D view shows as an image (PNG, JPEG, ...). Returns false on failure.
  bool saveScreenshot(const QString& path);
  void resetCamera();
  int objectCount() const;
  VtkView* view() const { return view_; }
  vtkMedialScene* scene() const;

  // Replaces the error dialog (the --screenshot mode prints to stderr instead).
  void setErrorHandler(std::function<void(const QString& title, const QString& message)> handler);

 private slots:
  void openDialog();
  void saveScreenshotDialog();
  void onItemChanged(QListWidgetItem* item);
  void about();

 private:
  void buildMenus();
  void reportError(const QString& title, const QString& message);

  VtkView* view_ = nullptr;
  QListWidget* objects_ = nullptr;
  QProgressBar* progress_ = nullptr;
  vtkSmartPointer<vtkMedialScene> scene_;
  std::vector<vtkSmartPointer<vtkProp3D>> props_;  // one per row of objects_
  std::function<void(const QString&, const QString&)> errorHandler_;
};

}  // namespace medial::gui
