#include "MedialMeshData.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace medial {

TriangleMesh toTriangleMesh(vtkPolyData* triangles) {
  TriangleMesh mesh;
  mesh.vertices.resize(triangles->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < triangles->GetNumberOfPoints(); ++i) {
    double p[3];
    triangles->GetPoint(i, p);
    mesh.vertices.row(i) << p[0], p[1], p[2];
  }
  mesh.faces.resize(triangles->GetNumberOfPolys(), 3);
  auto ids = vtkSmartPointer<vtkIdList>::New();
  vtkCellArray* polys = triangles->GetPolys();
  Eigen::Index f = 0;
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
    if (ids->GetNumberOfIds() == 3) mesh.faces.row(f++) << int(ids->GetId(0)), int(ids->GetId(1)), int(ids->GetId(2));
  mesh.faces.conservativeResize(f, 3);
  return mesh;
}

}  // namespace medial
