/// \file
/// The actor that draws a skeleton as tubes and balls: each edge a truncated cone between its nodes' radii,
/// each node a sphere. Shared by vtkMedialScene and the GUI's skeleton editor (which changes the polydata in
/// place as the user drags).
#pragma once

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;

namespace medial {

/// `skeleton`: points, 2-point lines and point scalars holding each node's drawn radius. `sides` around a
/// tube (and a ball's circle).
vtkSmartPointer<vtkActor> skeletonTubesActor(vtkPolyData* skeleton, int sides);

}  // namespace medial
