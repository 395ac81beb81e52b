#include "MainWindow.h"

#include "CenterlinePanel.h"
#include "FilterRunner.h"
#include "IsoSurfacePanel.h"
#include "MedialSketchData.h"
#include "ObjectList.h"
#include "SampleMenu.h"
#include "SkeletonEditor.h"
#include "SketchPanel.h"
#include "SkeletonPanel.h"
#include "SqmPanel.h"
#include "VolumeRendering.h"
#include "ViewGeometry.h"
#include "VtkView.h"

#include "vtkMedialGhostPass.h"
#include "MedialErrorCollector.h"
#include "vtkMedialReader.h"
#include "vtkMedialScene.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QAction>
#include <QComboBox>
#include <QDateTime>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QScrollArea>
#include <QSettings>
#include <QShowEvent>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QToolBar>

#include <vtkAssembly.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkDataArray.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageData.h>
#include <vtkImageProperty.h>
#include <vtkImageSlice.h>
#include <vtkImageSliceMapper.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkProp3DCollection.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkScalarsToColors.h>
#include <vtkVersion.h>
#include <vtkVolume.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace medial::gui {

namespace {

constexpr int kMaxRecent = 8;

QSettings settings() { return QSettings("Medial", "medial-gui"); }

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), scene_(vtkSmartPointer<vtkMedialScene>::New()) {
  setWindowTitle("Medial");
  setAcceptDrops(true);
  view_ = new VtkView(this);
  view_->setObjectName("view3d");
  view_->addRenderer(scene_->GetRenderer());
  scene_->GetRenderer()->UseFXAAOn();  // the widget's framebuffer has no multisampling
  connect(view_, &VtkView::resetCameraRequested, this, &MainWindow::resetCamera);
  connect(view_, &VtkView::clicked, this, &MainWindow::onViewClicked);
  connect(view_, &VtkView::strokeDrawn, this, &MainWindow::onStrokeDrawn);

  slices_ = new SliceViews(this);
  slices_->hide();
  connect(slices_, &SliceViews::cursorChanged, this, &MainWindow::onCursorChanged);
  connect(slices_, &SliceViews::windowLevelChanged, this, &MainWindow::onWindowLevelChanged);
  splitter_ = new QSplitter(Qt::Vertical, this);
  splitter_->addWidget(view_);
  splitter_->addWidget(slices_);
  splitter_->setStretchFactor(0, 3);
  splitter_->setStretchFactor(1, 2);
  setCentralWidget(splitter_);

  objects_ = new ObjectList(scene_, this);
  objects_->setErrorReporter(
      [this](const QString& title, const QString& message) { reportError(title, message); });
  connect(objects_, &ObjectList::sceneChanged, this, &MainWindow::render);
  connect(objects_, &ObjectList::logged, this, &MainWindow::log);
  connect(objects_, &ObjectList::objectsChanged, this, &MainWindow::onObjectsChanged);
  connect(objects_, &ObjectList::currentChanged, this, [this](SceneObject* object) {
    if (object && object->kind == SceneObject::Kind::Volume) showVolume(object);
  });
  auto* objectDock = new QDockWidget("Objects", this);
  objectDock->setObjectName("objects");
  objectDock->setWidget(objects_);
  addDockWidget(Qt::LeftDockWidgetArea, objectDock);

  log_ = new QPlainTextEdit(this);
  log_->setObjectName("log");
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(2000);
  auto* logDock = new QDockWidget("Log", this);
  logDock->setObjectName("logDock");
  logDock->setWidget(log_);
  addDockWidget(Qt::BottomDockWidgetArea, logDock);
  resizeDocks({logDock}, {110}, Qt::Vertical);

  progress_ = new QProgressBar(this);
  progress_->setRange(0, 100);
  progress_->setMaximumWidth(200);
  progress_->hide();
  statusBar()->addPermanentWidget(progress_);
  statusBar()->showMessage("Open a mesh, skeleton, volume or sketch with File > Open, or drop files here");

  buildPanels();
  buildGhostToolBar();
  buildMenus();
  // At 1024x768 the 3-D view keeps at least half the width: the docks start narrow (Objects 180,
  // Filters 300 pixels); users widen them, or close them from View > Panels.
  resizeDocks({objectDock, findChild<QDockWidget*>("filtersDock")}, {180, 300}, Qt::Horizontal);
  resize(1400, 900);
}

MainWindow::~MainWindow() {
  for (FilterPanel* panel : panels_) {  // stop workers before the objects they feed go away
    panel->cancel();
    panel->wait();
  }
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (reading_) {  // openFile is waiting for the reader further up the stack
    statusBar()->showMessage("A file is being read: close the window when it is done", 5000);
    event->ignore();
    return;
  }
  for (FilterPanel* panel : panels_) panel->cancel();
  if (layoutRestored_) saveLayout();
  QMainWindow::closeEvent(event);
}

void MainWindow::restoreLayout() {
  layoutRestored_ = true;
  QSettings s = settings();
  restoreGeometry(s.value("window/geometry").toByteArray());
  restoreState(s.value("window/state").toByteArray());
}

void MainWindow::saveLayout() {
  QSettings s = settings();
  s.setValue("window/geometry", saveGeometry());
  s.setValue("window/state", saveState());
}

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  // Files opened before the window was shown were framed for a guessed aspect ratio: frame them again
  // for the view's real size.
  if (!shownOnce_ && objectCount() > 0) resetCamera();
  shownOnce_ = true;
}

void MainWindow::buildPanels() {
  skeleton_ = new SkeletonPanel(objects_, this);
  sqm_ = new SqmPanel(objects_, this);
  centerline_ = new CenterlinePanel(objects_, this);
  sketch_ = new SketchPanel(objects_, this);
  iso_ = new IsoSurfacePanel(objects_, this);
  panels_ = {skeleton_, sqm_, centerline_, sketch_, iso_};
  tabs_ = new QTabWidget(this);
  tabs_->setObjectName("filters");
  const QStringList tips = {"Skeleton by mesh contraction (Au et al. 2008, contraction paper §III)",
                            "SQM quad-dominant tube mesh from a skeleton (CESCG 2014)",
                            "TSK centerline of a tubular structure in a volume (WSCG 2008)",
                            "Sketch skeletonization (straight skeleton + BoundedDP)",
                            "Iso-surface of a volume"};
  for (size_t i = 0; i < panels_.size(); ++i) {
    FilterPanel* panel = panels_[i];
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    const int tab = tabs_->addTab(scroll, panel->title());
    tabs_->setTabToolTip(tab, tips[static_cast<int>(i)]);
    connect(panel, &FilterPanel::message, this, &MainWindow::log);
    connect(panel, &FilterPanel::failed, this, &MainWindow::reportError);
  }
  connect(skeleton_, &SkeletonPanel::sceneChanged, this, &MainWindow::render);
  editor_ = new SkeletonEditor(objects_, scene_, view_, this);
  auto* editorScroll = new QScrollArea(this);
  editorScroll->setWidget(editor_);
  editorScroll->setWidgetResizable(true);
  tabs_->setTabToolTip(
      tabs_->addTab(editorScroll, "Edit"),
      "Skeleton editor with a live SQM mesh (SQM paper §6): drag nodes, add branches, radii");
  connect(editor_, &SkeletonEditor::sceneChanged, this, &MainWindow::render);
  connect(editor_, &SkeletonEditor::message, this, &MainWindow::log);
  connect(editor_, &SkeletonEditor::failed, this, &MainWindow::reportError);
  legend_ = vtkSmartPointer<vtkScalarBarActor>::New();
  legend_->SetNumberOfLabels(5);
  legend_->SetLabelFormat("%.2f");
  legend_->SetPosition(0.86, 0.15);
  legend_->SetWidth(0.12);
  legend_->SetHeight(0.6);
  legend_->SetMaximumWidthInPixels(110);
  legend_->VisibilityOff();
  scene_->GetRenderer()->AddViewProp(legend_);
  connect(skeleton_, &SkeletonPanel::legendChanged, this,
          [this](vtkScalarsToColors* table, const QString& title) {
            legend_->SetVisibility(table != nullptr);
            if (table) {
              legend_->SetLookupTable(table);
              legend_->SetTitle(title.toUtf8().constData());
            }
            render();
          });
  connect(centerline_, &CenterlinePanel::flyTo, this, &MainWindow::onFlyTo);
  connect(slices_, &SliceViews::pointClicked, this, [this](const SliceViews::Point& p) {
    if (tabs_->currentWidget() && tabs_->currentWidget()->isAncestorOf(centerline_)) centerline_->setSeed(p);
  });
  connect(sketch_, &SketchPanel::drawingToggled, this, [this](bool on) {
    view_->setDrawingMode(on);
    log(on ? "Sketch: drawing on (left-drag draws a closed stroke on the view plane through the focal point)"
           : "Sketch: drawing off");
  });
  auto* dock = new QDockWidget("Filters", this);
  dock->setObjectName("filtersDock");
  dock->setWidget(tabs_);
  dock->setMinimumWidth(260);
  addDockWidget(Qt::RightDockWidgetArea, dock);
  tabs_->setUsesScrollButtons(true);  // six tabs must not make the dock wider than its panels
}

FilterPanel* MainWindow::panel(const QString& name) const {
  for (FilterPanel* panel : panels_)
    if (panel->title().compare(name, Qt::CaseInsensitive) == 0) return panel;
  return nullptr;
}

void MainWindow::buildGhostToolBar() {
  QToolBar* bar = addToolBar("Ghost view");
  bar->setObjectName("ghostBar");
  bar->addWidget(new QLabel(" Ghost view ", bar));
  ghostMode_ = new QComboBox(bar);
  ghostMode_->setObjectName("ghostMode");
  ghostMode_->addItems({"Off", "Ghost", "Cutaway"});
  ghostMode_->setCurrentIndex(1);
  ghostMode_->setToolTip(
      "How objects of interest (Interest column; Shift+click in the 3-D view) show through "
      "what hides them (Luboschik and Schumann, WSCG 2008)");
  bar->addWidget(ghostMode_);
  bar->addWidget(new QLabel(" Opacity ", bar));
  ghostOpacity_ = new QSlider(Qt::Horizontal, bar);
  ghostOpacity_->setObjectName("ghostOpacity");
  ghostOpacity_->setRange(0, 100);
  ghostOpacity_->setValue(25);
  ghostOpacity_->setMaximumWidth(160);
  ghostOpacity_->setToolTip("Opacity of an occluder in front of an object of interest (default 0.25)");
  bar->addWidget(ghostOpacity_);
  bar->addWidget(new QLabel(" Conflicts ", bar));
  ghostConflict_ = new QComboBox(bar);
  ghostConflict_->setObjectName("ghostConflict");
  ghostConflict_->addItems({"Depth sorting", "Gradual importance"});
  ghostConflict_->setCurrentIndex(scene_->GetGhostPass()->GetConflict());
  ghostConflict_->setToolTip(
      "Where objects of interest hide each other (the paper's Fig. 2): the nearest one wins, or the more "
      "important one shows through the less important, which is ghosted by its importance");
  bar->addWidget(ghostConflict_);
  connect(ghostConflict_, &QComboBox::currentIndexChanged, this, [this](int conflict) {
    scene_->GetGhostPass()->SetConflict(conflict);
    render();
  });
  QAction* map = bar->addAction("Map");
  map->setObjectName("importanceMap");
  map->setCheckable(true);
  map->setToolTip(
      "Show the importance map over the view (the paper's Figs. 2, 4, 6): where the objects of "
      "interest project, brighter for the more important");
  connect(map, &QAction::toggled, this, &MainWindow::setImportanceMapShown);
  QAction* layers = bar->addAction("Layers");
  layers->setObjectName("ghostLayers");
  layers->setCheckable(true);
  layers->setToolTip(
      "Show every occluding layer in front of an object of interest, not only the one drawn "
      "last (slower on software OpenGL)");
  connect(layers, &QAction::toggled, this, [this](bool on) {
    scene_->GetGhostPass()->SetLayeredGhosts(on);
    render();
  });
  connect(ghostMode_, &QComboBox::currentIndexChanged, this, &MainWindow::setGhostMode);
  connect(ghostOpacity_, &QSlider::valueChanged, this, [this](int v) { setGhostOpacity(v / 100.0); });
}

void MainWindow::setImportanceMapShown(bool shown) {
  scene_->GetGhostPass()->SetKeepImportanceMap(shown);
  view_->setOverlay(shown ? std::function<QImage()>([this] { return importanceMapImage(); }) : nullptr);
  render();
}

QImage MainWindow::importanceMapImage() const {
  vtkImageData* map = scene_->GetGhostPass()->GetImportanceMap();
  vtkDataArray* values = map ? map->GetPointData()->GetScalars() : nullptr;
  if (!values) return {};
  const int width = map->GetDimensions()[0], height = map->GetDimensions()[1];
  // Translucent amber, as opaque as importance x coverage; rows flipped (GL's first row is the bottom).
  QImage image(width, height, QImage::Format_ARGB32_Premultiplied);
  for (int y = 0; y < height; ++y) {
    auto* row = reinterpret_cast<QRgb*>(image.scanLine(height - 1 - y));
    for (int x = 0; x < width; ++x) {
      const vtkIdType i = vtkIdType(y) * width + x;
      const double a = 0.7 * std::clamp(values->GetComponent(i, 0) * values->GetComponent(i, 2), 0.0, 1.0);
      row[x] = qPremultiply(qRgba(255, 180, 0, int(std::lround(255 * a))));
    }
  }
  return image;
}

void MainWindow::setGhostMode(int mode) {
  scene_->GetGhostPass()->SetMode(mode);
  if (ghostMode_->currentIndex() != mode) ghostMode_->setCurrentIndex(mode);
  render();
}

void MainWindow::setGhostOpacity(double opacity) {
  scene_->GetGhostPass()->SetGhostOpacity(opacity);
  const int value = static_cast<int>(opacity * 100 + 0.5);
  if (ghostOpacity_->value() != value) ghostOpacity_->setValue(value);
  render();
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction("&Open...", QKeySequence::Open, this, &MainWindow::openDialog);
  file->addAction("Open &DICOM Folder...", this, &MainWindow::openDicomDialog);
  recentMenu_ = file->addMenu("Open &Recent");
  fillSampleMenu(file->addMenu("Open a &Sample"), this,
                 [this](const QString& path) { return openFile(path); });
  updateRecentMenu();
  file->addAction("Save &Image...", QKeySequence("Ctrl+Shift+S"), this, &MainWindow::saveScreenshotDialog);
  file->addSeparator();
  file->addAction("&Quit", QKeySequence::Quit, qApp, &QApplication::closeAllWindows);
  QMenu* view = menuBar()->addMenu("&View");
  view->addAction("&Reset Camera", QKeySequence("R"), this, &MainWindow::resetCamera);
  QAction* slices = view->addAction("&Slice Views");
  slices->setCheckable(true);
  connect(slices, &QAction::toggled, slices_, &QWidget::setVisible);
  connect(objects_, &ObjectList::objectsChanged, slices,
          [this, slices] { slices->setChecked(slices_->isVisible()); });
  QMenu* panels = view->addMenu("&Panels");  // a closed dock comes back from here
  for (QDockWidget* dock : findChildren<QDockWidget*>()) panels->addAction(dock->toggleViewAction());
  QMenu* rendering = view->addMenu("&Volume Rendering");
  rendering->setToolTip("Ray-cast rendering of the volume shown in the slice views");
  volumeRenderingActions_ = new QActionGroup(this);
  QStringList names = volumePresetNames();
  names.prepend("Off");
  for (int i = 0; i < names.size(); ++i) {
    QAction* action = rendering->addAction(names[i], this, [this, i] { setVolumeRendering(i - 1); });
    action->setCheckable(true);
    action->setChecked(i == 0);
    volumeRenderingActions_->addAction(action);
  }
  QMenu* help = menuBar()->addMenu("&Help");
  help->addAction("&About Medial", this, &MainWindow::about);
}

void MainWindow::setErrorHandler(std::function<void(const QString&, const QString&)> handler) {
  errorHandler_ = std::move(handler);
}

void MainWindow::reportError(const QString& title, const QString& message) {
  statusBar()->showMessage(message, 10000);
  log("Error: " + message);
  if (errorHandler_)
    errorHandler_(title, message);
  else
    QMessageBox::critical(this, title, message);
}

void MainWindow::log(const QString& text) {
  log_->appendPlainText(QDateTime::currentDateTime().toString("hh:mm:ss  ") + text);
}

bool MainWindow::legendShown() const { return legend_->GetVisibility() != 0; }

QString MainWindow::logText() const { return log_->toPlainText(); }

bool MainWindow::openFile(const QString& path) {
  const QByteArray name = path.toLocal8Bit();
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  reader->SetFileName(name.constData());
  if (reading_) {
    reportError("Cannot open file", path + ": another file is being read; open it when that one is done");
    return false;
  }
  // The read runs on a worker thread (FilterRunner) while the window keeps painting; the status bar shows
  // its progress. Our readers cannot be interrupted, so there is no Cancel.
  reading_ = true;
  FilterRunner runner;
  connect(&runner, &FilterRunner::progressed, progress_, &QProgressBar::setValue);
  progress_->setValue(0);
  progress_->show();
  statusBar()->showMessage("Reading " + path);
  QApplication::setOverrideCursor(Qt::WaitCursor);
  QString readError;
  connect(&runner, &FilterRunner::finished, this,
          [&readError](vtkAlgorithm*, bool ok, const QString& message, double) {
            if (!ok) readError = message.isEmpty() ? QString("cannot be read") : message;
          });
  runner.start(reader, "read");
  runner.wait();
  QApplication::restoreOverrideCursor();
  progress_->hide();
  reading_ = false;

  if (!readError.isEmpty()) {
    QString message = readError;
    if (*reader->GetErrorMessage()) message = QString::fromLocal8Bit(reader->GetErrorMessage());
    reportError("Cannot open file", message.contains(path) ? message : path + ": " + message);
    return false;
  }
  vtkDataObject* data = reader->GetOutputDataObject(0);
  const QString title = QFileInfo(path).fileName().isEmpty() ? path : QFileInfo(path).fileName();
  SceneObject* object = objects_->add(title, data, path);
  if (!object) return false;
  addRigSkeleton(path, title);
  addRecent(path);
  log("Opened " + path);
  if (objectCount() == 1) resetCamera();
  statusBar()->showMessage("Opened " + path, 5000);
  return true;
}

void MainWindow::addRigSkeleton(const QString& path, const QString& title) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix != "fbx" && suffix != "glb" && suffix != "gltf") return;
  auto reader = vtkSmartPointer<vtkMedialReader>::New();
  auto errors = medial::ErrorCollector::Watch(reader);  // a glTF scene without joints is a mesh: no dialog
  const QByteArray name = path.toLocal8Bit();
  reader->SetFileName(name.constData());
  reader->RigSkeletonOn();
  reader->Update();
  if (errors->HasErrors()) return;
  if (objects_->add(title + " skeleton", reader->GetOutputDataObject(0), path))
    log("Opened the rig's skeleton");
}

void MainWindow::onObjectsChanged() {
  scene_->GetRenderer()->ResetCameraClippingRange();  // new objects may lie outside the near/far planes

  // The slice views follow the volume shown; when it is deleted, the next volume (or none).
  const auto volumes = objects_->ofKind(SceneObject::Kind::Volume);
  bool live = false;
  for (SceneObject* v : volumes) live = live || v == shownVolume_;
  if (!live) {
    shownVolume_ = nullptr;
    if (volumeRendering_) setVolumeRendering(-1);
    if (volumes.empty()) {
      slices_->setVolume(nullptr, QString());
      slices_->hide();
    } else {
      showVolume(volumes.back());
    }
  }
}

bool MainWindow::setVolumeRendering(int preset) {
  if (volumeRendering_) {
    scene_->GetRenderer()->RemoveVolume(volumeRendering_);
    volumeRendering_ = nullptr;
  }
  const bool on = preset >= 0 && shownVolume_;
  if (on) {
    volumeRendering_ =
        makeVolumeRendering(vtkImageData::SafeDownCast(shownVolume_->data), VolumePreset(preset));
    scene_->GetRenderer()->AddVolume(volumeRendering_);
    objects_->setVisible(shownVolume_, false);  // its opaque slices would cut through the rendering
    log(shownVolume_->name + ": volume rendering, " + volumePresetNames()[preset]);
  }
  volumeRenderingActions_->actions()[on ? preset + 1 : 0]->setChecked(true);
  render();
  return on || preset < 0;
}

void MainWindow::showVolume(SceneObject* volume) {
  if (volume == shownVolume_) return;
  if (volumeRendering_) setVolumeRendering(-1);
  shownVolume_ = volume;
  slices_->show();
  slices_->setVolume(vtkImageData::SafeDownCast(volume->data), volume->name);
}

std::vector<vtkImageSlice*> MainWindow::shownVolumeSlices() const {
  // The three slices vtkMedialScene draws for the shown volume (parts of its assembly).
  std::vector<vtkImageSlice*> slices;
  auto* assembly = shownVolume_ ? vtkAssembly::SafeDownCast(shownVolume_->prop) : nullptr;
  if (!assembly) return slices;
  vtkProp3DCollection* parts = assembly->GetParts();
  parts->InitTraversal();
  while (vtkProp3D* part = parts->GetNextProp3D())
    if (auto* slice = vtkImageSlice::SafeDownCast(part)) slices.push_back(slice);
  return slices;
}

void MainWindow::onCursorChanged(const SliceViews::Point&) {
  // The 3-D view's three slices of the shown volume follow the cursor.
  for (vtkImageSlice* slice : shownVolumeSlices())
    if (auto* mapper = vtkImageSliceMapper::SafeDownCast(slice->GetMapper()))
      mapper->SetSliceNumber(slices_->view(mapper->GetOrientation())->sliceIndex());
  render();
}

void MainWindow::onWindowLevelChanged(double window, double level) {
  for (vtkImageSlice* slice : shownVolumeSlices()) {
    slice->GetProperty()->SetColorWindow(window);
    slice->GetProperty()->SetColorLevel(level);
  }
  render();
}

void MainWindow::onViewClicked(const QPointF& position, Qt::KeyboardModifiers modifiers) {
  // A click selects the object under the pointer; on a skeleton with skinning weights it colors the mesh
  // by the nearest bone's weight; Shift+click toggles the object of interest (ghost view). Skeletons are
  // tried first: they usually lie inside the mesh that a plain pick would return.
  const qreal ratio = view_->devicePixelRatioF();
  const double x = position.x() * ratio, y = (view_->height() - position.y()) * ratio;
  auto picker = vtkSmartPointer<vtkCellPicker>::New();
  picker->SetTolerance(0.002);
  picker->PickFromListOn();
  for (SceneObject* skeleton : objects_->ofKind(SceneObject::Kind::Skeleton))
    if (skeleton->prop->GetVisibility()) picker->AddPickList(skeleton->prop);
  if (!picker->Pick(x, y, 0, scene_->GetRenderer())) {
    picker->PickFromListOff();
    if (!picker->Pick(x, y, 0, scene_->GetRenderer())) return;
  }
  vtkProp3D* prop = picker->GetProp3D();
  for (int row = 0; row < objects_->count(); ++row) {
    SceneObject* object = objects_->at(row);
    if (object->prop != prop) continue;
    objects_->setCurrent(object);
    if (modifiers & Qt::ShiftModifier) {
      objects_->setInterest(object, !object->interest);
      log(object->name + (object->interest ? ": object of interest" : ": context"));
    } else if (object->kind == SceneObject::Kind::Skeleton && object->skinnedMesh) {
      double point[3];
      picker->GetPickPosition(point);
      skeleton_->selectBone(object, SkeletonPanel::nearestBone(object, point));
    } else if (object->kind == SceneObject::Kind::Skeleton &&
               object->polyData()->GetCellData()->GetArray("Branch")) {
      // A sketch's skeleton: the clicked bone's branch gets its own epsilon_s (branch-level control).
      double point[3];
      picker->GetPickPosition(point);
      const int bone = SkeletonPanel::nearestBone(object, point);
      vtkDataArray* part = object->polyData()->GetCellData()->GetArray("Part");
      vtkDataArray* branch = object->polyData()->GetCellData()->GetArray("Branch");
      if (bone >= 0 && part && branch->GetComponent(bone, 0) >= 0) {
        sketch_->selectBranch(int(part->GetComponent(bone, 0)), int(branch->GetComponent(bone, 0)));
        log(QString("Sketch: ε_s of part %1, branch %2")
                .arg(int(part->GetComponent(bone, 0)) + 1)
                .arg(int(branch->GetComponent(bone, 0))));
      }
    }
    return;
  }
}

void MainWindow::onStrokeDrawn(const QVector<QPointF>& positions) {
  // The stroke lies in the plane facing the viewer through the focal point: its 2-D coordinates are along
  // the view's right (u) and up (v) axes, and its Placement maps (x, y, 0) back to 3-D: o + x u + y v.
  vtkCamera* camera = scene_->GetRenderer()->GetActiveCamera();
  camera->OrthogonalizeViewUp();
  double o[3], v[3], n[3], u[3], w[3];
  camera->GetFocalPoint(o);
  camera->GetViewUp(v);
  camera->GetDirectionOfProjection(n);
  vtkMath::Cross(n, v, u);  // right = direction of projection x up
  vtkMath::Normalize(u);
  vtkMath::Normalize(v);
  vtkMath::Cross(u, v, w);  // towards the viewer: a right-handed frame
  QVector<QPointF> stroke;
  for (const QPointF& position : positions) {
    Eigen::Vector3d p;
    if (!viewPlanePoint(scene_->GetRenderer(), view_, position, Eigen::Vector3d(o), Eigen::Vector3d(n), p))
      continue;
    const double d[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
    stroke.append(QPointF(vtkMath::Dot(d, u), vtkMath::Dot(d, v)));
  }
  const Placement placement = {u[0], v[0], w[0], o[0], u[1], v[1], w[1], o[1],
                               u[2], v[2], w[2], o[2], 0,    0,    0,    1};
  if (!sketch_->addStroke(stroke, placement))
    log("Sketch: the stroke needs at least 3 points on the drawing plane");
}

void MainWindow::onFlyTo(const std::array<double, 3>& eye, const std::array<double, 3>& /*focal*/,
                         const std::array<double, 3>& /*up*/) {
  vtkCamera* camera = scene_->GetRenderer()->GetActiveCamera();
  camera->ParallelProjectionOff();
  centerline_->applyCamera(camera);  // eye, focal, up and view angle of the fly-through
  if (shownVolume_) slices_->setCursor(eye);
  render();
}

void MainWindow::render() { view_->update(); }

int MainWindow::objectCount() const { return objects_->count(); }

vtkMedialScene* MainWindow::scene() const { return scene_; }

void MainWindow::resetCamera() {
  vtkCamera* camera = scene_->GetRenderer()->GetActiveCamera();
  camera->ParallelProjectionOff();
  const double aspect =
      view_->height() > 0 ? static_cast<double>(view_->width()) / view_->height() : 4.0 / 3.0;
  scene_->ResetCamera(aspect);
  if (!objects_->ofKind(SceneObject::Kind::Volume).empty()) {
    // Medical volumes (LPS: anterior is -y, superior +z): the patient's front, head up, as in 3D Slicer.
    const double* focal = camera->GetFocalPoint();
    const double distance = camera->GetDistance();
    camera->SetPosition(focal[0], focal[1] - distance, focal[2]);
    camera->SetViewUp(0, 0, 1);
    scene_->GetRenderer()->ResetCamera();
  }
  for (int axis = 0; axis < 3; ++axis) slices_->view(axis)->resetCamera();
  render();
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
  const QString filter =
      QString(
          "Meshes, skeletons, volumes and sketches (%1 %2 %3);;Meshes and skeletons (%1);;Volumes (%2);;"
          "Sketches (%3);;All files (*)")
          .arg(vtkMedialReader::GetMeshExtensions(), vtkMedialReader::GetVolumeExtensions(),
               vtkMedialReader::GetSketchExtensions());
  const QStringList paths = QFileDialog::getOpenFileNames(this, "Open", QString(), filter);
  for (const QString& path : paths) openFile(path);
}

void MainWindow::openDicomDialog() {
  const QString folder = QFileDialog::getExistingDirectory(this, "Open DICOM series folder");
  if (!folder.isEmpty()) openFile(folder);
}

void MainWindow::saveScreenshotDialog() {
  const QString path = QFileDialog::getSaveFileName(this, "Save Image", "medial.png", "Images (*.png *.jpg)");
  if (!path.isEmpty()) saveScreenshot(path);
}

QStringList MainWindow::recentFiles() const { return settings().value("recentFiles").toStringList(); }

void MainWindow::addRecent(const QString& path) {
  QStringList recent = recentFiles();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  recent.removeAll(absolute);
  recent.prepend(absolute);
  while (recent.size() > kMaxRecent) recent.removeLast();
  settings().setValue("recentFiles", recent);
  updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
  recentMenu_->clear();
  for (const QString& path : recentFiles())
    recentMenu_->addAction(path, this, [this, path] { openFile(path); });
  recentMenu_->setEnabled(!recentMenu_->isEmpty());
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  for (const QUrl& url : event->mimeData()->urls())
    if (url.isLocalFile()) openFile(url.toLocalFile());
  event->acceptProposedAction();
}

void MainWindow::about() {
  QMessageBox::about(
      this, "About Medial",
      QString("<b>Medial %1</b><br>Skeletons, centerlines, tube meshes and ghost views.<br><br>"
              "VTK %2 &middot; Qt %3 (built with %4) &middot; ITK %5 &middot; CGAL %6 &middot; "
              "Eigen %7")
          .arg(MEDIAL_VERSION, vtkVersion::GetVTKVersion(), qVersion(), QT_VERSION_STR, MEDIAL_ITK_VERSION,
               MEDIAL_CGAL_VERSION, MEDIAL_EIGEN_VERSION));
}

}  // namespace medial::gui
