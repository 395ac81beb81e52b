// The polygons of a vtkPolyData as lists of point ids, the form computeMeshTopology and the tests' CGAL
// meshes take.
#pragma once

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <vector>

namespace medial::test {

inline std::vector<std::vector<int64_t>> polygonsOf(vtkPolyData* mesh) {
  std::vector<std::vector<int64_t>> faces;
  auto ids = vtkSmartPointer<vtkIdList>::New();
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(ids);) {
    faces.emplace_back();
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) faces.back().push_back(ids->GetId(k));
  }
  return faces;
}

}  // namespace medial::test
