// Conversions between VTK polygonal meshes and the plain TriangleMesh of src/.
#pragma once

#include "mesh/TriangleMesh.h"

class vtkPolyData;

namespace medial {

// The points and the triangles of `triangles` (other cells are skipped: triangulate first).
TriangleMesh toTriangleMesh(vtkPolyData* triangles);

}  // namespace medial
