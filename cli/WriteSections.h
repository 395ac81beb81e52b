// Writing the TSK filter's sections: the profile table as CSV and the unfolded wall as a PNG.
#pragma once

#include <string>

class vtkImageData;
class vtkTable;

namespace medial::cli {

// CSV with a header (arc_length_mm,min_diameter_mm,max_diameter_mm,perimeter_mm,area_mm2,bridged), one row
// per section (bridged 1: on a bridge across a gap, measures NaN), atomically; throws Failure when it cannot
// be written.
void writeProfileCsv(vtkTable* profile, const std::string& path);

// The `WallDistance` image as a PNG figure (medial::terrainFigure: colour map, angle and arc-length axes,
// colour bar in mm, bridged sections orange), atomically; throws Failure on error.
void writeTerrainPng(vtkImageData* terrain, const std::string& path);

}  // namespace medial::cli
