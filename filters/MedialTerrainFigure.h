/// \file
/// MedialTerrainFigure: the TSK filter's unfolded wall (paper §4, Fig. 15) as a figure a reader can measure
/// on - the wall's distance from the axis on a colour map, the angle around the axis across the top, the
/// arc length down the side, a colour bar in millimetres, and a legend for the bridged gaps and the rays that
/// found no wall. Drawn in memory with FreeType (no display needed): the CLI's --terrain PNG.
#pragma once

#include <vtkSmartPointer.h>

class vtkImageData;

namespace medial {

/// An RGB figure of `terrain` (the filter's output port 2), VTK's y up (what vtkPNGWriter expects), or
/// nullptr when the terrain holds no wall distance.
vtkSmartPointer<vtkImageData> terrainFigure(vtkImageData* terrain);

}  // namespace medial
