#include "vtkMedialSketchReader.h"

#include "MedialTextFile.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <vector>

vtkStandardNewMacro(vtkMedialSketchReader);

vtkMedialSketchReader::vtkMedialSketchReader() { this->SetNumberOfInputPorts(0); }

void vtkMedialSketchReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}

namespace {

struct Part {
  std::vector<std::array<double, 2>> points;
  std::vector<std::array<double, 4>> matrixRows;
  int firstLine = 0;
};

}  // namespace

int vtkMedialSketchReader::RequestData(vtkInformation*, vtkInformationVector**,
                                       vtkInformationVector* outputVector) {
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  medial::TextFile file;
  std::string error;
  if (!file.open(this->FileName, error)) {
    vtkErrorMacro(<< error);
    return 0;
  }
  std::vector<Part> parts(1);
  std::string text;
  std::vector<double> numbers;
  while (file.nextLine(text)) {
    const int lineNumber = file.lineNumber();
    if (text.find_first_not_of(" \t\r,") == std::string::npos) {
      if (!parts.back().points.empty()) parts.emplace_back();  // a blank line ends a part
      continue;
    }
    for (char& c : text)
      if (c == ',') c = ' ';
    Part& part = parts.back();
    const std::string where = file.where();
    if (!medial::parseNumbers(text, numbers) || (numbers.size() != 2 && numbers.size() != 4)) {
      vtkErrorMacro(
          << where << "expected 'x y' (a stroke point) or four numbers (a row of the placement matrix), got '"
          << text << "'");
      return 0;
    }
    if (part.points.empty()) part.firstLine = lineNumber;
    if (numbers.size() == 2) {
      if (!part.matrixRows.empty()) {
        vtkErrorMacro(<< where
                      << "a stroke point after the placement matrix; separate parts with a blank line");
        return 0;
      }
      part.points.push_back({numbers[0], numbers[1]});
    } else {
      if (part.points.empty()) {
        vtkErrorMacro(<< where << "a placement matrix row before any stroke point");
        return 0;
      }
      if (part.matrixRows.size() == 4) {
        vtkErrorMacro(<< where << "a fifth placement matrix row (the matrix is 4x4)");
        return 0;
      }
      part.matrixRows.push_back({numbers[0], numbers[1], numbers[2], numbers[3]});
    }
  }
  if (parts.back().points.empty()) parts.pop_back();
  if (parts.empty()) {
    vtkErrorMacro(<< this->FileName << ": no stroke (the file needs 'x y' lines)");
    return 0;
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto placement = vtkSmartPointer<vtkDoubleArray>::New();
  placement->SetName("Placement");
  placement->SetNumberOfComponents(16);
  for (const Part& part : parts) {
    if (!part.matrixRows.empty() && part.matrixRows.size() != 4) {
      vtkErrorMacro(<< this->FileName << ":" << part.firstLine << ": the part's placement matrix has "
                    << part.matrixRows.size() << " rows instead of 4");
      return 0;
    }
    const vtkIdType first = points->GetNumberOfPoints();
    for (const auto& p : part.points) points->InsertNextPoint(p[0], p[1], 0.0);
    lines->InsertNextCell(vtkIdType(part.points.size() + 1));
    for (vtkIdType i = 0; i < vtkIdType(part.points.size()); ++i) lines->InsertCellPoint(first + i);
    lines->InsertCellPoint(first);
    double matrix[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (size_t r = 0; r < part.matrixRows.size(); ++r)
      for (int c = 0; c < 4; ++c) matrix[4 * r + c] = part.matrixRows[r][c];
    placement->InsertNextTuple(matrix);
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetCellData()->AddArray(placement);
  return 1;
}
