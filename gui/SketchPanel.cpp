#include "SketchPanel.h"

#include "FilterDefaults.h"
#include "ObjectList.h"
#include "vtkMedialSketchSkeleton.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>
#include <QSlider>
#include <QVBoxLayout>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkPoints.h>
#include <vtkProperty.h>

namespace medial::gui {

namespace {

constexpr const char* kDrawnSketch = "drawn sketch";

std::vector<Parameter> sketchParameters() {
  const auto f = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
  return {
      MEDIAL_REAL_PARAMETER(
          f, Thickness, "Thickness", 2,
          "Height parameter c of the inflation (§4.1: Poisson equation, Dirichlet boundary); "
          "scales the thickness"),
      MEDIAL_TOGGLE_PARAMETER(f, Inflate, "Inflated mesh",
                              "Also build the inflated mesh of every stroke (§4.1)"),
      MEDIAL_TOGGLE_PARAMETER(f, MergeParts, "One watertight mesh",
                              "Join the inflated strokes into one closed mesh, the union of their volumes "
                              "(off: one overlapping mesh per stroke)"),
  };
}

// The four thresholds of §3.3 as sliders: their defaults are the filter's (globalDefaults); the sliders'
// ends are the GUI's choice, ten times the paper's default.
struct Threshold {
  const char* name;
  const char* label;
  int maximum;
  const char* tooltip;
};

constexpr Threshold kThresholds[4] = {
    {"Simplification", "ε_s simplify", 50,
     "Branch simplification ε_s of BoundedDP, Algorithms 1-2 (§3.1; default 5 px)"},
    {"Merging", "ε_m merge", 300, "Joint merging ε_m (§3.3; default 30 px)"},
    {"Pruning", "ε_t prune", 300, "Branch pruning ε_t (§3.3; default 30 px)"},
    {"Collapsing", "ε_c collapse", 100, "Edge collapsing ε_c (§3.3; default 10 px)"},
};

std::array<double, 4> globalDefaults() {
  const auto f = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
  return {f->GetSimplificationThreshold(), f->GetMergingThreshold(), f->GetPruningThreshold(),
          f->GetCollapsingThreshold()};
}

}  // namespace

SketchPanel::SketchPanel(ObjectList* objects, QWidget* parent)
    : FilterPanel("Sketch", SceneObject::Kind::Sketch, sketchParameters(), objects, parent),
      global_(globalDefaults()) {
  auto* rows = new QFormLayout;
  rows->setRowWrapPolicy(QFormLayout::WrapLongRows);
  scope_ = new QComboBox(this);
  scope_->setObjectName("thresholdScope");
  scope_->setToolTip(
      "Multi-level control (§3.3): the sliders set the global thresholds, those of one part, or\n"
      "ε_s of one branch (click a bone of the sketch's skeleton in the 3-D view)");
  rows->addRow("Thresholds of", scope_);
  connect(scope_, &QComboBox::currentIndexChanged, this, &SketchPanel::showScope);
  for (int i = 0; i < 4; ++i) {
    auto* slider = new QSlider(Qt::Horizontal, this);
    slider->setObjectName(kThresholds[i].name);
    slider->setRange(0, kThresholds[i].maximum);
    slider->setValue(static_cast<int>(global_[size_t(i)]));
    slider->setToolTip(kThresholds[i].tooltip);
    auto* value = new QLabel(QString::number(slider->value()), this);
    value->setMinimumWidth(28);
    connect(slider, &QSlider::valueChanged, value, [value](int v) { value->setNum(v); });
    connect(slider, &QSlider::valueChanged, this, &SketchPanel::parameterChanged);
    auto* row = new QHBoxLayout;
    row->addWidget(slider, 1);
    row->addWidget(value);
    rows->addRow(kThresholds[i].label, row);
    thresholds_[i] = slider;
    values_[i] = value;
  }
  live_ = new QCheckBox("Update live", this);
  live_->setChecked(true);
  draw_ = new QCheckBox("Draw strokes in the 3-D view", this);
  draw_->setObjectName("draw");
  draw_->setToolTip(
      "Left-drag draws a closed stroke on the plane facing you through the focal point; each\n"
      "stroke is a new part (rotate the view between strokes to draw parts in other planes).\n"
      "Turn off to rotate the view again.");
  rows->addRow(live_);
  rows->addRow(draw_);
  // Part modelling: the part chosen in "Thresholds of".
  auto* partTools = new QGridLayout;
  const auto tool = [this, partTools](const QString& text, const QString& tip, int row, int column,
                                      const std::function<void(int)>& action) {
    auto* button = new QToolButton(this);  // tool buttons: four push buttons a row overflowed the dock
    button->setText(text);
    button->setToolTip(tip);
    button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    connect(button, &QToolButton::clicked, this, [this, action] {
      if (scopePart() >= 0) action(scopePart());
    });
    partTools->addWidget(button, row, column);
  };
  tool("←", "Move the part left in its plane", 0, 0, [this](int k) { movePart(k, -1, 0); });
  tool("→", "Move the part right in its plane", 0, 1, [this](int k) { movePart(k, 1, 0); });
  tool("↑", "Move the part up in its plane", 0, 2, [this](int k) { movePart(k, 0, 1); });
  tool("↓", "Move the part down in its plane", 0, 3, [this](int k) { movePart(k, 0, -1); });
  tool("⟲ 15°", "Turn the part about its center", 1, 0, [this](int k) { turnPart(k, 1); });
  tool("⟳ 15°", "Turn the part the other way", 1, 1, [this](int k) { turnPart(k, -1); });
  tool("+10 %", "Grow the part about its center", 1, 2, [this](int k) { scalePart(k, 1); });
  tool("−10 %", "Shrink the part", 1, 3, [this](int k) { scalePart(k, -1); });
  tool("Mirror", "Add the part mirrored across part 1's drawing plane (draw one half, get both)", 2, 0,
       [this](int k) { mirrorPart(k); });
  rows->addRow("Part (choose above)", partTools);
  auto* exportButton = new QPushButton("Export character...", this);
  exportButton->setToolTip("Bind the sketch's mesh to its skeleton (heat weights) and write the rig");
  connect(exportButton, &QPushButton::clicked, this, [this] {
    if (!input()) return;
    const QString path =
        QFileDialog::getSaveFileName(this, "Export character", input()->name + ".glb", "Rigs (*.glb *.fbx)");
    if (!path.isEmpty()) exportCharacter(path);
  });
  rows->addRow(exportButton);
  extraLayout()->addLayout(rows);
  enableSteps(
      "Keep the skeleton after each step: straight skeleton, BoundedDP, connection, pruning, merging");
  connect(form(), &ParameterForm::valueChanged, this, &SketchPanel::parameterChanged);
  connect(draw_, &QCheckBox::toggled, this, &SketchPanel::drawingToggled);
}

bool SketchPanel::isDrawing() const { return draw_->isChecked(); }
void SketchPanel::setDrawing(bool on) { draw_->setChecked(on); }

void SketchPanel::parameterChanged() {
  const QPoint scope = scope_->currentData().toPoint();  // (part, branch); part -1: all parts
  const Thresholds values = {double(thresholds_[0]->value()), double(thresholds_[1]->value()),
                             double(thresholds_[2]->value()), double(thresholds_[3]->value())};
  if (scope.y() >= 0)
    branchSimplification_[{scope.x(), scope.y()}] = values[0];  // branch level: epsilon_s only
  else if (scope.x() < 0)
    global_ = values;
  else
    partThresholds_[scope.x()] = values;
  if (live_->isChecked() && input() && objects()->findByName(input()->name + " skeleton")) runAgain();
}

void SketchPanel::inputChanged(SceneObject* input) {
  // A new sketch: one scope entry per part; part-level thresholds belong to the previous sketch.
  // (The drawn sketch is rebuilt with each stroke under the same name: its parts keep their thresholds.)
  if (input->name != scopeName_) partThresholds_.clear(), branchSimplification_.clear();
  scopeName_ = input->name;
  const QSignalBlocker block(scope_);
  scope_->clear();
  scope_->addItem("all parts", QPoint(-1, -1));
  for (vtkIdType k = 0; k < input->polyData()->GetNumberOfLines(); ++k)
    scope_->addItem(QString("part %1").arg(k + 1), QPoint(int(k), -1));
  showScope(0);
}

void SketchPanel::setThresholdScope(int part) { scope_->setCurrentIndex(part + 1); }

void SketchPanel::selectBranch(int part, int branch) {
  // One entry at the end of the scope list for the branch last picked (branch level: epsilon_s only).
  const int last = scope_->count() - 1;
  if (last > 0 && scope_->itemData(last).toPoint().y() >= 0) scope_->removeItem(last);
  scope_->addItem(QString("part %1, branch %2 (ε_s)").arg(part + 1).arg(branch), QPoint(part, branch));
  scope_->setCurrentIndex(scope_->count() - 1);
}

void SketchPanel::showScope(int index) {
  // The sliders show the chosen scope's values without re-running; a branch scope sets epsilon_s only.
  const QPoint scope = scope_->itemData(index).toPoint();
  const auto custom = partThresholds_.find(scope.x());
  Thresholds values = scope.x() >= 0 && custom != partThresholds_.end() ? custom->second : global_;
  const auto branch = branchSimplification_.find({scope.x(), scope.y()});
  if (scope.y() >= 0 && branch != branchSimplification_.end()) values[0] = branch->second;
  for (int i = 0; i < 4; ++i) {
    const QSignalBlocker block(thresholds_[i]);
    thresholds_[i]->setValue(int(values[size_t(i)]));
    thresholds_[i]->setEnabled(i == 0 || scope.y() < 0);
  }
  for (int i = 0; i < 4; ++i) values_[i]->setNum(thresholds_[i]->value());
}

bool SketchPanel::addStroke(const QVector<QPointF>& points, const Placement& placement) {
  if (points.size() < 3) return false;
  // The drawn sketch is rebuilt with one more closed polyline (its first point repeated at the end) and
  // its `Placement`.
  auto sketch = vtkSmartPointer<vtkPolyData>::New();
  auto coordinates = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto placements = vtkSmartPointer<vtkDoubleArray>::New();
  placements->SetName("Placement");
  placements->SetNumberOfComponents(16);
  SceneObject* previous = objects()->findByName(kDrawnSketch);
  if (previous) {
    coordinates->DeepCopy(previous->polyData()->GetPoints());
    lines->DeepCopy(previous->polyData()->GetLines());
    placements->DeepCopy(previous->polyData()->GetCellData()->GetArray("Placement"));
  }
  const vtkIdType first = coordinates->GetNumberOfPoints();
  lines->InsertNextCell(points.size() + 1);
  for (const QPointF& p : points) lines->InsertCellPoint(coordinates->InsertNextPoint(p.x(), p.y(), 0.0));
  lines->InsertCellPoint(first);
  placements->InsertNextTuple(placement.data());
  sketch->SetPoints(coordinates);
  sketch->SetLines(lines);
  sketch->GetCellData()->AddArray(placements);

  if (previous) objects()->remove(previous);
  SceneObject* object = objects()->add(kDrawnSketch, sketch);
  if (!object) return false;
  setInput(object);
  if (live_->isChecked()) runAgain();
  return true;
}

int SketchPanel::scopePart() const { return scope_->currentData().toPoint().x(); }

bool SketchPanel::editSketch(const std::function<bool(vtkPolyData*)>& edit) {
  SceneObject* sketch = input();
  if (!sketch || !isSketch(sketch->polyData())) return false;
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(sketch->polyData());
  if (!edit(copy)) return false;
  const QString name = sketch->name, path = sketch->path;
  const int scope = scope_->currentIndex();
  objects()->remove(sketch);
  SceneObject* replaced = objects()->add(name, copy, path);
  if (!replaced) return false;
  setInput(replaced);
  scope_->setCurrentIndex(std::min(scope, scope_->count() - 1));
  if (live_->isChecked()) runAgain();
  return true;
}

bool SketchPanel::movePart(int part, double alongU, double alongV) {
  return editSketch([&](vtkPolyData* sketch) {
    if (part < 0 || part >= sketch->GetNumberOfLines()) return false;
    double m[16];
    sketch->GetCellData()->GetArray("Placement")->GetTuple(part, m);
    const double step = 0.02 * sketchSize(sketch);
    std::array<double, 3> offset;
    for (int c = 0; c < 3; ++c) offset[size_t(c)] = step * (alongU * m[4 * c] + alongV * m[4 * c + 1]);
    return medial::movePart(sketch, part, offset);
  });
}

bool SketchPanel::turnPart(int part, double steps) {
  return editSketch([&](vtkPolyData* sketch) { return medial::turnPart(sketch, part, 15 * steps); });
}

bool SketchPanel::scalePart(int part, double steps) {
  return editSketch(
      [&](vtkPolyData* sketch) { return medial::scalePart(sketch, part, std::pow(1.1, steps)); });
}

bool SketchPanel::mirrorPart(int part) {
  return editSketch([&](vtkPolyData* sketch) { return medial::mirrorPart(sketch, part, 0) >= 0; });
}

bool SketchPanel::exportCharacter(const QString& path) {
  SceneObject* skeleton = input() ? objects()->findByName(input()->name + " skeleton") : nullptr;
  SceneObject* mesh = input() ? objects()->findByName(input()->name + " mesh") : nullptr;
  if (!skeleton || !mesh) {
    emit failed("Cannot export character", "Run the sketch with \"Inflated mesh\" on first");
    return false;
  }
  return objects()->bindMesh(skeleton, mesh) && objects()->exportRig(skeleton, path);
}

vtkSmartPointer<vtkAlgorithm> SketchPanel::makeFilter(SceneObject* input, QString&) {
  auto filter = vtkSmartPointer<vtkMedialSketchSkeleton>::New();
  filter->SetInputData(copyOf(input));
  filter->SetSimplificationThreshold(global_[0]);
  filter->SetMergingThreshold(global_[1]);
  filter->SetPruningThreshold(global_[2]);
  filter->SetCollapsingThreshold(global_[3]);
  for (const auto& [part, t] : partThresholds_) filter->SetPartThresholds(part, t[0], t[1], t[2], t[3]);
  for (const auto& [key, epsilon] : branchSimplification_)
    filter->SetBranchSimplification(key.first, key.second, epsilon);
  filter->SetThickness(form()->value("Thickness"));
  filter->SetInflate(form()->isOn("Inflate"));
  filter->SetMergeParts(form()->isOn("MergeParts"));
  filter->SetRecordStages(recordSteps());
  return filter;
}

FilterPanel::Steps SketchPanel::steps(vtkAlgorithm* filter) {
  auto* sketch = static_cast<vtkMedialSketchSkeleton*>(filter);
  Steps steps;
  for (const std::string& name : vtkMedialSketchSkeleton::GetStageSkeletonNames())
    if (vtkPolyData* stage = sketch->GetStageSkeleton(name))
      steps.emplace_back(QString::fromStdString(name), stage);
  return steps;
}

void SketchPanel::collect(vtkAlgorithm* filter, SceneObject* input, double seconds) {
  auto* sketch = static_cast<vtkMedialSketchSkeleton*>(filter);
  auto skeleton = vtkSmartPointer<vtkPolyData>::New();
  skeleton->ShallowCopy(sketch->GetOutput(0));
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(sketch->GetOutput(1));
  for (const QString suffix : {" skeleton", " mesh"})
    if (SceneObject* previous = objects()->findByName(input->name + suffix)) objects()->remove(previous);
  if (mesh->GetNumberOfPoints() > 0)
    if (SceneObject* m = objects()->add(input->name + " mesh", mesh)) objects()->setOpacity(m, 0.5);
  if (SceneObject* s = objects()->add(input->name + " skeleton", skeleton, QString(), kComputedRadiusScale))
    objects()->setInterest(s, true);
  emit message(QString("Sketch: %1 nodes, %2 bones in %3 ms")
                   .arg(skeleton->GetNumberOfPoints())
                   .arg(skeleton->GetNumberOfLines())
                   .arg(seconds * 1000, 0, 'f', 1));
}

}  // namespace medial::gui
