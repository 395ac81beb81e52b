#include "CenterlinePanel.h"

#include "FilterDefaults.h"
#include "ObjectList.h"
#include "MedialTerrainImage.h"
#include "ProfileChart.h"
#include "TerrainView.h"
#include "vtkMedialTskCenterline.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkLookupTable.h>
#include <vtkMapper.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkTable.h>

#include <algorithm>
#include <cmath>

namespace medial::gui {

namespace {

// Border-part rules in the order of vtkMedialTskCenterline's BORDER_PARTS_* values.
const char* const kBorderParts = "automatic, drop, keep";

std::vector<Parameter> centerlineParameters() {
  using P = Parameter;
  const auto f = vtkSmartPointer<vtkMedialTskCenterline>::New();
  const char* border[] = {"automatic", "drop", "keep"};
  return {
      choiceOf(
          "Selection", "Structure", "label, threshold, non-zero, automatic", f->GetSelectionName(),
          "Which voxels form the tube: one label, an intensity window (e.g. colon air), all non-zero, or "
          "chosen from the volume (the default: a CT's air in the window, else the non-zero voxels)"),
      P::integer("Label", "Label", f->GetLabel(), -1000000, 1000000,
                 "Voxel value of the structure (label images)"),
      P::real("ThresholdLow", "Threshold low", f->GetThresholdLow(), -1e6, 1e6, 1,
              "Lower end of the window (HU for CT)"),
      P::real("ThresholdHigh", "Threshold high", f->GetThresholdHigh(), -1e6, 1e6, 1,
              "Upper end of the window (colon air: -600 HU)"),
      choiceOf("BorderParts", "Border parts", kBorderParts, border[f->GetBorderParts()],
               "Parts touching the volume border: automatic drops them for a threshold (the air outside the "
               "body) and keeps them otherwise"),
      MEDIAL_TOGGLE_PARAMETER(f, FillHoles, "Fill holes",
                              "Fill cavities of the structure before the distance field"),
      MEDIAL_REAL_PARAMETER(
          f, MaxGap, "Max gap (mm)", 1,
          "Parts of the structure (a colon split by collapsed or fluid-filled segments) are "
          "joined across gaps up to this long, bridged through the CT; 0: the largest part only"),
      MEDIAL_REAL_PARAMETER(f, MinimumPartVolume, "Min part volume (mm³)", 0,
                            "Smaller parts of the structure are left out (noise, small-bowel gas)"),
      MEDIAL_REAL_PARAMETER(
          f, AntecedentWidth, "Antecedent width", 3,
          "Width of the TSK antecedent Gaussians relative to their cluster (§3, default 0.3)"),
      MEDIAL_TOGGLE_PARAMETER(
          f, DetectBranches, "Branching structure",
          "Vessels, airways: one centerline per branch, joined at the junctions (beyond the paper)"),
      MEDIAL_INTEGER_PARAMETER(
          f, CenteringIterations, "Centering passes",
          "Moves the TSK curve to the center of its perpendicular sections (centricity, §2); "
          "0: the paper's curve"),
      MEDIAL_REAL_PARAMETER(f, SampleSpacing, "Output spacing (mm)", 2,
                            "Distance between output points; 0: smallest voxel"),
      MEDIAL_REAL_PARAMETER(
          f, SectionSpacing, "Section spacing k (mm)", 2,
          "Perpendicular sections every k mm for the profile and the unfolded wall (§4, Figs. 14-15)"),
      // On here (the filter's default is off): the fly-through and the ghost view need the lumen's wall.
      P::toggle("ComputeSurface", "Lumen surface", true,
                "The closed surface of the followed lumen (smoothed, at most SurfaceTriangles triangles) as "
                "an object of its own: the wall the fly-through flies inside"),
  };
}

}  // namespace

CenterlinePanel::CenterlinePanel(ObjectList* objects, QWidget* parent)
    : FilterPanel("Centerline", SceneObject::Kind::Volume, centerlineParameters(), objects, parent) {
  seedLabel_ = new QLabel(this);
  seedLabel_->setObjectName("seed");
  seedLabel_->setWordWrap(true);  // the seed's coordinates must not widen the dock
  auto* clear = new QPushButton("Clear seed", this);
  connect(clear, &QPushButton::clicked, this, &CenterlinePanel::clearSeed);
  auto* seedRow = new QHBoxLayout;
  seedRow->addWidget(seedLabel_, 1);
  seedRow->addWidget(clear);
  extraLayout()->addLayout(seedRow);
  enableSteps(
      "Keep the structure's voxels (Manhattan layers, clusters), the primitive centerline and the "
      "TSK curve before centering (the paper's Figs. 3-10)");
  clearSeed();

  profile_ = new ProfileChart(this);
  extraLayout()->addWidget(profile_);
  terrain_ = new TerrainView(this);
  extraLayout()->addWidget(new QLabel("Unfolded wall", this));
  extraLayout()->addWidget(terrain_);
  connect(profile_, &ProfileChart::clicked, this, &CenterlinePanel::setPosition);
  connect(terrain_, &TerrainView::clicked, this, &CenterlinePanel::setPosition);
  buildFlyControls();
  connect(playButton_, &QPushButton::toggled, this, &CenterlinePanel::play);
  connect(positionSlider_, &QSlider::valueChanged, this, [this](int value) {
    if (!fly_.empty()) setPosition(fly_.length() * value / 1000.0);
  });
  timer_.setInterval(40);
  connect(&timer_, &QTimer::timeout, this, &CenterlinePanel::step);
}

void CenterlinePanel::buildFlyControls() {
  positionSlider_ = new QSlider(Qt::Horizontal, this);
  positionSlider_->setObjectName("flyPosition");
  positionSlider_->setRange(0, 1000);
  positionSlider_->setToolTip("Camera position along the centerline");
  playButton_ = new QPushButton("Play", this);
  playButton_->setObjectName("play");
  playButton_->setCheckable(true);
  backward_ = new QCheckBox("Backward", this);
  backward_->setObjectName("flyBackward");
  backward_->setToolTip("Fly and look towards the start of the centerline (the way back of a colonoscopy)");
  speed_ = new QDoubleSpinBox(this);
  speed_->setObjectName("flySpeed");
  speed_->setRange(0.5, 500);
  speed_->setValue(20);
  speed_->setSuffix(" mm/s");
  viewAngle_ = new QDoubleSpinBox(this);
  viewAngle_->setObjectName("flyViewAngle");
  viewAngle_->setRange(20, 140);
  viewAngle_->setValue(80);
  viewAngle_->setSuffix(" deg");
  viewAngle_->setToolTip("The camera's vertical field of view (an endoscope: about 80 to 140 degrees)");
  auto* flyRow = new QHBoxLayout;
  flyRow->addWidget(playButton_);
  flyRow->addWidget(backward_);
  auto* flyForm = new QFormLayout;
  flyForm->setRowWrapPolicy(QFormLayout::WrapLongRows);
  flyForm->addRow("Fly-through", flyRow);
  flyForm->addRow("Speed", speed_);  // a row of its own: beside Play and Backward it widened the dock
  flyForm->addRow("Field of view", viewAngle_);
  flyForm->addRow("Position", positionSlider_);
  extraLayout()->addLayout(flyForm);
  for (QWidget* w : {static_cast<QWidget*>(positionSlider_), static_cast<QWidget*>(playButton_)})
    w->setEnabled(false);
  // A changed direction or angle re-aims the camera where it stands (once a line is there).
  connect(backward_, &QCheckBox::toggled, this, [this] {
    if (!fly_.empty()) setPosition(position_);
  });
  connect(viewAngle_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this] {
    if (!fly_.empty()) setPosition(position_);
  });
}

void CenterlinePanel::setSeed(const std::array<double, 3>& seed) {
  seed_ = seed;
  seedLabel_->setText(QString("Seed P0: %1, %2, %3 mm")
                          .arg(seed[0], 0, 'f', 1)
                          .arg(seed[1], 0, 'f', 1)
                          .arg(seed[2], 0, 'f', 1));
}

void CenterlinePanel::clearSeed() {
  seed_.reset();
  seedLabel_->setText("Seed P0: lowest end (click a slice view to set)");
}

vtkSmartPointer<vtkAlgorithm> CenterlinePanel::makeFilter(SceneObject* input, QString&) {
  auto filter = vtkSmartPointer<vtkMedialTskCenterline>::New();
  filter->SetInputData(copyOf(input));
  const QString selection = form()->choice("Selection");
  if (selection == "label")
    filter->SetLabel(static_cast<int>(form()->value("Label")));
  else if (selection == "threshold")
    filter->SetThreshold(form()->value("ThresholdLow"), form()->value("ThresholdHigh"));
  else if (selection == "non-zero")
    filter->SelectNonZero();
  else
    filter->SelectAutomatically();
  filter->SetBorderParts(static_cast<int>(form()->value("BorderParts")));
  filter->SetFillHoles(form()->isOn("FillHoles"));
  filter->SetMaxGap(form()->value("MaxGap"));
  filter->SetMinimumPartVolume(form()->value("MinimumPartVolume"));
  filter->SetAntecedentWidth(form()->value("AntecedentWidth"));
  filter->SetSampleSpacing(form()->value("SampleSpacing"));
  filter->SetCenteringIterations(static_cast<int>(form()->value("CenteringIterations")));
  filter->SetDetectBranches(form()->isOn("DetectBranches"));
  if (seed_) filter->SetSeed((*seed_)[0], (*seed_)[1], (*seed_)[2]);
  filter->ComputeSectionsOn();
  filter->SetSectionSpacing(form()->value("SectionSpacing"));
  filter->SetRecordStages(recordSteps());
  filter->SetComputeSurface(form()->isOn("ComputeSurface"));
  return filter;
}

FilterPanel::Steps CenterlinePanel::steps(vtkAlgorithm* filter) {
  auto* tsk = static_cast<vtkMedialTskCenterline*>(filter);
  const QStringList names = {"structure voxels (layers, clusters)", "primitive centerline",
                             "TSK curve before centering"};
  Steps steps;
  for (size_t k = 0; k < vtkMedialTskCenterline::GetStageDataNames().size(); ++k)
    if (vtkPolyData* stage = tsk->GetStageData(vtkMedialTskCenterline::GetStageDataNames()[k]))
      steps.emplace_back(names[int(k)], stage);
  return steps;
}

void CenterlinePanel::collect(vtkAlgorithm* filter, SceneObject* input, double) {
  auto* tsk = static_cast<vtkMedialTskCenterline*>(filter);
  auto line = vtkSmartPointer<vtkPolyData>::New();
  line->ShallowCopy(tsk->GetOutput());
  const QString name = input->name + " centerline";
  if (SceneObject* previous = objects()->findByName(name)) objects()->remove(previous);
  // A plain line, not tubes and balls: the fly-through's camera stands on it, and the tubes of a long
  // colon take long to build on the UI thread.
  SceneObject* result = objects()->addLine(name, line, {0.1, 0.8, 0.2}, 3);
  if (!result) return;
  showBridges(result, line);
  objects()->setInterest(result, true);
  showLumen(input, vtkPolyData::SafeDownCast(tsk->GetOutputDataObject(3)));
  fly_.setPath(line);
  profile_->setProfile(vtkTable::SafeDownCast(tsk->GetOutputDataObject(1)));
  terrain_->setTerrain(vtkImageData::SafeDownCast(tsk->GetOutputDataObject(2)));
  position_ = 0;
  showPosition();  // the camera stays where the user left it until they fly
  for (QWidget* w : {static_cast<QWidget*>(positionSlider_), static_cast<QWidget*>(playButton_)})
    w->setEnabled(!fly_.empty());
  emit message(QString("Centerline: %1 points, %2 mm, %3 structure voxels")
                   .arg(line->GetNumberOfPoints())
                   .arg(fly_.length(), 0, 'f', 1)
                   .arg(tsk->GetStructureVoxels()));
  for (int i = 0; i < tsk->GetNumberOfNotes(); ++i) emit message(QString("Centerline: ") + tsk->GetNote(i));
}

void CenterlinePanel::showLumen(SceneObject* input, vtkPolyData* surface) {
  // The lumen's wall, the context of the ghost view; the volume's 3-D slices would hide it.
  const QString name = input->name + " lumen";
  if (SceneObject* previous = objects()->findByName(name)) objects()->remove(previous);
  if (!surface || surface->GetNumberOfPolys() == 0) return;
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(surface);
  if (!objects()->add(name, copy)) return;
  objects()->setVisible(input, false);
  emit message(QString("Centerline: lumen surface of %1 triangles").arg(copy->GetNumberOfPolys()));
}

void CenterlinePanel::showBridges(SceneObject* object, vtkPolyData* line) {
  // Bridges across gaps (collapsed segments) in orange, the rest of the line green.
  vtkDataArray* bridged = line->GetPointData()->GetArray("Bridged");
  auto* actor = vtkActor::SafeDownCast(object->prop);
  if (!bridged || !actor || bridged->GetRange(0)[1] < 1) return;
  auto colors = vtkSmartPointer<vtkLookupTable>::New();
  colors->SetNumberOfTableValues(2);
  colors->SetTableValue(0, 0.1, 0.8, 0.2);
  colors->SetTableValue(1, medial::kBridgedRgb[0] / 255.0, medial::kBridgedRgb[1] / 255.0,
                        medial::kBridgedRgb[2] / 255.0);
  colors->SetTableRange(0, 1);
  vtkMapper* mapper = actor->GetMapper();
  mapper->SetLookupTable(colors);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Bridged");
  mapper->SetScalarRange(0, 1);
  mapper->ScalarVisibilityOn();
}

int CenterlinePanel::profilePoints() const { return profile_->points(); }

int CenterlinePanel::bridgedProfilePoints() const { return profile_->bridgedPoints(); }

const QImage& CenterlinePanel::terrainImage() const { return terrain_->image(); }

void CenterlinePanel::showPosition() {
  {
    const QSignalBlocker block(positionSlider_);
    positionSlider_->setValue(
        fly_.empty() ? 0 : static_cast<int>(std::lround(1000.0 * position_ / fly_.length())));
  }
  profile_->setMarker(position_);
  terrain_->setMarker(position_);
}

void CenterlinePanel::setPosition(double arcLength) {
  if (fly_.empty()) return;
  position_ = std::clamp(arcLength, 0.0, fly_.length());
  showPosition();
  emit flyTo(fly_.eye(position_), fly_.focal(position_, backward()), fly_.up(position_, backward()));
}

void CenterlinePanel::setBackward(bool backward) { backward_->setChecked(backward); }

bool CenterlinePanel::backward() const { return backward_->isChecked(); }

void CenterlinePanel::setViewAngle(double degrees) { viewAngle_->setValue(degrees); }

double CenterlinePanel::viewAngle() const { return viewAngle_->value(); }

void CenterlinePanel::applyCamera(vtkCamera* camera) const {
  fly_.apply(camera, position_, backward(), viewAngle());
}

void CenterlinePanel::play(bool on) {
  if (on && !fly_.empty()) {
    // At the end it goes (a forward flight at the end starts again from the start, a backward one at
    // the start from the end).
    if (!backward() && position_ >= fly_.length()) setPosition(0);
    if (backward() && position_ <= 0) setPosition(fly_.length());
    timer_.start();
  } else {
    timer_.stop();
  }
  const QSignalBlocker block(playButton_);
  playButton_->setChecked(timer_.isActive());
  playButton_->setText(timer_.isActive() ? "Pause" : "Play");
}

void CenterlinePanel::step() {
  const double step = speed_->value() * timer_.interval() / 1000.0;
  setPosition(position_ + (backward() ? -step : step));
  if (backward() ? position_ <= 0 : position_ >= fly_.length()) play(false);
}

}  // namespace medial::gui
