#include "WriteSections.h"

#include "CommandLine.h"

#include "MedialFileNames.h"
#include "MedialTerrainFigure.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkUnsignedCharArray.h>

#include <cstdio>
#include <fstream>
#include <functional>

namespace medial::cli {

namespace {

// Writes `path` atomically (no partial or temporary file left on failure), or throws Failure.
void writeOrFail(const std::string& path,
                 const std::function<bool(const std::string&, std::string&)>& write) {
  std::string error;
  if (!medial::writeAtomically(path, write, error)) throw Failure(path + ": " + error);
}

}  // namespace

void writeProfileCsv(vtkTable* profile, const std::string& path) {
  const char* columns[5] = {"ArcLength", "MinDiameter", "MaxDiameter", "Perimeter", "Area"};
  vtkDataArray* bridged = vtkDataArray::SafeDownCast(profile ? profile->GetColumnByName("Bridged") : nullptr);
  vtkDataArray* arrays[5];
  for (int c = 0; c < 5; ++c) {
    arrays[c] = vtkDataArray::SafeDownCast(profile ? profile->GetColumnByName(columns[c]) : nullptr);
    if (!arrays[c]) throw Failure(path + ": the centerline filter gave no profile");
  }
  writeOrFail(path, [&](const std::string& temporary, std::string& error) {
    std::ofstream out(temporary);
    if (!out) {
      error = "cannot create the file";
      return false;
    }
    out << "arc_length_mm,min_diameter_mm,max_diameter_mm,perimeter_mm,area_mm2,bridged\n";
    char line[256];
    for (vtkIdType row = 0; row < arrays[0]->GetNumberOfTuples(); ++row) {
      std::snprintf(line, sizeof line, "%.3f,%.3f,%.3f,%.3f,%.3f,%d\n", arrays[0]->GetComponent(row, 0),
                    arrays[1]->GetComponent(row, 0), arrays[2]->GetComponent(row, 0),
                    arrays[3]->GetComponent(row, 0), arrays[4]->GetComponent(row, 0),
                    bridged && bridged->GetComponent(row, 0) != 0 ? 1 : 0);
      out << line;  // NaN (no wall on some ray) is written as "nan"
    }
    if (!out.flush()) error = "cannot write the file";
    return error.empty();
  });
}

void writeTerrainPng(vtkImageData* terrain, const std::string& path) {
  const vtkSmartPointer<vtkImageData> image = medial::terrainFigure(terrain);
  if (!image) throw Failure(path + ": no wall was found along the centerline");
  writeOrFail(path, [&](const std::string& temporary, std::string& error) {
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetInputData(image);
    writer->SetFileName(temporary.c_str());
    writer->Write();
    if (writer->GetErrorCode() != 0) error = "cannot write the image";
    return error.empty();
  });
}

}  // namespace medial::cli
