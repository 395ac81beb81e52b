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
  grey.low = low;
  grey.high = low + range;
  grey.pixels.resize(size_t(dims[0]) * dims[1]);
  grey.noWall.assign(grey.pixels.size(), 0);
  grey.bridged.assign(size_t(dims[1]), 0);
  if (vtkDataArray* bridged = terrain->GetPointData()->GetArray("Bridged"))
    for (int y = 0; y < dims[1]; ++y)
      grey.bridged[size_t(y)] = bridged->GetComponent(vtkIdType(y) * dims[0], 0) != 0;
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      const double d = distance->GetComponent(vtkIdType(y) * dims[0] + x, 0);
      const double level = std::isfinite(d) ? std::clamp(255.0 * (d - low) / range, 0.0, 255.0) : 255.0;
      grey.pixels[size_t(y) * dims[0] + x] = uint8_t(std::lround(level));  // VTK's row y = section y
      grey.noWall[size_t(y) * dims[0] + x] = !std::isfinite(d);
    }
  return grey;
}

void terrainColour(uint8_t level, uint8_t rgb[3]) {
  // viridis (matplotlib's, van der Walt and Smith 2015) at nine stops, linear in between
  static const uint8_t stops[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},
                                      {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                      {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  const double t = level / 255.0 * 8.0;
  const int k = std::min(7, int(t));
  const double f = t - k;
  for (int c = 0; c < 3; ++c) rgb[c] = uint8_t(std::lround((1 - f) * stops[k][c] + f * stops[k + 1][c]));
}

void terrainPixelColour(const TerrainGrey& grey, size_t index, uint8_t rgb[3]) {
  const uint8_t* fixed = grey.bridged[index / size_t(grey.width)] ? kBridgedRgb
                         : grey.noWall[index]                     ? kNoWallRgb
                                                                  : nullptr;
  if (fixed)
    std::copy(fixed, fixed + 3, rgb);
  else
    terrainColour(grey.pixels[index], rgb);
}

}  // namespace medial
