#include "NodeColors.h"

#include <vtkActor.h>
#include <vtkLookupTable.h>
#include <vtkMapper.h>
#include <vtkMath.h>

#include <algorithm>

namespace medial::gui {

vtkSmartPointer<vtkLookupTable> segmentColors(int count) {
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(std::max(count, 1));
  double hue = 0.1;
  for (int i = 0; i < std::max(count, 1); ++i, hue += 0.618034) {
    hue -= static_cast<int>(hue);
    double rgb[3];
    vtkMath::HSVToRGB(hue, 0.55, 0.95, rgb, rgb + 1, rgb + 2);
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2]);
  }
  table->SetTableRange(0, std::max(count - 1, 1));
  return table;
}

bool colorByLabel(vtkActor* actor, const char* name, int count) {
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  if (!mapper) return false;
  mapper->ScalarVisibilityOn();
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SetColorModeToMapScalars();
  mapper->SetLookupTable(segmentColors(count));
  mapper->ColorByArrayComponent(name, 0);
  mapper->SetScalarRange(0, std::max(count - 1, 1));
  return true;
}

}  // namespace medial::gui
