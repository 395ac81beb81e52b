// A sketch as VTK data: closed 2-D strokes as line cells with cell data `Placement`, as vtkMedialSketchReader
// reads them and the GUI draws them (docs/ARCHITECTURE.md §4). placedStrokes gives the strokes where they
// lie in 3-D: each line cell's points (x, y, 0 in its own
// plane) moved by the cell's row-major 4x4 `Placement` (the format of vtkMedialSketchReader and of the
// strokes drawn in the 3-D view), for display.
#pragma once

#include <vtkSmartPointer.h>

#include <array>

class vtkPolyData;

namespace medial {

using Placement = std::array<double, 16>;  // row-major 4x4

// True for a polydata of strokes (line cells with a 16-component `Placement` cell array).
bool isSketch(vtkPolyData* polyData);

vtkSmartPointer<vtkPolyData> placedStrokes(vtkPolyData* sketch);

}  // namespace medial
