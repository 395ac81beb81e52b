#include "vtkMedialScene.h"

#include "MedialVolumeRendering.h"

#include "MedialErrorCollector.h"
#include "MedialFileNames.h"
#include "MedialSketchData.h"
#include "MedialSkeletonData.h"
#include "MedialSkeletonTubes.h"
#include "MedialXDisplay.h"
#include "vtkMedialGhostPass.h"

#include <vtkActor.h>
#include <vtkAssembly.h>
#include <vtkVolume.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkImageDataOutlineFilter.h>
#include <vtkImageProperty.h>
#include <vtkImageSlice.h>
#include <vtkImageSliceMapper.h>
#include <vtkLightKit.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

vtkStandardNewMacro(vtkMedialScene);

namespace {

// Ivory for the first mesh, then well-separated hues (skeletons are usually the second object).
constexpr double kPalette[][3] = {{0.93, 0.87, 0.76}, {0.85, 0.22, 0.18}, {0.25, 0.50, 0.85},
                                  {0.30, 0.70, 0.35}, {0.95, 0.65, 0.15}, {0.60, 0.35, 0.75}};
constexpr int kPaletteSize = sizeof(kPalette) / sizeof(kPalette[0]);

bool hasRgbColors(vtkPolyData* mesh) {
  vtkDataArray* scalars = mesh->GetPointData()->GetScalars();
  return scalars && vtkUnsignedCharArray::SafeDownCast(scalars) &&
         (scalars->GetNumberOfComponents() == 3 || scalars->GetNumberOfComponents() == 4);
}

}  // namespace

vtkMedialScene::vtkMedialScene() : Renderer(vtkSmartPointer<vtkRenderer>::New()) {
  this->Renderer->GradientBackgroundOn();
  this->Renderer->SetBackground(0.10, 0.11, 0.14);   // bottom
  this->Renderer->SetBackground2(0.32, 0.34, 0.43);  // top
  auto lights = vtkSmartPointer<vtkLightKit>::New();
  lights->AddLightsToRenderer(this->Renderer);
}

vtkMedialScene::~vtkMedialScene() = default;

void vtkMedialScene::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SkeletonRadiusScale: " << this->SkeletonRadiusScale << "\n";
  os << indent << "MeshOpacity: " << this->MeshOpacity << "\n";
  os << indent
     << "VolumeStyle: " << medial::volumeStyleName(static_cast<medial::VolumeStyle>(this->VolumeStyle))
     << "\n";
  os << indent << "GhostPass: " << (this->GhostPass ? "installed" : "(none)") << "\n";
}

vtkRenderer* vtkMedialScene::GetRenderer() { return this->Renderer; }

bool vtkMedialScene::IsSkeleton(vtkPolyData* polyData) { return medial::looksLikeSkeleton(polyData); }

void vtkMedialScene::GetPaletteColor(int i, double rgb[3]) {
  const double* c = kPalette[((i % kPaletteSize) + kPaletteSize) % kPaletteSize];
  std::copy(c, c + 3, rgb);
}

vtkMedialGhostPass* vtkMedialScene::GetGhostPass() {
  if (!this->GhostPass) {
    this->GhostPass = vtkSmartPointer<vtkMedialGhostPass>::New();
    this->Renderer->SetPass(this->GhostPass);
  }
  return this->GhostPass;
}

void vtkMedialScene::SetImportance(vtkProp* prop, double importance) {
  this->GetGhostPass();
  vtkMedialGhostPass::SetImportance(prop, importance);
}

vtkProp3D* vtkMedialScene::AddData(vtkDataObject* data) {
  double rgb[3];
  if (auto* polyData = vtkPolyData::SafeDownCast(data)) {
    if (polyData->GetNumberOfPoints() == 0) {
      vtkErrorMacro(<< "nothing to show: the polydata has no points");
      return nullptr;
    }
    GetPaletteColor(this->ColorIndex++, rgb);
    if (medial::isSketch(polyData))  // strokes, drawn where their placements put them
      return this->AddSkeleton(medial::placedStrokes(polyData), rgb);
    return IsSkeleton(polyData) ? this->AddSkeleton(polyData, rgb) : this->AddMesh(polyData, rgb);
  }
  if (auto* image = vtkImageData::SafeDownCast(data)) {
    if (image->GetNumberOfPoints() == 0 || !image->GetPointData()->GetScalars()) {
      vtkErrorMacro(<< "nothing to show: the image has no voxels");
      return nullptr;
    }
    return this->AddVolume(image);
  }
  vtkErrorMacro(<< "cannot show a " << (data ? data->GetClassName() : "null data object"));
  return nullptr;
}

void vtkMedialScene::Clear() {
  this->Renderer->RemoveAllViewProps();
  this->ColorIndex = 0;
}

vtkProp3D* vtkMedialScene::AddMesh(vtkPolyData* mesh, const double rgb[3]) {
  // Smooth shading with sharp features kept: normals split at 60° (CAD-like meshes keep their edges).
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputData(mesh);
  normals->SetFeatureAngle(60.0);
  normals->ConsistencyOff();  // keep the file's orientation; inconsistent meshes still shade two-sided
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(normals->GetOutputPort());
  if (hasRgbColors(mesh)) {
    mapper->SetColorModeToDirectScalars();
    mapper->ScalarVisibilityOn();
  } else {
    mapper->ScalarVisibilityOff();
  }
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  actor->GetProperty()->SetSpecular(0.25);
  actor->GetProperty()->SetSpecularPower(30);
  actor->GetProperty()->BackfaceCullingOff();
  actor->GetProperty()->SetOpacity(this->MeshOpacity);
  this->Renderer->AddActor(actor);
  return actor;
}

vtkProp3D* vtkMedialScene::AddLine(vtkPolyData* polyData, const double rgb[3], double width) {
  if (!polyData || polyData->GetNumberOfPoints() == 0) {
    vtkErrorMacro(<< "nothing to show: the line has no points");
    return nullptr;
  }
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(polyData);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  actor->GetProperty()->LightingOff();
  this->Renderer->AddActor(actor);
  return actor;
}

vtkProp3D* vtkMedialScene::AddSkeleton(vtkPolyData* skeleton, const double rgb[3]) {
  // Radius per node: the `Radius` array, else 1 % of the bounding-box diagonal.
  double bounds[6];
  skeleton->GetBounds(bounds);
  const double diagonal = std::sqrt(std::pow(bounds[1] - bounds[0], 2) + std::pow(bounds[3] - bounds[2], 2) +
                                    std::pow(bounds[5] - bounds[4], 2));
  const vtkIdType n = skeleton->GetNumberOfPoints();
  auto radius = vtkSmartPointer<vtkDoubleArray>::New();
  radius->SetName("DrawRadius");
  radius->SetNumberOfValues(n);
  vtkDataArray* given = skeleton->GetPointData()->GetArray(medial::kRadiusArray);
  const double fallback = diagonal > 0 ? 0.01 * diagonal : 1.0;
  for (vtkIdType i = 0; i < n; ++i) {
    const double r = given ? given->GetComponent(i, 0) : fallback;
    radius->SetValue(i, (std::isfinite(r) && r > 0 ? r : fallback) * this->SkeletonRadiusScale);
  }
  auto withRadius = vtkSmartPointer<vtkPolyData>::New();
  withRadius->SetPoints(skeleton->GetPoints());
  withRadius->SetLines(skeleton->GetLines());
  withRadius->GetPointData()->SetScalars(radius);

  // Edges as truncated cones (radius interpolated between the two nodes), nodes as spheres.
  vtkSmartPointer<vtkActor> actor = medial::skeletonTubesActor(withRadius, 24);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  actor->GetProperty()->SetSpecular(0.4);
  actor->GetProperty()->SetSpecularPower(40);
  this->Renderer->AddActor(actor);
  return actor;
}

vtkProp3D* vtkMedialScene::AddVolume(vtkImageData* image) {
  if (this->VolumeStyle != 0) {
    vtkSmartPointer<vtkVolume> volume =
        medial::makeVolumeRendering(image, static_cast<medial::VolumeStyle>(this->VolumeStyle));
    this->Renderer->AddVolume(volume);
    return volume;
  }
  // Window from the 1st to the 99th percentile would be nicer; the full range shows every structure.
  double range[2];
  image->GetPointData()->GetScalars()->GetRange(range, 0);
  const double window = std::max(range[1] - range[0], 1e-9);
  const double level = 0.5 * (range[0] + range[1]);

  auto assembly = vtkSmartPointer<vtkAssembly>::New();
  int dims[3];
  image->GetDimensions(dims);
  for (int axis = 0; axis < 3; ++axis) {
    if (dims[axis] < 1) continue;
    auto mapper = vtkSmartPointer<vtkImageSliceMapper>::New();
    mapper->SetInputData(image);
    mapper->SetOrientation(axis);
    mapper->SetSliceNumber(image->GetExtent()[2 * axis] + dims[axis] / 2);
    auto slice = vtkSmartPointer<vtkImageSlice>::New();
    slice->SetMapper(mapper);
    slice->GetProperty()->SetColorWindow(window);
    slice->GetProperty()->SetColorLevel(level);
    slice->GetProperty()->SetInterpolationTypeToLinear();
    assembly->AddPart(slice);
  }
  auto outline = vtkSmartPointer<vtkImageDataOutlineFilter>::New();
  outline->SetInputData(image);
  auto outlineMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  outlineMapper->SetInputConnection(outline->GetOutputPort());
  auto outlineActor = vtkSmartPointer<vtkActor>::New();
  outlineActor->SetMapper(outlineMapper);
  outlineActor->GetProperty()->SetColor(0.9, 0.9, 0.5);
  assembly->AddPart(outlineActor);
  this->Renderer->AddViewProp(assembly);
  return assembly;
}

void vtkMedialScene::ResetCamera() {
  double aspect = 4.0 / 3.0;
  if (vtkRenderWindow* window = this->Renderer->GetRenderWindow()) {
    const int* size = window->GetSize();
    if (size[0] > 0 && size[1] > 0) aspect = static_cast<double>(size[0]) / size[1];
  }
  this->ResetCamera(aspect);
}

void vtkMedialScene::ResetCamera(double aspect) { this->ResetCamera(aspect, 30.0, 20.0); }

void vtkMedialScene::ResetCamera(double aspect, double azimuth, double elevation) {
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 1);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->Azimuth(azimuth);
  camera->Elevation(elevation);
  camera->OrthogonalizeViewUp();
  this->Renderer->ResetCamera();  // centres the focal point and sets a first distance

  // Tighter than the bounding sphere: the nearest distance at which the eight corners of the bounding
  // box project inside the view (with a 5 % margin) for this aspect ratio.
  double bounds[6];
  this->Renderer->ComputeVisiblePropBounds(bounds);
  if (!(bounds[0] <= bounds[1]) || aspect <= 0) return;
  double focal[3], direction[3], up[3], right[3];
  camera->GetFocalPoint(focal);
  camera->GetDirectionOfProjection(direction);  // from the camera towards the focal point
  camera->GetViewUp(up);
  vtkMath::Cross(direction, up, right);
  const double tanHalf = std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0) * 0.95;
  double distance = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const double p[3] = {bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
                         bounds[4 + ((corner >> 2) & 1)]};
    const double d[3] = {p[0] - focal[0], p[1] - focal[1], p[2] - focal[2]};
    const double x = vtkMath::Dot(d, right), y = vtkMath::Dot(d, up);
    const double towardsCamera = -vtkMath::Dot(d, direction);
    distance = std::max(
        {distance, towardsCamera + std::abs(x) / (tanHalf * aspect), towardsCamera + std::abs(y) / tanHalf});
  }
  if (distance <= 0) return;
  camera->SetPosition(focal[0] - distance * direction[0], focal[1] - distance * direction[1],
                      focal[2] - distance * direction[2]);
  this->Renderer->ResetCameraClippingRange();
}

bool vtkMedialScene::RenderToImage(const char* fileName, int width, int height) {
  if (!fileName || width <= 0 || height <= 0) {
    vtkErrorMacro(<< "RenderToImage needs a file name and a positive size");
    return false;
  }
  // VTK's X window aborts the process when it cannot connect; connect here (with retries: a busy Xvfb
  // refuses a connection now and then) and report a failure as an error instead.
  void* ownDisplay = nullptr;
  if (!this->DisplayId && !(ownDisplay = medial::openXDisplay())) {
    const char* name = std::getenv("DISPLAY");
    vtkErrorMacro(<< "cannot render: no X display (DISPLAY=" << (name ? name : "") << ") to connect to; "
                  << "run under xvfb-run -a, or use `medial render`, which starts its own Xvfb");
    return false;
  }
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetDisplayId(this->DisplayId ? this->DisplayId : ownDisplay);
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(8);
  window->SetSize(width, height);
  window->AddRenderer(this->Renderer);
  window->Render();

  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();

  const std::string target = fileName;
  const auto write = [&](const std::string& temporary, std::string& why) {
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetFileName(temporary.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    auto errors = medial::ErrorCollector::Watch(writer);
    writer->Write();
    if (errors->HasErrors()) why = target + ": cannot write the image (" + errors->Joined() + ")";
    return !errors->HasErrors();
  };
  std::string error;
  const bool written = medial::writeAtomically(target, write, error);
  window->RemoveRenderer(this->Renderer);
  grab = nullptr;
  window->Finalize();  // before its X connection closes
  window = nullptr;
  medial::closeXDisplay(ownDisplay);
  if (!written) vtkErrorMacro(<< error);
  return written;
}
