// MedialTerrainImage: the TSK filter's unfolded wall (`WallDistance` over angle x arc length) as 8-bit
// grey levels for pictures (the CLI's --terrain PNG, the GUI's terrain view).
#pragma once

#include <cstdint>
#include <vector>

class vtkImageData;

namespace medial {

struct TerrainGrey {
  int width = 0, height = 0;     // angles x sections
  std::vector<uint8_t> pixels;   // row-major, the first section on the top row
  std::vector<uint8_t> bridged;  // per section (row): 1 on a bridge across a gap, where there is no lumen
};

// The colour pictures give the rows of bridged sections (orange), else the grey level.
constexpr uint8_t kBridgedRgb[3] = {255, 140, 0};

// Black = the 2nd percentile of the wall distances, white = the 98th and rays without a wall (a few rays
// that run far along a bend would otherwise squeeze the haustral folds into a few grey levels). Empty
// when the image has no finite distance. `bridged` from the image's `Bridged` array (all 0 without it).
TerrainGrey terrainGrey(vtkImageData* terrain);

}  // namespace medial
