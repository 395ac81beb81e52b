#include "SkeletonPanel.h"

#include "NodeColors.h"

#include "FilterDefaults.h"
#include "ObjectList.h"
#include "vtkMedialContractionSkeleton.h"

#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkLine.h>
#include <vtkLookupTable.h>
#include <vtkMapper.h>
#include <vtkPointData.h>

#include <limits>

namespace medial::gui {

namespace {

std::vector<Parameter> contractionParameters() {
  const auto f = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  auto weights = MEDIAL_TOGGLE_PARAMETER(f, ComputeWeights, "Skinning weights",
                                         "Heat-diffusion skinning weights (§III.E), for the rig");
  weights.value = 1;  // a GUI preset: the weights cost a factorization, but Export Rig needs them
  return {
      MEDIAL_INTEGER_PARAMETER(f, TargetNodes, "Skeleton nodes",
                               "Nodes kept by node selection (§III.D); 0 keeps the whole curve skeleton"),
      MEDIAL_INTEGER_PARAMETER(f, ContractionVertices, "Contracted vertices",
                               "Larger meshes are decimated to this many vertices before the contraction "
                               "(topology kept); 0 contracts the mesh as it is"),
      MEDIAL_INTEGER_PARAMETER(f, ReferenceVertices, "Reference vertices",
                               "A mesh contracted with more vertices starts with W_L0 × (n / this)^1.5, so "
                               "that its first iterations contract as at this size; 0: the paper's W_L0"),
      MEDIAL_REAL_PARAMETER(f, InitialContractionFactor, "W_L0 factor", 6,
                            "W_L0 = factor · sqrt(mean face area) (§III.A, default 1e-3)"),
      MEDIAL_REAL_PARAMETER(f, ContractionScale, "s_L", 2, "Growth of W_L per iteration (§III.A, default 2)"),
      MEDIAL_REAL_PARAMETER(f, InitialAttractionWeight, "W_H0", 3,
                            "Initial attraction weight (§III.A, default 1)"),
      MEDIAL_REAL_PARAMETER(f, MaxContractionWeight, "W_L cap", 0,
                            "Upper bound of W_L (§III.A, default 2048)"),
      MEDIAL_REAL_PARAMETER(f, MaxAttractionWeight, "W_H cap", 0,
                            "Upper bound of W_H (§III.A, default 10000)"),
      MEDIAL_INTEGER_PARAMETER(f, MaxIterations, "Max iterations", "Contraction iterations at most (§III.A)"),
      MEDIAL_REAL_PARAMETER(f, ShapeWeight, "w_a", 3,
                            "Shape cost weight of the surgery, eq. (10) (default 1)"),
      MEDIAL_REAL_PARAMETER(f, SamplingWeight, "w_b", 3,
                            "Sampling cost weight of the surgery, eq. (10) (default 0.1)"),
      MEDIAL_REAL_PARAMETER(
          f, CollapseLengthFraction, "δ (collapse length)", 4,
          "Surgery pre-pass: edges shorter than this fraction of the contracted mesh's size "
          "collapse first (§III.B, default 0.001)"),
      MEDIAL_TOGGLE_PARAMETER(f, RefineEmbedding, "Refine embedding",
                              "Move nodes to the center of their vertices (§III.C)"),
      MEDIAL_TOGGLE_PARAMETER(
          f, RestoreCycles, "Restore cycles",
          "Put back the cycles surgery lost: as many skeleton cycles as the mesh has genus"),
      MEDIAL_TOGGLE_PARAMETER(f, CenterNodes, "Center nodes",
                              "Move nodes to the centroid of the mesh's cross-section through them"),
      weights,
      MEDIAL_REAL_PARAMETER(f, HeatConstant, "c (heat)", 3,
                            "H_jj = c / d(j)^2 (§III.E, Baran and Popović: 1)"),
      choiceOf("Solver", "Solver", vtkMedialContractionSkeleton::GetSolverNames(), f->GetSolver(),
               "Sparse solver of the normal equations (5)"),
  };
}

vtkSmartPointer<vtkLookupTable> weightColors() {
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetHueRange(0.667, 0.0);  // blue (0) to red (1)
  table->SetTableRange(0, 1);
  table->Build();
  return table;
}

}  // namespace

SkeletonPanel::SkeletonPanel(ObjectList* objects, QWidget* parent)
    : FilterPanel("Skeleton", SceneObject::Kind::Mesh, contractionParameters(), objects, parent) {
  bone_ = new QSpinBox(this);
  bone_->setObjectName("bone");
  bone_->setRange(-1, -1);
  bone_->setSpecialValueText("segments");
  bone_->setToolTip("Color the mesh by this bone's skinning weight (or click a bone in the 3-D view)");
  auto* row = new QFormLayout;
  row->addRow("Show weights of bone", bone_);
  extraLayout()->addLayout(row);
  enableSteps(
      "Keep the contracted mesh after every iteration (the paper's Fig. 5, with |LV| and the "
      "weights of Fig. 7) and the skeleton after the surgery and before the selection");
  connect(bone_, &QSpinBox::valueChanged, this, [this](int bone) {
    if (lastSkeleton_) selectBone(lastSkeleton_, bone);
  });
  connect(objects, &ObjectList::objectsChanged, this, [this] {
    bool live = false;
    for (SceneObject* s : this->objects()->ofKind(SceneObject::Kind::Skeleton))
      live = live || s == lastSkeleton_;
    if (!live) lastSkeleton_ = nullptr;
  });
}

vtkSmartPointer<vtkAlgorithm> SkeletonPanel::makeFilter(SceneObject* input, QString&) {
  auto filter = vtkSmartPointer<vtkMedialContractionSkeleton>::New();
  const ParameterForm* f = form();
  filter->SetInputData(copyOf(input));
  filter->SetTargetNodes(static_cast<int>(f->value("TargetNodes")));
  filter->SetContractionVertices(static_cast<int>(f->value("ContractionVertices")));
  filter->SetReferenceVertices(static_cast<int>(f->value("ReferenceVertices")));
  filter->SetInitialContractionFactor(f->value("InitialContractionFactor"));
  filter->SetContractionScale(f->value("ContractionScale"));
  filter->SetMaxContractionWeight(f->value("MaxContractionWeight"));
  filter->SetMaxAttractionWeight(f->value("MaxAttractionWeight"));
  filter->SetMaxIterations(static_cast<int>(f->value("MaxIterations")));
  filter->SetShapeWeight(f->value("ShapeWeight"));
  filter->SetSamplingWeight(f->value("SamplingWeight"));
  filter->SetInitialAttractionWeight(f->value("InitialAttractionWeight"));
  filter->SetCollapseLengthFraction(f->value("CollapseLengthFraction"));
  filter->SetRefineEmbedding(f->isOn("RefineEmbedding"));
  filter->SetRestoreCycles(f->isOn("RestoreCycles"));
  filter->SetCenterNodes(f->isOn("CenterNodes"));
  filter->SetComputeWeights(f->isOn("ComputeWeights"));
  filter->SetHeatConstant(f->value("HeatConstant"));
  filter->SetSolver(f->choice("Solver").toStdString());
  filter->SetRecordStages(recordSteps());
  return filter;
}

FilterPanel::Steps SkeletonPanel::steps(vtkAlgorithm* filter) {
  auto* contraction = static_cast<vtkMedialContractionSkeleton*>(filter);
  Steps steps;
  for (int t = 0; t < contraction->GetNumberOfContractionSteps(); ++t)
    steps.emplace_back(QString("contraction iteration %1").arg(t), contraction->GetContractionStep(t));
  if (contraction->GetSurgerySkeleton())
    steps.emplace_back("skeleton after the surgery (III.B)", contraction->GetSurgerySkeleton());
  if (contraction->GetUnselectedSkeleton())
    steps.emplace_back("skeleton before the selection (III.C)", contraction->GetUnselectedSkeleton());
  return steps;
}

void SkeletonPanel::collect(vtkAlgorithm* filter, SceneObject* input, double) {
  auto* contraction = static_cast<vtkMedialContractionSkeleton*>(filter);
  auto skeletonData = vtkSmartPointer<vtkPolyData>::New();
  skeletonData->ShallowCopy(contraction->GetOutput(0));
  auto meshData = vtkSmartPointer<vtkPolyData>::New();
  meshData->ShallowCopy(contraction->GetOutput(1));
  const int restored = contraction->GetRestoredCycles();
  emit message(QString("Skeleton: %1 nodes, %2 bones, %3 contraction iterations%4")
                   .arg(skeletonData->GetNumberOfPoints())
                   .arg(skeletonData->GetNumberOfLines())
                   .arg(contraction->GetContractionIterations())
                   .arg(restored > 0 ? QString("; %1 cycles surgery lost put back (genus %2)")
                                           .arg(restored)
                                           .arg(contraction->GetGenus())
                                     : QString()));

  SceneObject* segmentation = objects()->add(input->name + " segments", meshData);
  SceneObject* skeleton =
      objects()->add(input->name + " skeleton", skeletonData, QString(), kComputedRadiusScale);
  if (!segmentation || !skeleton) return;
  if (meshData->GetPointData()->GetArray("SkinWeights")) skeleton->skinnedMesh = meshData;
  objects()->setVisible(input, false);  // the segmentation mesh replaces it
  objects()->setOpacity(segmentation, 0.6);
  objects()->setInterest(skeleton, true);  // seen through the mesh in the ghost view
  lastSkeleton_ = skeleton;
  {
    const QSignalBlocker block(bone_);
    bone_->setRange(-1, skeleton->skinnedMesh ? static_cast<int>(skeletonData->GetNumberOfLines()) - 1 : -1);
    bone_->setValue(-1);
  }
  selectBone(skeleton, -1);
}

SceneObject* SkeletonPanel::segmentationOf(SceneObject* skeleton) const {
  if (!skeleton) return nullptr;
  const QString name =
      skeleton->name.endsWith(" skeleton") ? skeleton->name.chopped(9) + " segments" : QString();
  return objects()->findByName(name);
}

bool SkeletonPanel::selectBone(SceneObject* skeleton, int bone) {
  SceneObject* mesh = segmentationOf(skeleton);
  auto* actor = mesh ? vtkActor::SafeDownCast(mesh->prop) : nullptr;
  if (!actor) return false;
  vtkPolyData* data = mesh->polyData();
  vtkMapper* mapper = actor->GetMapper();
  vtkDataArray* weights = data->GetPointData()->GetArray("SkinWeights");
  if (bone >= 0 && (!weights || bone >= weights->GetNumberOfComponents())) return false;
  mapper->ScalarVisibilityOn();
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SetColorModeToMapScalars();
  if (bone < 0) {
    colorByLabel(actor, "SkeletonNode", static_cast<int>(skeleton->polyData()->GetNumberOfPoints()));
  } else {
    mapper->SetLookupTable(weightColors());
    mapper->ColorByArrayComponent("SkinWeights", bone);
    mapper->SetScalarRange(0, 1);
  }
  if (skeleton == lastSkeleton_ && bone_->value() != bone) {
    const QSignalBlocker block(bone_);
    bone_->setValue(bone);
  }
  emit message(bone < 0 ? QString("Mesh colored by SkeletonNode")
                        : QString("Mesh colored by the weight of bone %1").arg(bone));
  emit legendChanged(bone < 0 ? nullptr : mapper->GetLookupTable(), QString("bone %1").arg(bone));
  emit sceneChanged();
  return true;
}

int SkeletonPanel::nearestBone(SceneObject* skeleton, const double point[3]) {
  vtkPolyData* data = skeleton ? skeleton->polyData() : nullptr;
  if (!data || !data->GetLines()) return -1;
  int best = -1, cell = 0;
  double bestDistance = std::numeric_limits<double>::max();
  vtkIdType count;
  const vtkIdType* ids;
  auto lines = data->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(count, ids); ++cell) {
    if (count < 2) continue;
    double a[3], b[3], t, closest[3];
    data->GetPoint(ids[0], a);
    data->GetPoint(ids[count - 1], b);
    const double d = vtkLine::DistanceToLine(point, a, b, t, closest);
    if (d < bestDistance) bestDistance = d, best = cell;
  }
  return best;
}

}  // namespace medial::gui
