#include "IsoSurfacePanel.h"

#include "ObjectList.h"

#include <vtkDataArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkWindowedSincPolyDataFilter.h>

namespace medial::gui {

namespace {

std::vector<Parameter> isoParameters() {
  using P = Parameter;
  return {
      P::real("Value", "Iso-value", 300, -1e6, 1e6, 2,
              "Surface where the volume crosses this value: CT bone 300 HU, skin -400 HU; labels 0.5"),
      P::toggle("LargestOnly", "Largest part only", false, "Keep only the largest connected surface"),
      P::integer("Smoothing", "Smoothing iterations", 15, 0, 200,
                 "Windowed-sinc smoothing that removes the voxel staircase (0: none)"),
  };
}

}  // namespace

IsoSurfacePanel::IsoSurfacePanel(ObjectList* objects, QWidget* parent)
    : FilterPanel("Iso-surface", SceneObject::Kind::Volume, isoParameters(), objects, parent) {}

void IsoSurfacePanel::inputChanged(SceneObject* input) {
  auto* image = vtkImageData::SafeDownCast(input->data);
  if (!image || !image->GetPointData()->GetScalars()) return;
  double range[2];
  image->GetPointData()->GetScalars()->GetRange(range, 0);
  // A CT: bone (300 HU) when it holds any, else the wall between air and soft tissue (-500 HU: the colon's,
  // as docs/gui.md says; the middle of the range was -438.5 on the colon phantom); any other volume: the
  // middle of its range.
  const bool ct = range[0] < -500;
  form()->setValue("Value", ct ? (range[1] > 300 ? 300.0 : -500.0) : 0.5 * (range[0] + range[1]));
}

vtkSmartPointer<vtkAlgorithm> IsoSurfacePanel::makeFilter(SceneObject* input, QString& error) {
  auto* image = vtkImageData::SafeDownCast(input->data);
  double range[2];
  image->GetPointData()->GetScalars()->GetRange(range, 0);
  const double value = form()->value("Value");
  if (value <= range[0] || value >= range[1]) {
    error = QString("The iso-value %1 lies outside the values of %2 (%3 to %4).")
                .arg(value)
                .arg(input->name)
                .arg(range[0])
                .arg(range[1]);
    return nullptr;
  }
  auto contour = vtkSmartPointer<vtkFlyingEdges3D>::New();
  contour->SetInputData(copyOf(input));
  contour->SetValue(0, value);
  contour->ComputeNormalsOff();
  contour->ComputeScalarsOff();
  vtkSmartPointer<vtkPolyDataAlgorithm> last = contour;
  if (form()->isOn("LargestOnly")) {
    auto largest = vtkSmartPointer<vtkPolyDataConnectivityFilter>::New();
    largest->SetInputConnection(last->GetOutputPort());
    largest->SetExtractionModeToLargestRegion();
    last = largest;
  }
  const int iterations = static_cast<int>(form()->value("Smoothing"));
  if (iterations > 0) {
    auto smooth = vtkSmartPointer<vtkWindowedSincPolyDataFilter>::New();
    smooth->SetInputConnection(last->GetOutputPort());
    smooth->SetNumberOfIterations(iterations);
    smooth->SetPassBand(0.1);
    smooth->NormalizeCoordinatesOn();
    last = smooth;
  }
  return last;
}

void IsoSurfacePanel::collect(vtkAlgorithm* filter, SceneObject* input, double) {
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(vtkPolyDataAlgorithm::SafeDownCast(filter)->GetOutput());
  if (mesh->GetNumberOfPolys() == 0) {
    emit failed("Iso-surface", "The surface is empty: choose another iso-value.");
    return;
  }
  const QString name = QString("%1 iso %2").arg(input->name).arg(form()->value("Value"));
  if (SceneObject* previous = objects()->findByName(name)) objects()->remove(previous);
  objects()->add(name, mesh);
  objects()->setVisible(input, false);  // the volume's opaque 3-D slices would hide the surface
  emit message(QString("Iso-surface: %1 triangles").arg(mesh->GetNumberOfPolys()));
}

}  // namespace medial::gui
