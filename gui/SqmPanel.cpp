#include "SqmPanel.h"

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
  using P = Parameter;
  return {
      P::choice("Smoothing", "LIE smoothing", {"quaternion", "averaging", "area-laplacian", "valency-laplacian"},
                "LIE smoothing after each BNP subdivision (CESCG 2014, Fig. 3; quaternion is the paper's "
                "proposal)"),
      P::choice("Pairing", "Ring pairing", {"total-distance", "distance", "angle"},
                "How a tube's last ring is paired with a BNP face (SQM step 3, bridging of BNPs)"),
      P::integer("LinearRingVertices", "Ring vertices N", 8, 3, 1024,
                 "Vertices of a ring when the skeleton has no branch node (CESCG 2014, linear skeletons)"),
      P::toggle("Capsules", "Capsule leaves", false, "Close leaves with hemispheres (CESCG 2014, Capsule Ending)"),
      P::toggle("PairTriangles", "Quads at leaf tips", true,
                "Join the triangles of leaf fans and cycle bands into quads (off: the paper's triangle fans)"),
      P::toggle("SharpScaling", "Sharp scaling", false,
                "With subdivision: shrink the cone radius near sharp vertices by a Bézier curve (CESCG 2014, "
                "Tessellation)"),
      P::real("SharpMinimumScale", "Sharp scale", 0.8, 0.05, 1.0, 2, "Radius factor at a sharp vertex"),
      P::toggle("FoldRepair", "Repair folds", true,
                "With subdivision: where the projection onto the cones makes faces cut each other, move their "
                "vertices back towards the plain Catmull-Clark surface"),
  };
}

}  // namespace

SqmPanel::SqmPanel(ObjectList* objects, QWidget* parent)
    : FilterPanel("SQM", SceneObject::Kind::Skeleton, sqmParameters(), objects, parent) {
  subdivision_ = new QSlider(Qt::Horizontal, this);
  subdivision_->setObjectName("SubdivisionLevels");
  subdivision_->setRange(0, 4);
  subdivision_->setPageStep(1);
  subdivision_->setTickPosition(QSlider::TicksBelow);
  subdivision_->setToolTip("Catmull-Clark levels, each projected onto the skeleton's cones (CESCG 2014, Tessellation, Fig. 9)");
  live_ = new QCheckBox("Update live", this);
  live_->setObjectName("live");
  live_->setChecked(true);
  live_->setToolTip("Re-run when a parameter changes, replacing the previous mesh");
  auto* rows = new QFormLayout;
  rows->addRow("Subdivision", subdivision_);
  rows->addRow(live_);
  extraLayout()->addLayout(rows);
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
  filter->SetPairTriangles(form()->isOn("PairTriangles"));
  filter->SetSubdivisionLevels(subdivision_->value());
  filter->SetSharpScaling(form()->isOn("SharpScaling"));
  filter->SetFoldRepair(form()->isOn("FoldRepair"));
  filter->SetSharpMinimumScale(form()->value("SharpMinimumScale"));
  return filter;
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
  const int merged = static_cast<vtkMedialSQM*>(filter)->GetMergedNodes();
  const int unfolded = static_cast<vtkMedialSQM*>(filter)->GetFoldRepairedVertices();
  emit message(QString("SQM: %1 faces, %2 vertices, subdivision %3%4%5")
                   .arg(mesh->GetNumberOfPolys())
                   .arg(mesh->GetNumberOfPoints())
                   .arg(subdivision_->value())
                   .arg(merged > 0 ? QString("; %1 nodes inside a neighbouring branch node's sphere merged into it")
                                         .arg(merged)
                                   : QString())
                   .arg(unfolded > 0 ? QString("; %1 refined vertices moved off their cones to undo folds").arg(unfolded)
                                     : QString()));
}

}  // namespace medial::gui
