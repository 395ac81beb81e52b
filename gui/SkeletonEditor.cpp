#include "SkeletonEditor.h"

#include "ObjectList.h"
#include "ViewGeometry.h"

#include "MedialErrorCollector.h"
#include "MedialSkeletonData.h"
#include "MedialSkeletonTubes.h"
#include "skeleton/SkeletonEdits.h"
#include "vtkMedialPolyDataWriter.h"
#include "vtkMedialSQM.h"
#include "vtkMedialScene.h"

#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QPushButton>
#include <QSpinBox>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <cmath>

namespace medial::gui {

namespace {

constexpr double kPickPixels = 12;    // a node or an edge this near the pointer is under it
constexpr double kWheelFactor = 1.1;  // radius change per wheel notch
constexpr int kRadiusStep = 1;        // QUndoCommand id: consecutive radius notches of a node merge

// One edit: the skeleton before and after it. Snapshots keep undo exact whatever the edit did to the ids.
class EditStep : public QUndoCommand {
 public:
  EditStep(SkeletonEditor* editor, Skeleton before, Skeleton after, const QString& what, int node,
           bool radius)
      : QUndoCommand(what),
        editor_(editor),
        before_(std::move(before)),
        after_(std::move(after)),
        node_(node),
        radius_(radius) {}
  void undo() override { editor_->setSkeleton(before_); }
  void redo() override { editor_->setSkeleton(after_); }
  int id() const override { return radius_ ? kRadiusStep : -1; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* step = static_cast<const EditStep*>(other);
    if (step->node_ != node_) return false;
    after_ = step->after_;
    return true;
  }

 private:
  SkeletonEditor* editor_;
  Skeleton before_, after_;
  int node_;
  bool radius_;
};

// Points, lines and a drawn radius (scale x Radius) of `nodes` of the skeleton.
void fillShown(vtkPolyData* shown, const Skeleton& s, const std::vector<int>& nodes, double scale,
               bool lines) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto radius = vtkSmartPointer<vtkDoubleArray>::New();
  radius->SetName("DrawRadius");
  for (int node : nodes) {
    points->InsertNextPoint(s.nodes[size_t(node)].data());
    radius->InsertNextValue(scale * (s.radii.empty() ? 1.0 : s.radii[size_t(node)]));
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  if (lines)
    for (const auto& e : s.edges) {
      const vtkIdType ids[2] = {e[0], e[1]};
      cells->InsertNextCell(2, ids);
    }
  shown->Initialize();
  shown->SetPoints(points);
  shown->SetLines(cells);
  shown->GetPointData()->SetScalars(radius);
}

}  // namespace

SkeletonEditor::SkeletonEditor(ObjectList* objects, vtkMedialScene* scene, VtkView* view, QWidget* parent)
    : QWidget(parent), objects_(objects), scene_(scene), view_(view), undo_(new QUndoStack(this)) {
  setObjectName("skeletonEditor");
  choice_ = new QComboBox(this);
  edit_ = new QCheckBox("Edit in the 3-D view", this);
  edit_->setObjectName("editSkeleton");
  levels_ = new QSpinBox(this);
  levels_->setRange(0, 3);
  levels_->setValue(1);
  levels_->setToolTip("Subdivision levels of the live SQM mesh (the fold repair runs when a drag ends)");
  auto* form = new QFormLayout;
  form->addRow("Skeleton", choice_);
  form->addRow("Mesh levels", levels_);
  auto* undo = new QPushButton("Undo", this);
  auto* redo = new QPushButton("Redo", this);
  auto* remove = new QPushButton("Delete node", this);
  auto* root = new QPushButton("Set root", this);
  auto* saveButton = new QPushButton("Save...", this);
  saveButton->setToolTip("Save the edited skeleton (VTP keeps radii and root; SWC for neuron tools)");
  auto* done = new QPushButton("Done", this);
  done->setToolTip("Add the edited skeleton and its mesh to the objects (save or rig them from there)");
  // Three buttons a row: six in one row made the panel wider than the Filters dock at 1024x768.
  auto* buttons = new QGridLayout;
  QPushButton* const order[] = {undo, redo, remove, root, saveButton, done};
  for (int i = 0; i < 6; ++i) buttons->addWidget(order[i], i / 3, i % 3);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  auto* help = new QLabel(
      "Drag a node to move it; Shift+drag from a node: new branch; Ctrl+click an edge: new node; wheel "
      "over a node: radius; Delete: remove the selected node. Elsewhere the mouse turns the camera.",
      this);
  help->setWordWrap(true);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(edit_);
  layout->addLayout(buttons);
  layout->addWidget(status_);
  layout->addWidget(help);
  layout->addStretch();

  connect(objects_, &ObjectList::objectsChanged, this, &SkeletonEditor::refreshChoices);
  connect(edit_, &QCheckBox::toggled, this, [this](bool on) {
    if (on && !editing_ && !begin(objects_->findByName(choice_->currentText()))) edit_->setChecked(false);
    if (!on && editing_) finish();
  });
  connect(levels_, &QSpinBox::valueChanged, this, [this] {
    if (editing_) rebuild(true);
  });
  connect(undo, &QPushButton::clicked, undo_, &QUndoStack::undo);
  connect(redo, &QPushButton::clicked, undo_, &QUndoStack::redo);
  connect(remove, &QPushButton::clicked, this, [this] {
    QKeyEvent del(QEvent::KeyPress, Qt::Key_Delete, Qt::NoModifier);
    keyPress(&del);
  });
  connect(root, &QPushButton::clicked, this, [this] {
    if (!editing_ || selected_ < 0) return;
    const Skeleton before = skeleton_;
    setRoot(skeleton_, selected_);
    commit(before, "Set root");
  });
  connect(done, &QPushButton::clicked, this, [this] { edit_->setChecked(false); });
  connect(saveButton, &QPushButton::clicked, this, [this] {
    if (!editing_) return;
    const QString path = QFileDialog::getSaveFileName(this, "Save skeleton", sourceName_ + " edited.vtp",
                                                      "Skeletons (*.vtp *.swc)");
    if (!path.isEmpty()) save(path);
  });

  skeletonShown_ = vtkSmartPointer<vtkPolyData>::New();
  selectionShown_ = vtkSmartPointer<vtkPolyData>::New();
  meshShown_ = vtkSmartPointer<vtkPolyData>::New();
  skeletonActor_ = skeletonTubesActor(skeletonShown_, 16);
  skeletonActor_->GetProperty()->SetColor(0.85, 0.3, 0.25);
  selectionActor_ = skeletonTubesActor(selectionShown_, 16);
  selectionActor_->GetProperty()->SetColor(1.0, 0.85, 0.1);
  auto meshMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  meshMapper->SetInputData(meshShown_);
  meshMapper->ScalarVisibilityOff();
  meshActor_ = vtkSmartPointer<vtkActor>::New();
  meshActor_->SetMapper(meshMapper);
  meshActor_->GetProperty()->SetColor(0.9, 0.85, 0.7);
  meshActor_->GetProperty()->SetOpacity(0.4);
  refreshChoices();
}

SkeletonEditor::~SkeletonEditor() {
  if (view_) view_->setInteraction(nullptr);
}

vtkPolyData* SkeletonEditor::mesh() const { return meshShown_; }

void SkeletonEditor::refreshChoices() {
  const QString current = editing_ ? sourceName_ : choice_->currentText();
  choice_->clear();
  for (SceneObject* object : objects_->ofKind(SceneObject::Kind::Skeleton)) choice_->addItem(object->name);
  const int index = choice_->findText(current);
  if (index >= 0) choice_->setCurrentIndex(index);
  if (editing_ && !objects_->findByName(sourceName_)) source_ = nullptr;  // deleted while edited
}

bool SkeletonEditor::begin(SceneObject* skeleton) {
  if (!skeleton || skeleton->kind != SceneObject::Kind::Skeleton) {
    emit failed("Cannot edit", "Open or compute a skeleton to edit first");
    return false;
  }
  Skeleton loaded;
  std::string error;
  if (!skeletonFromPolyData(skeleton->polyData(), loaded, error)) {
    emit failed("Cannot edit " + skeleton->name, QString::fromStdString(error));
    return false;
  }
  ensureRadii(loaded);
  source_ = skeleton;
  sourceName_ = skeleton->name;
  choice_->setCurrentText(skeleton->name);
  editing_ = true;
  undo_->clear();
  selected_ = -1;
  objects_->setVisible(skeleton, false);
  vtkRenderer* renderer = scene_->GetRenderer();
  renderer->AddActor(meshActor_);
  renderer->AddActor(skeletonActor_);
  renderer->AddActor(selectionActor_);
  view_->setInteraction(this);
  edit_->setChecked(true);
  setSkeleton(loaded);
  emit message(QString("Editing %1: %2 nodes").arg(sourceName_).arg(skeleton_.nodeCount()));
  return true;
}

void SkeletonEditor::finish() {
  if (!editing_) return;
  editing_ = false;
  view_->setInteraction(nullptr);
  vtkRenderer* renderer = scene_->GetRenderer();
  renderer->RemoveActor(meshActor_);
  renderer->RemoveActor(skeletonActor_);
  renderer->RemoveActor(selectionActor_);
  if (source_) objects_->setVisible(source_, true);
  const QString name = sourceName_ + " edited";
  for (const QString& stale : {name, name + " SQM"})
    if (SceneObject* previous = objects_->findByName(stale)) objects_->remove(previous);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(meshShown_);
  if (mesh->GetNumberOfPolys() > 0)
    if (SceneObject* m = objects_->add(name + " SQM", mesh)) objects_->setOpacity(m, 0.5);
  objects_->add(name, polyDataFromSkeleton(skeleton_), QString(), kComputedRadiusScale);
  edit_->setChecked(false);
  emit message(QString("Skeleton editor: %1 and its SQM mesh added").arg(name));
  emit sceneChanged();
}

void SkeletonEditor::setSkeleton(const Skeleton& skeleton) {
  skeleton_ = skeleton;
  if (selected_ >= skeleton_.nodeCount()) selected_ = -1;
  rebuild(true);
}

void SkeletonEditor::selectNode(int node) {
  selected_ = node >= 0 && node < skeleton_.nodeCount() ? node : -1;
  showSelection();
  emit sceneChanged();
}

void SkeletonEditor::showSelection() {
  std::vector<int> nodes;
  if (selected_ >= 0) nodes.push_back(selected_);
  fillShown(selectionShown_, skeleton_, nodes, kComputedRadiusScale * 1.5, false);
  selectionShown_->Modified();
  QString text = QString("%1 nodes, %2 edges; mesh %3 ms")
                     .arg(skeleton_.nodeCount())
                     .arg(skeleton_.edgeCount())
                     .arg(meshMilliseconds_, 0, 'f', 1);
  if (selected_ >= 0)
    text += QString("; node %1, radius %2")
                .arg(selected_)
                .arg(skeleton_.radii.empty() ? 0.0 : skeleton_.radii[size_t(selected_)], 0, 'g', 4);
  status_->setText(text);
}

void SkeletonEditor::rebuild(bool final) {
  std::vector<int> all(size_t(skeleton_.nodeCount()));
  for (int i = 0; i < skeleton_.nodeCount(); ++i) all[size_t(i)] = i;
  fillShown(skeletonShown_, skeleton_, all, kComputedRadiusScale, true);
  skeletonShown_->Modified();

  QElapsedTimer clock;
  clock.start();
  auto sqm = vtkSmartPointer<vtkMedialSQM>::New();
  auto errors = ErrorCollector::Watch(sqm);
  sqm->SetInputData(polyDataFromSkeleton(skeleton_));
  sqm->SetSubdivisionLevels(levels_->value());
  sqm->SetFoldRepair(final);
  sqm->Update();
  meshMilliseconds_ = double(clock.nsecsElapsed()) / 1e6;
  if (errors->HasErrors()) {
    // Mid-drag a node can pass through another: keep the last mesh and say why.
    status_->setText("SQM: " + QString::fromStdString(errors->Joined()));
  } else {
    meshShown_->ShallowCopy(sqm->GetOutput());
    meshShown_->Modified();
  }
  showSelection();
  if (errors->HasErrors()) status_->setText("SQM: " + QString::fromStdString(errors->Joined()));
  emit sceneChanged();
}

void SkeletonEditor::commit(const Skeleton& before, const QString& what) {
  undo_->push(new EditStep(this, before, skeleton_, what, selected_, false));
}

int SkeletonEditor::nodeAt(const QPointF& position) const {
  int best = -1;
  double bestDistance = kPickPixels;
  for (int i = 0; i < skeleton_.nodeCount(); ++i) {
    const QPointF at = widgetPosition(scene_->GetRenderer(), view_, skeleton_.nodes[size_t(i)]);
    const double d = std::hypot(at.x() - position.x(), at.y() - position.y());
    if (d < bestDistance) bestDistance = d, best = i;
  }
  return best;
}

bool SkeletonEditor::mousePress(QMouseEvent* event) {
  if (!editing_ || event->button() != Qt::LeftButton) return false;
  const int node = nodeAt(event->position());
  if (node < 0 && (event->modifiers() & Qt::ControlModifier)) {
    // Ctrl+click on an edge: a new node there.
    Eigen::Vector3d nearPoint, farPoint;
    if (!pointerRay(scene_->GetRenderer(), view_, event->position(), nearPoint, farPoint)) return false;
    const EdgeNearRay hit = nearestEdgeToRay(skeleton_, nearPoint, farPoint - nearPoint);
    if (hit.edge < 0) return false;
    const auto [a, b] = skeleton_.edges[size_t(hit.edge)];
    const Eigen::Vector3d onEdge =
        (1 - hit.t) * skeleton_.nodes[size_t(a)] + hit.t * skeleton_.nodes[size_t(b)];
    const QPointF shown = widgetPosition(scene_->GetRenderer(), view_, onEdge);
    if (std::hypot(shown.x() - event->position().x(), shown.y() - event->position().y()) > kPickPixels)
      return false;
    const Skeleton before = skeleton_;
    selected_ = splitEdge(skeleton_, hit.edge, hit.t);
    commit(before, "Add node");
    return true;
  }
  if (node < 0) return false;  // the camera turns
  beforeDrag_ = skeleton_;
  selected_ = node;
  dragged_ = node;
  dragWhat_ = "Move node";
  if (event->modifiers() & Qt::ShiftModifier) {  // a new branch: its leaf follows the pointer
    dragged_ = selected_ = addBranch(skeleton_, node, skeleton_.nodes[size_t(node)]);
    dragWhat_ = "Add branch";
  }
  dragOrigin_ = skeleton_.nodes[size_t(dragged_)];
  showSelection();
  emit sceneChanged();
  return true;
}

bool SkeletonEditor::mouseMove(QMouseEvent* event) {
  if (!editing_ || dragged_ < 0) return false;
  double direction[3];
  scene_->GetRenderer()->GetActiveCamera()->GetDirectionOfProjection(direction);
  Eigen::Vector3d point;
  if (viewPlanePoint(scene_->GetRenderer(), view_, event->position(), dragOrigin_, Eigen::Vector3d(direction),
                     point)) {
    moveNode(skeleton_, dragged_, point);
    rebuild(false);
  }
  return true;
}

bool SkeletonEditor::mouseRelease(QMouseEvent* event) {
  if (!editing_ || dragged_ < 0 || event->button() != Qt::LeftButton) return false;
  dragged_ = -1;
  if (dragWhat_ == "Add branch" || skeleton_.nodes != beforeDrag_.nodes) {
    commit(beforeDrag_, dragWhat_);  // its redo rebuilds with the fold repair
  } else {
    showSelection();  // a click: the node is selected
    emit sceneChanged();
  }
  return true;
}

bool SkeletonEditor::wheel(QWheelEvent* event) {
  if (!editing_) return false;
  const int node = nodeAt(event->position());
  if (node < 0 || event->angleDelta().y() == 0) return false;  // the camera zooms
  selected_ = node;
  const Skeleton before = skeleton_;
  const double factor = event->angleDelta().y() > 0 ? kWheelFactor : 1 / kWheelFactor;
  setNodeRadius(skeleton_, node, (skeleton_.radii.empty() ? 1.0 : skeleton_.radii[size_t(node)]) * factor);
  undo_->push(new EditStep(this, before, skeleton_, "Change radius", node, true));
  return true;
}

bool SkeletonEditor::keyPress(QKeyEvent* event) {
  if (!editing_ || (event->key() != Qt::Key_Delete && event->key() != Qt::Key_Backspace)) return false;
  if (selected_ < 0) return true;
  const Skeleton before = skeleton_;
  deleteNode(skeleton_, selected_);
  selected_ = -1;
  commit(before, "Delete node");
  return true;
}

bool SkeletonEditor::save(const QString& path) {
  auto writer = vtkSmartPointer<vtkMedialPolyDataWriter>::New();
  auto errors = ErrorCollector::Watch(writer);
  writer->SetInputData(polyDataFromSkeleton(skeleton_));
  const QByteArray name = path.toLocal8Bit();
  writer->SetFileName(name.constData());
  writer->Write();
  if (errors->HasErrors()) {
    emit failed("Cannot save", path + ": " + QString::fromStdString(errors->Joined()));
    return false;
  }
  return true;
}

}  // namespace medial::gui
