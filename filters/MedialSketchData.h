/// \file
/// A sketch as VTK data: closed 2-D strokes as line cells with cell data `Placement`, as
/// vtkMedialSketchReader reads them and the GUI draws them (docs/ARCHITECTURE.md §4). placedStrokes gives the
/// strokes where they lie in 3-D: each line cell's points (x, y, 0 in its own plane) moved by the cell's
/// row-major 4x4 `Placement` (the format of vtkMedialSketchReader and of the strokes drawn in the 3-D view),
/// for display.
#pragma once

#include <vtkSmartPointer.h>

#include <array>

class vtkPolyData;

namespace medial {

using Placement = std::array<double, 16>;  ///< row-major 4x4

/// True for a polydata of strokes (line cells with a 16-component `Placement` cell array).
bool isSketch(vtkPolyData* polyData);

/// The strokes of a sketch polydata placed in 3-D by their `Placement` matrices.
vtkSmartPointer<vtkPolyData> placedStrokes(vtkPolyData* sketch);

///@{
/// Modelling a sketch by parts (the sketch paper's §3.2 and §4.1: parts placed, turned and mirrored in
/// 3-D). Each changes `sketch` in place (Modified) and returns false, changing nothing, for a part that
/// does not exist. Turning and scaling are about the part's centroid; a turn is about its plane's normal.
bool movePart(vtkPolyData* sketch, int part, const std::array<double, 3>& offset);
bool turnPart(vtkPolyData* sketch, int part, double degrees);
bool scalePart(vtkPolyData* sketch, int part, double factor);
///@}
/// Appends a copy of `part` mirrored across the drawing plane of `planePart` (the body's plane: draw one
/// half, get both). Returns the new part's index, or -1.
int mirrorPart(vtkPolyData* sketch, int part, int planePart);
///@{
/// The centroid of a part's stroke in 3-D, and the sketch's size (its placed strokes' diagonal).
std::array<double, 3> partCentroid(vtkPolyData* sketch, int part);
double sketchSize(vtkPolyData* sketch);
///@}

}  // namespace medial
