// MedialTerrainImage: the TSK filter's unfolded wall (`WallDistance` over angle x arc length) as 8-bit
// grey levels for pictures (the CLI's --terrain PNG, the GUI's terrain view).
#pragma once

#include <cstdint>
#include <vector>

class vtkImageData;

namespace medial {

struct TerrainGrey {
  int width = 0, height = 0;    // angles x sections
  std::vector<uint8_t> pixels;  // row-major, the first section on the top row
};

// Black = the 2nd percentile of the wall distances, white = the 98th and rays without a wall (a few rays
// that run far along a bend would otherwise squeeze the haustral folds into a few grey levels). Empty
// when the image has no finite distance.
TerrainGrey terrainGrey(vtkImageData* terrain);

}  // namespace medial
