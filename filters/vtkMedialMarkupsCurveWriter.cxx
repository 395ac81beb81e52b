#include "vtkMedialMarkupsCurveWriter.h"

#include "MedialFileNames.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

vtkStandardNewMacro(vtkMedialMarkupsCurveWriter);

void vtkMedialMarkupsCurveWriter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "Name: " << this->Name << "\n";
  os << indent << "CoordinateSystem: " << this->CoordinateSystem << "\n";
}

int vtkMedialMarkupsCurveWriter::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace {

// Slicer accepts any markups-schema-v1.x.y; this is the one Slicer 5 writes.
const char* const schema =
    "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/Resources/Schema/"
    "markups-schema-v1.0.3.json#";

// A JSON string literal (names are ours, but a user's Name may hold quotes or backslashes).
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

// JSON has no NaN: a missing value (a section without a wall) is written as 0.
double finite(double value) { return std::isfinite(value) ? value : 0.0; }

// One per-control-point measurement, as Slicer's Extract Centerline writes its Radius.
void writeMeasurement(std::ostream& out, const char* name, const char* units, vtkDataArray* values,
                      vtkIdList* ids) {
  out << ",\n    {\"name\": " << quoted(name) << ", \"enabled\": true, \"units\": " << quoted(units)
      << ", \"printFormat\": \"%5.3f %s\", \"controlPointValues\": [";
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    out << (k ? ", " : "") << finite(values->GetComponent(ids->GetId(k), 0));
  out << "]}";
}

void writeCurve(std::ostream& out, vtkPolyData* input, vtkIdList* ids, const std::string& name,
                const std::string& frame) {
  double length = 0, previous[3] = {0, 0, 0};
  out << "  {\"type\": \"Curve\", \"name\": " << quoted(name) << ", \"coordinateSystem\": " << quoted(frame)
      << ", \"coordinateUnits\": \"mm\", \"locked\": true, \"fixedNumberOfControlPoints\": false,"
      << " \"labelFormat\": \"%N-%d\", \"lastUsedControlPointNumber\": " << ids->GetNumberOfIds()
      << ",\n   \"controlPoints\": [\n";
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
    double p[3];
    input->GetPoint(ids->GetId(k), p);
    if (k) length += std::sqrt(vtkMath::Distance2BetweenPoints(p, previous));
    std::copy(p, p + 3, previous);
    out << "    {\"id\": \"" << k + 1 << "\", \"label\": " << quoted(name + "-" + std::to_string(k + 1))
        << ", \"position\": [" << p[0] << ", " << p[1] << ", " << p[2]
        << "], \"orientation\": [-1.0, -0.0, -0.0, -0.0, -1.0, -0.0, 0.0, 0.0, 1.0], \"selected\": true,"
        << " \"locked\": true, \"visibility\": true, \"positionStatus\": \"defined\"}"
        << (k + 1 < ids->GetNumberOfIds() ? ",\n" : "\n");
  }
  out << "   ],\n   \"measurements\": [\n    {\"name\": \"length\", \"enabled\": true, \"value\": " << length
      << ", \"units\": \"mm\", \"printFormat\": \"%-#4.4g%s\"}";
  if (vtkDataArray* radius = input->GetPointData()->GetArray("Radius"))
    writeMeasurement(out, "Radius", "mm", radius, ids);
  if (vtkDataArray* bridged = input->GetPointData()->GetArray("Bridged"))
    writeMeasurement(out, "Bridged", "", bridged, ids);
  out << "\n   ],\n   \"display\": {\"visibility\": true, \"opacity\": 1.0, \"color\": [0.4, 1.0, 1.0],"
      << " \"selectedColor\": [1.0, 0.5, 0.5], \"propertiesLabelVisibility\": true,"
      << " \"pointLabelsVisibility\": false, \"glyphScale\": 1.0, \"lineThickness\": 0.5}}";
}

}  // namespace

void vtkMedialMarkupsCurveWriter::WriteData() {
  this->SetErrorCode(this->WriteCurves() ? vtkErrorCode::NoError : vtkErrorCode::UserError);
}

bool vtkMedialMarkupsCurveWriter::WriteCurves() {
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  if (this->FileName.empty()) {
    vtkErrorMacro(<< "no file name given");
    return false;
  }
  if (this->CoordinateSystem != "LPS" && this->CoordinateSystem != "RAS") {
    vtkErrorMacro(<< this->FileName << ": CoordinateSystem is LPS or RAS, not '" << this->CoordinateSystem
                  << "'");
    return false;
  }
  if (!input || !input->GetLines() || input->GetLines()->GetNumberOfCells() == 0) {
    vtkErrorMacro(<< this->FileName << ": "
                  << (input ? "the input has no polyline to write as a curve" : "no input"));
    return false;
  }
  std::ostringstream text;
  text << std::setprecision(10) << "{\"@schema\": " << quoted(schema) << ",\n \"markups\": [\n";
  auto ids = vtkSmartPointer<vtkIdList>::New();
  vtkCellArray* lines = input->GetLines();
  for (vtkIdType cell = 0; cell < lines->GetNumberOfCells(); ++cell) {
    lines->GetCellAtId(cell, ids);
    const std::string name = cell == 0 ? this->Name : this->Name + " branch " + std::to_string(cell);
    if (cell) text << ",\n";
    writeCurve(text, input, ids, name, this->CoordinateSystem);
  }
  text << "\n ]\n}\n";
  const auto write = [&text](const std::string& temporary, std::string& why) {
    std::ofstream out(temporary);
    if (!(out << text.str()) || !out.flush()) why = "cannot write the file (disk full or no permission?)";
    return why.empty();
  };
  std::string error;
  if (!medial::writeAtomically(this->FileName, write, error)) {
    vtkErrorMacro(<< this->FileName << ": " << error);
    return false;
  }
  return true;
}
