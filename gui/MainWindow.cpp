#include "MainWindow.h"

#include "VtkView.h"

#include "MedialErrorCollector.h"
#include "vtkMedialReader.h"
#include "vtkMedialScene.h"

#include <QApplication>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QStatusBar>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkProp3D.h>
#include <vtkRenderer.h>
#include <vtkVersion.h>

namespace medial::gui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), scene_(vtkSmartPointer<vtkMedialScene>::New()) {
  setWindowTitle("Medial");
  view_ = new VtkView(this);
  view_->addRenderer(scene_->GetRenderer());
  scene_->GetRenderer()->UseFXAAOn();  // the widget's framebuffer has no multisampling
  setCentralWidget(view_);
  connect(view_, &VtkView::resetCameraRequested, this, &MainWindow::resetCamera);

  auto* dock = new QDockWidget("Objects", this);
  dock->setObjectName("objects");
  objects_ = new QListWidget(dock);
  objects_->setToolTip("Loaded objects; untick to hide");
  dock->setWidget(objects_);
  addDockWidget(Qt::LeftDockWidgetArea, dock);
  connect(objects_, &QListWidget::itemChanged, this, &MainWindow::onItemChanged);

  progress_ = new QProgressBar(this);
  progress_->setRange(0, 100);
  progress_->setMaximumWidth(200);
  progress_->hide();
  statusBar()->addPermanentWidget(progress_);
  statusBar()->showMessage("Open a mesh, skeleton or volume with File > Open");

  buildMenus();
  resize(1100, 750);
}

MainWindow::~MainWindow() = default;

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction("&Open...", QKeySequence::Open, this, &MainWindow::openDialog);
  file->addAction("Save &Image...", QKeySequence("Ctrl+Shift+S"), this, &MainWindow::saveScreenshotDialog);
  file->addSeparator();
  file->addAction("&Quit", QKeySequence::Quit, qApp, &QApplication::closeAllWindows);
  QMenu* view = menuBar()->addMenu("&View");
  view->addAction("&Reset Camera", QKeySequence("R"), this, &MainWindow::resetCamera);
  QMenu* help = menuBar()->addMenu("&Help");
  help->addAction("&About Medial", this, &MainWindow::about);
}

void MainWindow::setErrorHandler(std::function<void(const QString&, const QString&)> handler) {
  errorHandler_ = std::move(handler);
}

void MainWindow::reportError(const QString& title, const QString& message) {
  statusBar()->showMessage(message, 10000);
  if (errorHandler_)
    errorHandler_(title, message);
  else
    QMessageBox::critical(this, title, message);
}

bool MainWindow::openFile(const QString& path) {
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  auto errors = medial::ErrorCollector::Watch(reader);
  reader->SetFileName(path.toLocal8Bit().constData());

  // Progress of the read, shown in the status bar (reading runs on the UI thread here).
  auto progress = vtkSmartPointer<vtkCallbackCommand>::New();
  progress->SetClientData(progress_);
  progress->SetCallback([](vtkObject*, unsigned long, void* bar, void* fraction) {
    auto* progressBar = static_cast<QProgressBar*>(bar);
    progressBar->setValue(static_cast<int>(*static_cast<double*>(fraction) * 100));
    progressBar->repaint();
  });
  reader->AddObserver(vtkCommand::ProgressEvent, progress);
  progress_->setValue(0);
  progress_->show();
  statusBar()->showMessage("Reading " + path);
  QApplication::setOverrideCursor(Qt::WaitCursor);
  reader->Update();
  QApplication::restoreOverrideCursor();
  progress_->hide();

  if (errors->HasErrors()) {
    reportError("Cannot open file", QString::fromLocal8Bit(reader->GetErrorMessage()));
    return false;
  }
  auto sceneErrors = medial::ErrorCollector::Watch(scene_);
  vtkProp3D* prop = scene_->AddData(reader->GetOutputDataObject(0));
  if (!prop) {
    reportError("Cannot show file", path + ": " + QString::fromStdString(sceneErrors->Joined()));
    return false;
  }
  props_.emplace_back(prop);
  auto* item = new QListWidgetItem(QFileInfo(path).fileName(), objects_);
  item->setToolTip(path);
  item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
  item->setCheckState(Qt::Checked);
  if (props_.size() == 1) resetCamera();
  view_->update();
  statusBar()->showMessage("Opened " + path, 5000);
  return true;
}

int MainWindow::objectCount() const { return static_cast<int>(props_.size()); }

vtkMedialScene* MainWindow::scene() const { return scene_; }

void MainWindow::onItemChanged(QListWidgetItem* item) {
  const int row = objects_->row(item);
  if (row < 0 || row >= static_cast<int>(props_.size())) return;
  props_[row]->SetVisibility(item->checkState() == Qt::Checked);
  view_->update();
}

void MainWindow::resetCamera() {
  const double aspect = view_->height() > 0 ? static_cast<double>(view_->width()) / view_->height() : 4.0 / 3.0;
  scene_->ResetCamera(aspect);
  view_->update();
}

bool MainWindow::saveScreenshot(const QString& path) {
  const QImage image = view_->grabFramebuffer();
  if (image.isNull() || !image.save(path)) {
    reportError("Cannot save image", path + ": cannot write the image");
    return false;
  }
  return true;
}

void MainWindow::openDialog() {
  const QString filter = QString("Meshes, skeletons and volumes (%1 %2);;Meshes and skeletons (%1);;Volumes (%2);;All files (*)")
                             .arg(vtkMedialReader::GetMeshExtensions(), vtkMedialReader::GetVolumeExtensions());
  const QStringList paths = QFileDialog::getOpenFileNames(this, "Open", QString(), filter);
  for (const QString& path : paths) openFile(path);
}

void MainWindow::saveScreenshotDialog() {
  const QString path = QFileDialog::getSaveFileName(this, "Save Image", "medial.png", "Images (*.png *.jpg)");
  if (!path.isEmpty()) saveScreenshot(path);
}

void MainWindow::about() {
  QMessageBox::about(this, "About Medial",
                     QString("<b>Medial %1</b><br>Skeletons, centerlines, tube meshes and ghost views.<br><br>"
                             "VTK %2 &middot; Qt %3")
                         .arg(MEDIAL_VERSION, vtkVersion::GetVTKVersion(), qVersion()));
}

}  // namespace medial::gui
