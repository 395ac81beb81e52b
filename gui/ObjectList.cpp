#include "ObjectList.h"

#include "MedialSketchData.h"
#include "MedialSkeletonData.h"

#include "MedialErrorCollector.h"
#include "vtkMedialMarkupsCurveWriter.h"
#include "vtkMedialPolyDataWriter.h"
#include "vtkMedialRigWriter.h"
#include "vtkMedialGhostPass.h"
#include "vtkMedialScene.h"
#include "vtkMedialSkinBinding.h"

#include <QApplication>
#include <QColorDialog>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QSlider>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkWriter.h>
#include <vtkXMLImageDataWriter.h>

#include <algorithm>
#include <cmath>

namespace medial::gui {

namespace {

constexpr int kNameColumn = 0, kInterestColumn = 1;

SceneObject::Kind kindOf(vtkDataObject* data) {
  if (vtkImageData::SafeDownCast(data)) return SceneObject::Kind::Volume;
  auto* polyData = vtkPolyData::SafeDownCast(data);
  if (medial::isSketch(polyData)) return SceneObject::Kind::Sketch;
  if (polyData && vtkMedialScene::IsSkeleton(polyData)) return SceneObject::Kind::Skeleton;
  return SceneObject::Kind::Mesh;
}

}  // namespace

QString kindName(SceneObject::Kind kind) {
  switch (kind) {
    case SceneObject::Kind::Mesh:
      return "mesh";
    case SceneObject::Kind::Skeleton:
      return "skeleton";
    case SceneObject::Kind::Volume:
      return "volume";
    case SceneObject::Kind::Sketch:
      return "sketch";
  }
  return {};
}

ObjectList::ObjectList(vtkMedialScene* scene, QWidget* parent) : QWidget(parent), scene_(scene) {
  tree_ = new QTreeWidget(this);
  tree_->setObjectName("objectTree");
  tree_->setColumnCount(2);
  tree_->setHeaderLabels({"Object", "Interest"});
  tree_->header()->setSectionResizeMode(kNameColumn, QHeaderView::Stretch);
  tree_->header()->setSectionResizeMode(kInterestColumn, QHeaderView::ResizeToContents);
  tree_->header()->setStretchLastSection(false);
  tree_->setRootIsDecorated(false);
  tree_->setContextMenuPolicy(Qt::CustomContextMenu);
  tree_->setToolTip(
      "Tick: visible. Interest: stays visible through other objects in the ghost view.\n"
      "Right-click for color, save as, rig export and delete.");
  connect(tree_, &QTreeWidget::itemChanged, this, &ObjectList::onItemChanged);
  connect(tree_, &QTreeWidget::customContextMenuRequested, this, &ObjectList::showMenu);
  connect(tree_, &QTreeWidget::currentItemChanged, this, [this] {
    SceneObject* object = current();
    opacity_->setEnabled(object && object->kind != SceneObject::Kind::Volume);
    if (auto* actor = object ? vtkActor::SafeDownCast(object->prop) : nullptr) {
      const QSignalBlocker block(opacity_);
      opacity_->setValue(static_cast<int>(actor->GetProperty()->GetOpacity() * 100 + 0.5));
    }
    importance_->setEnabled(object && object->kind != SceneObject::Kind::Volume);
    if (object) {
      const QSignalBlocker block(importance_);
      importance_->setValue(
          static_cast<int>(std::lround(10 * vtkMedialGhostPass::GetImportance(object->prop))));
    }
    emit currentChanged(object);
  });

  opacity_ = new QSlider(Qt::Horizontal, this);
  opacity_->setObjectName("objectOpacity");
  opacity_->setRange(0, 100);
  opacity_->setValue(100);
  opacity_->setEnabled(false);
  opacity_->setToolTip("Opacity of the selected object");
  connect(opacity_, &QSlider::valueChanged, this, [this](int value) {
    if (SceneObject* object = current()) setOpacity(object, value / 100.0);
  });

  // The ghost view's importance levels (the paper's Fig. 2): 0 context, 0.1 .. 1 objects of interest; a
  // more important object shows through a less important one in front of it (gradual conflict rule).
  importance_ = new QSlider(Qt::Horizontal, this);
  importance_->setObjectName("objectImportance");
  importance_->setRange(0, 10);
  importance_->setPageStep(1);
  importance_->setTickPosition(QSlider::TicksBelow);
  importance_->setEnabled(false);
  importance_->setToolTip("Importance of the selected object in the ghost view: 0 context, 1 most important");
  connect(importance_, &QSlider::valueChanged, this, [this](int value) {
    if (SceneObject* object = current()) setImportance(object, value / 10.0);
  });

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(tree_);
  layout->addWidget(new QLabel("Opacity", this));
  layout->addWidget(opacity_);
  layout->addWidget(new QLabel("Importance (ghost view)", this));
  layout->addWidget(importance_);
}

ObjectList::~ObjectList() = default;

void ObjectList::setErrorReporter(std::function<void(const QString&, const QString&)> report) {
  report_ = std::move(report);
}

void ObjectList::fail(const QString& title, const QString& message) {
  if (report_) report_(title, message);
}

SceneObject* ObjectList::add(const QString& name, vtkDataObject* data, const QString& path,
                             double radiusScale) {
  auto errors = medial::ErrorCollector::Watch(scene_);
  const double sceneScale = scene_->GetSkeletonRadiusScale();
  scene_->SetSkeletonRadiusScale(radiusScale);
  // A sketch is drawn where its strokes lie in 3-D (their Placement), not in their own planes' coordinates.
  vtkSmartPointer<vtkDataObject> shown = data;
  if (data && kindOf(data) == SceneObject::Kind::Sketch)
    shown = placedStrokes(vtkPolyData::SafeDownCast(data));
  vtkProp3D* prop = shown ? scene_->AddData(shown) : nullptr;
  scene_->SetSkeletonRadiusScale(sceneScale);
  scene_->RemoveObserver(errors);
  if (!prop) {
    fail("Cannot show " + name, name + ": " + QString::fromStdString(errors->Joined()));
    return nullptr;
  }
  return adopt(name, data, path, prop);
}

SceneObject* ObjectList::addLine(const QString& name, vtkPolyData* line, const std::array<double, 3>& rgb,
                                 double width) {
  auto errors = medial::ErrorCollector::Watch(scene_);
  vtkProp3D* prop = scene_->AddLine(line, rgb.data(), width);
  scene_->RemoveObserver(errors);
  if (!prop) {
    fail("Cannot show " + name, name + ": " + QString::fromStdString(errors->Joined()));
    return nullptr;
  }
  return adopt(name, line, QString(), prop);
}

SceneObject* ObjectList::adopt(const QString& name, vtkDataObject* data, const QString& path,
                               vtkProp3D* prop) {
  auto object = std::make_unique<SceneObject>();
  object->name = name;
  object->path = path;
  object->kind = kindOf(data);
  object->data = data;
  object->prop = prop;
  if (object->kind == SceneObject::Kind::Sketch)  // strokes: thin lines, not tubes
    if (auto* actor = vtkActor::SafeDownCast(prop)) actor->GetProperty()->SetColor(0.1, 0.1, 0.1);

  auto* item = new QTreeWidgetItem;
  item->setText(kNameColumn, name);
  item->setToolTip(kNameColumn,
                   (path.isEmpty() ? QString("computed") : path) + " (" + kindName(object->kind) + ")");
  item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
  item->setCheckState(kNameColumn, Qt::Checked);
  if (object->kind != SceneObject::Kind::Volume) item->setCheckState(kInterestColumn, Qt::Unchecked);
  {
    const QSignalBlocker block(tree_);  // no itemChanged for the row being built
    tree_->addTopLevelItem(item);
  }
  objects_.push_back(std::move(object));
  emit objectsChanged();  // panels list the new object before it becomes current
  tree_->setCurrentItem(item);
  emit sceneChanged();
  return objects_.back().get();
}

void ObjectList::remove(SceneObject* object) {
  const int row = rowOf(object);
  if (row < 0) return;
  if (object->interest) scene_->SetImportance(object->prop, 0);
  scene_->GetRenderer()->RemoveViewProp(object->prop);
  delete tree_->takeTopLevelItem(row);
  objects_.erase(objects_.begin() + row);
  emit objectsChanged();
  emit sceneChanged();
}

SceneObject* ObjectList::current() const {
  const int row = tree_->indexOfTopLevelItem(tree_->currentItem());
  return row >= 0 && row < count() ? objects_[row].get() : nullptr;
}

void ObjectList::setCurrent(SceneObject* object) {
  if (QTreeWidgetItem* item = itemOf(object)) tree_->setCurrentItem(item);
}

SceneObject* ObjectList::findByName(const QString& name) const {
  for (const auto& object : objects_)
    if (object->name == name) return object.get();
  return nullptr;
}

std::vector<SceneObject*> ObjectList::ofKind(SceneObject::Kind kind) const {
  std::vector<SceneObject*> found;
  for (const auto& object : objects_)
    if (object->kind == kind) found.push_back(object.get());
  return found;
}

int ObjectList::rowOf(const SceneObject* object) const {
  for (int row = 0; row < count(); ++row)
    if (objects_[row].get() == object) return row;
  return -1;
}

QTreeWidgetItem* ObjectList::itemOf(const SceneObject* object) const {
  const int row = rowOf(object);
  return row < 0 ? nullptr : tree_->topLevelItem(row);
}

void ObjectList::onItemChanged(QTreeWidgetItem* item, int column) {
  const int row = tree_->indexOfTopLevelItem(item);
  if (row < 0 || row >= count()) return;
  SceneObject* object = objects_[row].get();
  if (column == kNameColumn) setVisible(object, item->checkState(kNameColumn) == Qt::Checked);
  if (column == kInterestColumn) setInterest(object, item->checkState(kInterestColumn) == Qt::Checked);
}

void ObjectList::setVisible(SceneObject* object, bool visible) {
  object->prop->SetVisibility(visible);
  if (QTreeWidgetItem* item = itemOf(object)) {
    const QSignalBlocker block(tree_);
    item->setCheckState(kNameColumn, visible ? Qt::Checked : Qt::Unchecked);
  }
  emit sceneChanged();
}

void ObjectList::setInterest(SceneObject* object, bool interest) {
  setImportance(object, interest ? 1.0 : 0.0);
}

void ObjectList::setImportance(SceneObject* object, double importance) {
  if (object->kind == SceneObject::Kind::Volume) return;  // the ghost pass cannot use an assembly
  importance = std::clamp(importance, 0.0, 1.0);
  object->interest = importance > 0;
  scene_->SetImportance(object->prop, importance);
  if (QTreeWidgetItem* item = itemOf(object)) {
    const QSignalBlocker block(tree_);
    item->setCheckState(kInterestColumn, object->interest ? Qt::Checked : Qt::Unchecked);
  }
  if (object == current()) {
    const QSignalBlocker block(importance_);
    importance_->setValue(static_cast<int>(std::lround(10 * importance)));
  }
  emit sceneChanged();
}

void ObjectList::setColor(SceneObject* object, double r, double g, double b) {
  if (auto* actor = vtkActor::SafeDownCast(object->prop)) {
    actor->GetProperty()->SetColor(r, g, b);
    emit sceneChanged();
  }
}

void ObjectList::setOpacity(SceneObject* object, double opacity) {
  if (auto* actor = vtkActor::SafeDownCast(object->prop)) {
    actor->GetProperty()->SetOpacity(opacity);
    emit sceneChanged();
  }
}

bool ObjectList::save(SceneObject* object, const QString& path) {
  const QByteArray name = path.toLocal8Bit();
  if (auto* image = vtkImageData::SafeDownCast(object->data)) {
    if (!path.endsWith(".vti", Qt::CaseInsensitive)) {
      fail("Cannot save", path + ": volumes are saved as VTK image data (.vti)");
      return false;
    }
    auto writer = vtkSmartPointer<vtkXMLImageDataWriter>::New();
    writer->SetInputData(image);
    writer->SetFileName(name.constData());
    if (writer->Write() != 1) {
      fail("Cannot save", path + ": cannot write the file");
      return false;
    }
    return true;
  }
  // A centerline for 3D Slicer: its polylines as markups curves.
  const bool markups = path.endsWith(".json", Qt::CaseInsensitive);
  vtkSmartPointer<vtkWriter> writer;
  if (markups) {
    auto curves = vtkSmartPointer<vtkMedialMarkupsCurveWriter>::New();
    curves->SetFileName(name.constData());
    writer = curves;
  } else {
    auto meshes = vtkSmartPointer<vtkMedialPolyDataWriter>::New();
    meshes->SetFileName(name.constData());
    writer = meshes;
  }
  auto errors = medial::ErrorCollector::Watch(writer);
  writer->SetInputData(object->data);
  writer->Write();
  if (errors->HasErrors()) {
    fail("Cannot save", path + ": " + QString::fromStdString(errors->Joined()));
    return false;
  }
  return true;
}

bool ObjectList::exportRig(SceneObject* object, const QString& path, const RigExportSettings& settings) {
  if (!object->skinnedMesh) {
    fail("Cannot export rig", object->name + " has no skinning weights: bind it to a mesh first");
    return false;
  }
  // The skeleton with the Root asked for (the weights do not depend on it).
  auto skeleton = vtkSmartPointer<vtkPolyData>::New();
  skeleton->ShallowCopy(object->polyData());
  if (settings.root >= 0) {
    if (settings.root >= skeleton->GetNumberOfPoints()) {
      fail("Cannot export rig", QString("node %1 is not a node of %2").arg(settings.root).arg(object->name));
      return false;
    }
    auto fields = vtkSmartPointer<vtkFieldData>::New();
    fields->DeepCopy(skeleton->GetFieldData());
    fields->RemoveArray(kRootField);
    auto root = vtkSmartPointer<vtkIntArray>::New();
    root->SetName(kRootField);
    root->InsertNextValue(settings.root);
    fields->AddArray(root);
    skeleton->SetFieldData(fields);
  }
  auto writer = vtkSmartPointer<vtkMedialRigWriter>::New();
  auto errors = medial::ErrorCollector::Watch(writer);
  writer->SetInputData(object->skinnedMesh);
  writer->SetSkeletonData(skeleton);
  const QByteArray name = path.toLocal8Bit(), axis = settings.upAxis.toLatin1();
  writer->SetFileName(name.constData());
  writer->SetUpAxis(axis.constData());
  writer->SetScale(settings.scale);
  writer->Write();
  if (errors->HasErrors()) {
    fail("Cannot export rig", path + ": " + QString::fromStdString(errors->Joined()));
    return false;
  }
  vtkDataArray* root = skeleton->GetFieldData()->GetArray(kRootField);
  emit logged(QString("Exported rig %1: %2 bones and Root at node %3, up axis %4, scale %5")
                  .arg(path)
                  .arg(skeleton->GetNumberOfLines())
                  .arg(root && root->GetNumberOfTuples() ? int(root->GetComponent(0, 0)) : 0)
                  .arg(settings.upAxis)
                  .arg(settings.scale));
  return true;
}

bool ObjectList::bindMesh(SceneObject* skeleton, SceneObject* mesh) {
  auto binding = vtkSmartPointer<vtkMedialSkinBinding>::New();
  auto errors = medial::ErrorCollector::Watch(binding);
  binding->SetInputData(0, mesh->polyData());
  binding->SetSkeletonData(skeleton->polyData());
  QApplication::setOverrideCursor(Qt::WaitCursor);
  binding->Update();
  QApplication::restoreOverrideCursor();
  if (errors->HasErrors()) {
    fail("Cannot bind " + mesh->name,
         mesh->name + " to " + skeleton->name + ": " + QString::fromStdString(errors->Joined()));
    return false;
  }
  skeleton->skinnedMesh = binding->GetOutput(0);
  vtkPolyData* data = skeleton->polyData();
  if (!data->GetFieldData()->GetArray(kRootField))
    data->GetFieldData()->AddArray(binding->GetOutput(1)->GetFieldData()->GetArray(kRootField));
  return true;
}

void ObjectList::showMenu(const QPoint& position) {
  QTreeWidgetItem* item = tree_->itemAt(position);
  if (!item) return;
  tree_->setCurrentItem(item);
  SceneObject* object = current();
  QMenu menu(this);
  QAction* color = menu.addAction("Color...", this, &ObjectList::chooseColor);
  color->setEnabled(object->kind != SceneObject::Kind::Volume);
  menu.addAction("Save As...", this, &ObjectList::saveDialog);
  QAction* rig = menu.addAction("Export Rig...", this, &ObjectList::rigDialog);
  rig->setEnabled(object->skinnedMesh != nullptr ||
                  (object->kind == SceneObject::Kind::Skeleton && !ofKind(SceneObject::Kind::Mesh).empty()));
  menu.addSeparator();
  menu.addAction("Delete", this, [this, object] { remove(object); });
  menu.exec(tree_->viewport()->mapToGlobal(position));
}

void ObjectList::chooseColor() {
  SceneObject* object = current();
  auto* actor = object ? vtkActor::SafeDownCast(object->prop) : nullptr;
  if (!actor) return;
  const double* rgb = actor->GetProperty()->GetColor();
  const QColor chosen =
      QColorDialog::getColor(QColor::fromRgbF(rgb[0], rgb[1], rgb[2]), this, "Color of " + object->name);
  if (chosen.isValid()) setColor(object, chosen.redF(), chosen.greenF(), chosen.blueF());
}

void ObjectList::saveDialog() {
  SceneObject* object = current();
  if (!object) return;
  const bool volume = object->kind == SceneObject::Kind::Volume;
  const QString filter = volume ? QString("VTK image data (*.vti)")
                                : QString("Meshes and skeletons (%1);;3D Slicer markups curves (*.mrk.json)")
                                      .arg(vtkMedialPolyDataWriter::GetExtensions());
  const QString suggested = QFileInfo(object->name).completeBaseName() + (volume ? ".vti" : ".vtp");
  const QString path = QFileDialog::getSaveFileName(this, "Save " + object->name, suggested, filter);
  if (!path.isEmpty()) save(object, path);
}

void ObjectList::rigDialog() {
  SceneObject* object = current();
  if (!object) return;
  if (!object->skinnedMesh) {
    // Any skeleton: bind it to a mesh of the scene first (the only one, or the one the user picks).
    QStringList meshes;
    for (SceneObject* mesh : ofKind(SceneObject::Kind::Mesh)) meshes << mesh->name;
    if (meshes.isEmpty())
      return fail("Cannot export rig", "Open or compute a mesh to bind " + object->name + " to");
    bool chosen = true;
    const QString name = meshes.size() == 1
                             ? meshes.front()
                             : QInputDialog::getItem(this, "Export rig", "Mesh to bind to " + object->name,
                                                     meshes, 0, false, &chosen);
    if (!chosen || !bindMesh(object, findByName(name))) return;
  }
  vtkDataArray* root = object->polyData()->GetFieldData()->GetArray(kRootField);
  RigExportDialog options(int(object->polyData()->GetNumberOfPoints()),
                          root && root->GetNumberOfTuples() ? int(root->GetComponent(0, 0)) : -1, this);
  if (options.exec() != QDialog::Accepted) return;
  const QString path =
      QFileDialog::getSaveFileName(this, "Export rig", QFileInfo(object->name).completeBaseName() + ".glb",
                                   QString("Rigs (%1)").arg(vtkMedialRigWriter::GetExtensions()));
  if (!path.isEmpty()) exportRig(object, path, options.settings());
}

}  // namespace medial::gui
