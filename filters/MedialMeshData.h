/// \file
/// Conversions between VTK polygonal meshes and the plain meshes of src/, both ways: the one place where
/// filters, writers and tests turn a vtkPolyData into vertices and faces and back
/// (docs/ARCHITECTURE.md §4).
#pragma once

#include "mesh/TriangleMesh.h"

#include <vtkSmartPointer.h>

#include <Eigen/Dense>

#include <cstdint>
#include <vector>

class vtkDataArray;
class vtkDoubleArray;
class vtkIntArray;
class vtkPolyData;

namespace medial {

/// `mesh`'s polygons and strips as triangles, its point data kept (vertices and lines left out).
vtkSmartPointer<vtkPolyData> triangulated(vtkPolyData* mesh);

/// The points and the triangles of `triangles` (other cells are skipped: triangulate first).
TriangleMesh toTriangleMesh(vtkPolyData* triangles);

/// The points of `mesh`.
std::vector<Eigen::Vector3d> pointsOf(vtkPolyData* mesh);

/// The polygons of `mesh` as lists of point ids, then its triangle strips split into triangles (every
/// second one turned, so that all keep the strip's orientation). Lines and vertices are skipped.
std::vector<std::vector<int64_t>> polygonsOf(vtkPolyData* mesh);

/// A polydata of triangles.
vtkSmartPointer<vtkPolyData> polyDataFromMesh(const TriangleMesh& mesh);

/// A polydata of polygons (quads, triangles, any size), as they are: no triangulation.
vtkSmartPointer<vtkPolyData> polyDataFromPolygons(const std::vector<Eigen::Vector3d>& vertices,
                                                  const std::vector<std::vector<int>>& faces);

///@{
/// A named array with one value per element of `values` (point data, cell data or a table column).
vtkSmartPointer<vtkIntArray> intArray(const char* name, const std::vector<int>& values);
vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const std::vector<double>& values);
///@}
/// One tuple per row of `rows`, one component per column (skinning weights: a vertex's weight per bone).
vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const Eigen::MatrixXd& rows);
/// The array's tuples as the rows of a matrix.
Eigen::MatrixXd matrixFromArray(vtkDataArray* array);

}  // namespace medial
