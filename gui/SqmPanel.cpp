#include "SqmPanel.h"

#include "FilterDefaults.h"
#include "ObjectList.h"
#include "vtkMedialSQM.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QSlider>
#include <QVBoxLayout>

#include <vtkActor.h>
#include <vtkProperty.h>

namespace medial::gui {

namespace {

std::vector<Parameter> sqmParameters() {
  const auto f = vtkSmartPointer<vtkMedialSQM>::New();
  return {
      choiceOf("Smoothing", "LIE smoothing", vtkMedialSQM::GetSmoothingNames(), f->GetSmoothing(),
               "LIE smoothing after each BNP subdivision (CESCG 2014, Fig. 3; quaternion is the paper's "
               "proposal)"),
      choiceOf("Pairing", "Ring pairing", vtkMedialSQM::GetPairingNames(), f->GetPairing(),
               "How a tube's last ring is paired with a BNP face (SQM step 3, bridging of BNPs)"),
      MEDIAL_INTEGER_PARAMETER(f, LinearRingVertices, "Ring vertices N",
                               "Vertices of a ring when the skeleton has no branch node (CESCG 2014, linear "
                               "skeletons)"),
      MEDIAL_TOGGLE_PARAMETER(f, Capsules, "Capsule leaves",
                              "Close leaves with hemispheres (CESCG 2014, Capsule Ending)"),
      MEDIAL_INTEGER_PARAMETER(f, CapsuleSteps, "Capsule rings",
                               "With capsule leaves: rings added beyond each leaf to close it"),
      MEDIAL_TOGGLE_PARAMETER(f, PairTriangles, "Quads at leaf tips",
                              "Join the triangles of leaf fans and cycle bands into quads (off: the paper's "
                              "triangle fans)"),
      MEDIAL_TOGGLE_PARAMETER(
          f, SharpScaling, "Sharp scaling",
          "With subdivision: shrink the swept spheres' radius near sharp vertices by a Bézier curve "
          "(CESCG 2014, Tessellation)"),
      MEDIAL_REAL_PARAMETER(f, SharpMinimumScale, "Sharp scale", 2, "Radius factor at a sharp vertex"),
      MEDIAL_TOGGLE_PARAMETER(
          f, FoldRepair, "Repair folds",
          "With subdivision: where the projection onto the swept spheres makes faces cut each "
          "other, move their vertices back towards the base mesh"),
      MEDIAL_TOGGLE_PARAMETER(f, MergeNodes, "Merge swallowed nodes",
                              "Merge a node lying inside a neighbouring branch node's sphere into it (off: "
                              "such a skeleton is an error naming the node)"),
      MEDIAL_TOGGLE_PARAMETER(
          f, Union, "Union of overlapping tubes",
          "Where tubes of parts that are not neighbours overlap, make the mesh the boundary of "
          "their union: one closed surface without self-intersections, triangles along the "
          "intersection curves (overlaps are counted in the log either way)"),
  };
}

}  // namespace

SqmPanel::SqmPanel(ObjectList* objects, QWidget* parent)
    : FilterPanel("SQM", SceneObject::Kind::Skeleton, sqmParameters(), objects, parent) {
  subdivision_ = new QSlider(Qt::Horizontal, this);
  subdivision_->setObjectName("SubdivisionLevels");
  const auto defaults = vtkSmartPointer<vtkMedialSQM>::New();
  subdivision_->setRange(defaults->GetSubdivisionLevelsMinValue(), defaults->GetSubdivisionLevelsMaxValue());
  subdivision_->setValue(defaults->GetSubdivisionLevels());
  subdivision_->setPageStep(1);
  subdivision_->setTickPosition(QSlider::TicksBelow);
  subdivision_->setToolTip(
      "Tessellation levels, each projected onto the spheres swept along the skeleton (CESCG 2014, "
      "Tessellation, Fig. 9)");
  live_ = new QCheckBox("Update live", this);
  live_->setObjectName("live");
  live_->setChecked(true);
  live_->setToolTip("Re-run when a parameter changes, replacing the previous mesh");
  auto* rows = new QFormLayout;
  rows->setRowWrapPolicy(QFormLayout::WrapLongRows);
  rows->addRow("Subdivision", subdivision_);
  rows->addRow(live_);
  extraLayout()->addLayout(rows);
  enableSteps(
      "Keep the branch node polyhedra as generated and after the LIE refinement (bind pose), and the "
      "joined mesh before subdivision, colored by node");
  connect(subdivision_, &QSlider::valueChanged, this, &SqmPanel::parameterChanged);
  connect(form(), &ParameterForm::valueChanged, this, &SqmPanel::parameterChanged);
}

void SqmPanel::parameterChanged() {
  if (!live_->isChecked() || !input()) return;
  // Only re-run a skeleton that already has a mesh: the first run is the user's Run.
  if (objects()->findByName(input()->name + " SQM")) runAgain();
}

vtkSmartPointer<vtkAlgorithm> SqmPanel::makeFilter(SceneObject* input, QString&) {
  auto filter = vtkSmartPointer<vtkMedialSQM>::New();
  filter->SetInputData(copyOf(input));
  filter->SetSmoothing(form()->choice("Smoothing").toStdString());
  filter->SetPairing(form()->choice("Pairing").toStdString());
  filter->SetLinearRingVertices(static_cast<int>(form()->value("LinearRingVertices")));
  filter->SetCapsules(form()->isOn("Capsules"));
  filter->SetCapsuleSteps(static_cast<int>(form()->value("CapsuleSteps")));
  filter->SetPairTriangles(form()->isOn("PairTriangles"));
  filter->SetSubdivisionLevels(subdivision_->value());
  filter->SetSharpScaling(form()->isOn("SharpScaling"));
  filter->SetFoldRepair(form()->isOn("FoldRepair"));
  filter->SetMergeNodes(form()->isOn("MergeNodes"));
  filter->SetUnion(form()->isOn("Union"));
  filter->CountOverlapsOn();
  filter->SetSharpMinimumScale(form()->value("SharpMinimumScale"));
  filter->SetRecordStages(recordSteps());
  return filter;
}

FilterPanel::Steps SqmPanel::steps(vtkAlgorithm* filter) {
  auto* sqm = static_cast<vtkMedialSQM*>(filter);
  const QStringList names = {"branch node polyhedra (generated)", "branch node polyhedra (LIE refined)",
                             "base mesh before subdivision"};
  Steps steps;
  for (size_t k = 0; k < vtkMedialSQM::GetStageMeshNames().size(); ++k)
    if (vtkPolyData* stage = sqm->GetStageMesh(vtkMedialSQM::GetStageMeshNames()[k]))
      steps.emplace_back(names[int(k)], stage);
  return steps;
}

void SqmPanel::collect(vtkAlgorithm* filter, SceneObject* input, double) {
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(static_cast<vtkMedialSQM*>(filter)->GetOutput());
  const QString name = input->name + " SQM";
  double opacity = 1.0;
  if (SceneObject* previous = objects()->findByName(name)) {
    if (auto* actor = vtkActor::SafeDownCast(previous->prop)) opacity = actor->GetProperty()->GetOpacity();
    objects()->remove(previous);
  }
  if (SceneObject* result = objects()->add(name, mesh)) objects()->setOpacity(result, opacity);
  auto* sqm = static_cast<vtkMedialSQM*>(filter);
  const int merged = sqm->GetMergedNodes();
  const int unfolded = sqm->GetFoldRepairedVertices();
  const int overlaps = sqm->GetOverlappingNodePairs();
  const QString atLeast = sqm->GetOverlapCountComplete() ? "" : "at least ";  // past the count's limit
  QString overlapNote;
  if (overlaps > 0 && sqm->GetUnion())
    overlapNote = QString("; tubes overlapped at %1%2 pairs of nodes, united (%3 polygons cut)")
                      .arg(atLeast)
                      .arg(overlaps)
                      .arg(sqm->GetUnionCutPolygons());
  else if (overlaps > 0)
    overlapNote = QString(
                      "; tubes overlap at %1%2 pairs of nodes (%1%3 pairs of faces cut each other): the mesh "
                      "bounds no volume, tick \"Union of overlapping tubes\"")
                      .arg(atLeast)
                      .arg(overlaps)
                      .arg(sqm->GetOverlappingFacePairs());
  emit message(
      QString("SQM: %1 faces, %2 vertices, subdivision %3%4%5%6")
          .arg(mesh->GetNumberOfPolys())
          .arg(mesh->GetNumberOfPoints())
          .arg(subdivision_->value())
          .arg(merged > 0 ? QString("; %1 nodes inside a neighbouring branch node's sphere merged into it")
                                .arg(merged)
                          : QString())
          .arg(unfolded > 0
                   ? QString("; %1 refined vertices moved off the swept spheres to undo folds").arg(unfolded)
                   : QString())
          .arg(overlapNote));
}

}  // namespace medial::gui
