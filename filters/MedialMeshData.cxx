#include "MedialMeshData.h"

#include <algorithm>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

namespace medial {

namespace {

vtkSmartPointer<vtkPoints> doublePoints() {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  return points;
}

}  // namespace

vtkSmartPointer<vtkPolyData> triangulated(vtkPolyData* mesh) {
  auto triangulate = vtkSmartPointer<vtkTriangleFilter>::New();
  triangulate->SetInputData(mesh);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  return triangulate->GetOutput();
}

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
    if (ids->GetNumberOfIds() == 3)
      mesh.faces.row(f++) << int(ids->GetId(0)), int(ids->GetId(1)), int(ids->GetId(2));
  mesh.faces.conservativeResize(f, 3);
  return mesh;
}

std::vector<Eigen::Vector3d> pointsOf(vtkPolyData* mesh) {
  std::vector<Eigen::Vector3d> points(size_t(mesh->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) mesh->GetPoint(i, points[size_t(i)].data());
  return points;
}

std::vector<std::vector<int64_t>> polygonsOf(vtkPolyData* mesh) {
  std::vector<std::vector<int64_t>> faces;
  faces.reserve(size_t(mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips()));
  auto ids = vtkSmartPointer<vtkIdList>::New();
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(ids);) faces.emplace_back(ids->begin(), ids->end());
  vtkCellArray* strips = mesh->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(ids);)
    for (vtkIdType k = 0; k + 2 < ids->GetNumberOfIds(); ++k) {  // strip triangle k, alternately turned
      if (k % 2 == 0)
        faces.push_back({ids->GetId(k), ids->GetId(k + 1), ids->GetId(k + 2)});
      else
        faces.push_back({ids->GetId(k + 1), ids->GetId(k), ids->GetId(k + 2)});
    }
  return faces;
}

vtkSmartPointer<vtkPolyData> polyDataFromMesh(const TriangleMesh& mesh) {
  auto points = doublePoints();
  points->SetNumberOfPoints(mesh.vertices.rows());
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    points->SetPoint(v, mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    const vtkIdType ids[3] = {mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2)};
    triangles->InsertNextCell(3, ids);
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(triangles);
  return polyData;
}

vtkSmartPointer<vtkPolyData> polyDataFromPolygons(const std::vector<Eigen::Vector3d>& vertices,
                                                  const std::vector<std::vector<int>>& faces) {
  auto points = doublePoints();
  points->SetNumberOfPoints(vtkIdType(vertices.size()));
  for (size_t v = 0; v < vertices.size(); ++v) points->SetPoint(vtkIdType(v), vertices[v].data());
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& face : faces) {
    polys->InsertNextCell(vtkIdType(face.size()));
    for (int v : face) polys->InsertCellPoint(v);
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(polys);
  return polyData;
}

namespace {

template <class Array, class Value>
vtkSmartPointer<Array> namedArray(const char* name, const std::vector<Value>& values) {
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  array->SetNumberOfValues(vtkIdType(values.size()));
  for (size_t i = 0; i < values.size(); ++i) array->SetValue(vtkIdType(i), values[i]);
  return array;
}

}  // namespace

vtkSmartPointer<vtkIntArray> intArray(const char* name, const std::vector<int>& values) {
  return namedArray<vtkIntArray>(name, values);
}

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const std::vector<double>& values) {
  return namedArray<vtkDoubleArray>(name, values);
}

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const Eigen::MatrixXd& rows) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(int(std::max<Eigen::Index>(rows.cols(), 1)));
  array->SetNumberOfTuples(rows.rows());
  for (Eigen::Index row = 0; row < rows.rows(); ++row)
    for (Eigen::Index column = 0; column < rows.cols(); ++column)
      array->SetTypedComponent(row, int(column), rows(row, column));
  return array;
}

Eigen::MatrixXd matrixFromArray(vtkDataArray* array) {
  Eigen::MatrixXd rows(array->GetNumberOfTuples(), array->GetNumberOfComponents());
  for (vtkIdType row = 0; row < array->GetNumberOfTuples(); ++row)
    for (int column = 0; column < array->GetNumberOfComponents(); ++column)
      rows(row, column) = array->GetComponent(row, column);
  return rows;
}

}  // namespace medial
