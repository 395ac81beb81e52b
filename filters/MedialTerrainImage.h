/// \file
/// MedialTerrainImage: the TSK filter's unfolded wall (`WallDistance` over angle x arc length) as 8-bit
/// grey levels for pictures (the CLI's --terrain PNG, the GUI's terrain view).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

class vtkImageData;

namespace medial {

/// The unfolded wall (paper Fig. 15) as grey levels: one row per section, one column per ray angle.
struct TerrainGrey {
  int width = 0;                 ///< ray angles (columns)
  int height = 0;                ///< sections (rows)
  std::vector<uint8_t> pixels;   ///< row-major, the first section on the top row
  std::vector<uint8_t> noWall;   ///< per pixel: 1 where the ray found no wall (its level is 255)
  std::vector<uint8_t> bridged;  ///< per section (row): 1 on a bridge across a gap, where there is no lumen
  double low = 0;                ///< the wall distance (mm) of level 0
  double high = 1;               ///< the wall distance (mm) of level 255
};

///@{
/// The colour pictures give the rows of bridged sections (orange), rays without a wall light grey, else
/// the level through terrainColour.
constexpr uint8_t kBridgedRgb[3] = {255, 140, 0};
constexpr uint8_t kNoWallRgb[3] = {215, 215, 215};
///@}

/// A level's colour on the viridis map (dark violet near the axis - folds, polyps - to yellow far from it):
/// perceptually even, readable in grey print and by colour-blind readers.
void terrainColour(uint8_t level, uint8_t rgb[3]);

/// Pixel `index` of `grey` (row-major) as a picture shows it: bridged, no wall, or the level's colour.
void terrainPixelColour(const TerrainGrey& grey, size_t index, uint8_t rgb[3]);

/// Black = the 2nd percentile of the wall distances, white = the 98th and rays without a wall (a few rays
/// that run far along a bend would otherwise squeeze the haustral folds into a few grey levels). Empty
/// when the image has no finite distance. `bridged` from the image's `Bridged` array (all 0 without it).
TerrainGrey terrainGrey(vtkImageData* terrain);

}  // namespace medial
