// PlacedStrokes: a sketch's strokes where they lie in 3-D: each line cell's points (x, y, 0 in its own
// plane) moved by the cell's row-major 4x4 `Placement` (the format of vtkMedialSketchReader and of the
// strokes drawn in the 3-D view), for display.
#pragma once

#include <vtkSmartPointer.h>

#include <array>

class vtkPolyData;

namespace medial::gui {

using Placement = std::array<double, 16>;  // row-major 4x4

vtkSmartPointer<vtkPolyData> placedStrokes(vtkPolyData* sketch);

}  // namespace medial::gui
