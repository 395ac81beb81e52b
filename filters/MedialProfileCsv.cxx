#include "MedialProfileCsv.h"

#include <vtkDataArray.h>
#include <vtkTable.h>

#include <cstdio>

namespace medial {

std::string profileCsv(vtkTable* profile) {
  const char* columns[5] = {"ArcLength", "MinDiameter", "MaxDiameter", "Perimeter", "Area"};
  vtkDataArray* bridged = vtkDataArray::SafeDownCast(profile ? profile->GetColumnByName("Bridged") : nullptr);
  vtkDataArray* arrays[5];
  for (int c = 0; c < 5; ++c) {
    arrays[c] = vtkDataArray::SafeDownCast(profile ? profile->GetColumnByName(columns[c]) : nullptr);
    if (!arrays[c]) return {};
  }
  std::string csv = "arc_length_mm,min_diameter_mm,max_diameter_mm,perimeter_mm,area_mm2,bridged\n";
  char line[256];
  for (vtkIdType row = 0; row < arrays[0]->GetNumberOfTuples(); ++row) {
    std::snprintf(line, sizeof line, "%.3f,%.3f,%.3f,%.3f,%.3f,%d\n", arrays[0]->GetComponent(row, 0),
                  arrays[1]->GetComponent(row, 0), arrays[2]->GetComponent(row, 0),
                  arrays[3]->GetComponent(row, 0), arrays[4]->GetComponent(row, 0),
                  bridged && bridged->GetComponent(row, 0) != 0 ? 1 : 0);
    csv += line;  // NaN (no wall on some ray) is written as "nan"
  }
  return csv;
}

}  // namespace medial
