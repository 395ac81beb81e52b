#include "MedialSketchData.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

namespace medial {

bool isSketch(vtkPolyData* polyData) {
  vtkDataArray* placement = polyData ? polyData->GetCellData()->GetArray("Placement") : nullptr;
  return placement && placement->GetNumberOfComponents() == 16 && polyData->GetNumberOfLines() > 0;
}

vtkSmartPointer<vtkPolyData> placedStrokes(vtkPolyData* sketch) {
  auto placed = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  vtkDataArray* placement = sketch->GetCellData()->GetArray("Placement");
  auto ids = vtkSmartPointer<vtkIdList>::New();
  vtkCellArray* strokes = sketch->GetLines();
  vtkIdType cell = 0;
  for (strokes->InitTraversal(); strokes->GetNextCell(ids); ++cell) {
    Placement m = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    if (placement && placement->GetNumberOfComponents() == 16) placement->GetTuple(cell, m.data());
    lines->InsertNextCell(ids->GetNumberOfIds());
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      double p[3];
      sketch->GetPoint(ids->GetId(k), p);  // (x, y) in the stroke's plane; z is ignored
      lines->InsertCellPoint(points->InsertNextPoint(m[0] * p[0] + m[1] * p[1] + m[3],
                                                     m[4] * p[0] + m[5] * p[1] + m[7],
                                                     m[8] * p[0] + m[9] * p[1] + m[11]));
    }
  }
  placed->SetPoints(points);
  placed->SetLines(lines);
  return placed;
}

namespace {

using Matrix4 = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;

bool hasPart(vtkPolyData* sketch, int part) {
  return isSketch(sketch) && part >= 0 && part < sketch->GetNumberOfLines();
}

Matrix4 placementOf(vtkPolyData* sketch, int part) {
  Matrix4 m;
  sketch->GetCellData()->GetArray("Placement")->GetTuple(part, m.data());
  return m;
}

void setPlacement(vtkPolyData* sketch, int part, const Matrix4& m) {
  sketch->GetCellData()->GetArray("Placement")->SetTuple(part, m.data());
  sketch->GetCellData()->GetArray("Placement")->Modified();
  sketch->Modified();
}

// The part's line cell: its points' ids.
vtkSmartPointer<vtkIdList> strokeIds(vtkPolyData* sketch, int part) {
  auto ids = vtkSmartPointer<vtkIdList>::New();
  vtkCellArray* lines = sketch->GetLines();
  lines->InitTraversal();
  for (int k = 0; k <= part; ++k) lines->GetNextCell(ids);
  return ids;
}

// About a point: translate it to the origin, apply `linear`, translate back.
Matrix4 about(const Eigen::Vector3d& centre, const Eigen::Matrix3d& linear) {
  Matrix4 t = Matrix4::Identity();
  t.topLeftCorner<3, 3>() = linear;
  t.topRightCorner<3, 1>() = centre - linear * centre;
  return t;
}

}  // namespace

std::array<double, 3> partCentroid(vtkPolyData* sketch, int part) {
  if (!hasPart(sketch, part)) return {0, 0, 0};
  const Matrix4 m = placementOf(sketch, part);
  const auto ids = strokeIds(sketch, part);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
    double p[3];
    sketch->GetPoint(ids->GetId(k), p);
    sum += (m * Eigen::Vector4d(p[0], p[1], 0, 1)).head<3>();
  }
  sum /= double(std::max<vtkIdType>(ids->GetNumberOfIds(), 1));
  return {sum.x(), sum.y(), sum.z()};
}

double sketchSize(vtkPolyData* sketch) { return isSketch(sketch) ? placedStrokes(sketch)->GetLength() : 0.0; }

bool movePart(vtkPolyData* sketch, int part, const std::array<double, 3>& offset) {
  if (!hasPart(sketch, part)) return false;
  Matrix4 m = placementOf(sketch, part);
  m.topRightCorner<3, 1>() += Eigen::Vector3d(offset[0], offset[1], offset[2]);
  setPlacement(sketch, part, m);
  return true;
}

bool turnPart(vtkPolyData* sketch, int part, double degrees) {
  if (!hasPart(sketch, part)) return false;
  const Matrix4 m = placementOf(sketch, part);
  const auto c = partCentroid(sketch, part);
  const Eigen::Vector3d normal = m.block<3, 1>(0, 2).normalized();
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(degrees * M_PI / 180, normal).toRotationMatrix();
  setPlacement(sketch, part, about({c[0], c[1], c[2]}, turn) * m);
  return true;
}

bool scalePart(vtkPolyData* sketch, int part, double factor) {
  if (!hasPart(sketch, part) || !(factor > 0)) return false;
  const auto c = partCentroid(sketch, part);
  setPlacement(sketch, part,
               about({c[0], c[1], c[2]}, factor * Eigen::Matrix3d::Identity()) * placementOf(sketch, part));
  return true;
}

int mirrorPart(vtkPolyData* sketch, int part, int planePart) {
  if (!hasPart(sketch, part) || !hasPart(sketch, planePart)) return -1;
  const Matrix4 plane = placementOf(sketch, planePart);
  const Eigen::Vector3d normal = plane.block<3, 1>(0, 2).normalized(), origin = plane.block<3, 1>(0, 3);
  const Eigen::Matrix3d reflection = Eigen::Matrix3d::Identity() - 2 * normal * normal.transpose();
  const Matrix4 mirrored = about(origin, reflection) * placementOf(sketch, part);
  // The stroke's points again, as a new line cell with the mirrored placement.
  const auto ids = strokeIds(sketch, part);
  vtkPoints* points = sketch->GetPoints();
  auto copy = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    copy->InsertNextId(points->InsertNextPoint(points->GetPoint(ids->GetId(k))));
  sketch->GetLines()->InsertNextCell(copy);
  vtkCellData* cellData = sketch->GetCellData();
  for (int a = 0; a < cellData->GetNumberOfArrays(); ++a)  // other cell data: the part's values again
    if (vtkDataArray* array = cellData->GetArray(a);
        array && std::string(array->GetName() ? array->GetName() : "") != "Placement")
      array->InsertNextTuple(part, array);
  cellData->GetArray("Placement")->InsertNextTuple(mirrored.data());
  points->Modified();
  sketch->GetLines()->Modified();
  sketch->Modified();
  return int(sketch->GetNumberOfLines()) - 1;
}

}  // namespace medial
