#include "MedialTerrainImage.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>

namespace medial {

TerrainGrey terrainGrey(vtkImageData* terrain) {
  TerrainGrey grey;
  vtkDataArray* distance = terrain ? terrain->GetPointData()->GetScalars() : nullptr;
  if (!distance) return grey;
  std::vector<double> values;
  for (vtkIdType i = 0; i < distance->GetNumberOfTuples(); ++i)
    if (std::isfinite(distance->GetComponent(i, 0))) values.push_back(distance->GetComponent(i, 0));
  if (values.empty()) return grey;
  std::sort(values.begin(), values.end());
  const double low = values[values.size() * 2 / 100], high = values[values.size() * 98 / 100];
  const double range = std::max(high - low, 1e-9);
  int dims[3];
  terrain->GetDimensions(dims);
  grey.width = dims[0];
  grey.height = dims[1];
  grey.pixels.resize(size_t(dims[0]) * dims[1]);
  grey.bridged.assign(size_t(dims[1]), 0);
  if (vtkDataArray* bridged = terrain->GetPointData()->GetArray("Bridged"))
    for (int y = 0; y < dims[1]; ++y)
      grey.bridged[size_t(y)] = bridged->GetComponent(vtkIdType(y) * dims[0], 0) != 0;
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      const double d = distance->GetComponent(vtkIdType(y) * dims[0] + x, 0);
      const double level = std::isfinite(d) ? std::clamp(255.0 * (d - low) / range, 0.0, 255.0) : 255.0;
      grey.pixels[size_t(y) * dims[0] + x] = uint8_t(std::lround(level));  // VTK's row y = section y
    }
  return grey;
}

}  // namespace medial
