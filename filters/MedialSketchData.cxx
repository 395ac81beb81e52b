#include "MedialSketchData.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

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

}  // namespace medial
