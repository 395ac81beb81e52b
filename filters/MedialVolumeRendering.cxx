#include "MedialVolumeRendering.h"

#include <vtkAutoInit.h>
#include <vtkColorTransferFunction.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

// vtkSmartVolumeMapper's GPU ray caster is an object-factory override of this module: registered here,
// so that every user of the scene (CLI, GUI, tests, Python) gets it without listing the module itself.
VTK_MODULE_INIT(vtkRenderingVolumeOpenGL2);

namespace medial {

namespace {
const VolumeStyle kStyles[] = {VolumeStyle::Slices, VolumeStyle::CtBone, VolumeStyle::CtSoftTissue,
                               VolumeStyle::FullRange};
}

const char* volumeStyleName(VolumeStyle style) {
  switch (style) {
    case VolumeStyle::Slices:
      return "slices";
    case VolumeStyle::CtBone:
      return "ct-bone";
    case VolumeStyle::CtSoftTissue:
      return "ct-soft-tissue";
    case VolumeStyle::FullRange:
      return "full-range";
  }
  return "";
}

bool parseVolumeStyle(const std::string& name, VolumeStyle& style) {
  for (VolumeStyle s : kStyles)
    if (name == volumeStyleName(s)) {
      style = s;
      return true;
    }
  return false;
}

vtkSmartPointer<vtkVolume> makeVolumeRendering(vtkImageData* image, VolumeStyle style) {
  if (style == VolumeStyle::Slices || !image || !image->GetPointData()->GetScalars()) return nullptr;
  auto colour = vtkSmartPointer<vtkColorTransferFunction>::New();
  auto opacity = vtkSmartPointer<vtkPiecewiseFunction>::New();
  switch (style) {
    case VolumeStyle::CtBone:  // cancellous bone from ~150 HU, cortical bone opaque above ~1000 HU
      colour->AddRGBPoint(150, 0.75, 0.55, 0.40);
      colour->AddRGBPoint(500, 0.95, 0.90, 0.80);
      colour->AddRGBPoint(1500, 1.0, 1.0, 1.0);
      opacity->AddPoint(150, 0.0);
      opacity->AddPoint(400, 0.25);
      opacity->AddPoint(1000, 0.85);
      break;
    case VolumeStyle::CtSoftTissue:  // faint skin, reddish soft tissue, opaque bone
      colour->AddRGBPoint(-500, 0.85, 0.60, 0.50);
      colour->AddRGBPoint(40, 0.80, 0.30, 0.25);
      colour->AddRGBPoint(300, 1.0, 0.95, 0.85);
      opacity->AddPoint(-600, 0.0);
      opacity->AddPoint(-400, 0.05);
      opacity->AddPoint(100, 0.08);
      opacity->AddPoint(300, 0.6);
      break;
    case VolumeStyle::Slices:
      break;
    case VolumeStyle::FullRange: {
      double range[2] = {0, 1};
      if (vtkDataArray* scalars = image->GetPointData()->GetScalars()) scalars->GetRange(range, 0);
      const double low = range[0] + 0.05 * (range[1] - range[0]);
      colour->AddRGBPoint(low, 0.6, 0.6, 0.7);
      colour->AddRGBPoint(range[1], 1.0, 0.95, 0.8);
      opacity->AddPoint(low, 0.0);
      opacity->AddPoint(range[1], 0.6);
      break;
    }
  }
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(colour);
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();
  property->ShadeOn();
  property->SetAmbient(0.3);
  property->SetDiffuse(0.7);
  property->SetSpecular(0.2);
  auto mapper = vtkSmartPointer<vtkSmartVolumeMapper>::New();
  mapper->SetInputData(image);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  return volume;
}

}  // namespace medial
