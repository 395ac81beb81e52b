/// \file
/// MedialProfileCsv: the TSK filter's profile table (output port 1) as CSV, for the CLI's --profile and the
/// GUI's profile export.
#pragma once

#include <string>

class vtkTable;

namespace medial {

/// A header (arc_length_mm,min_diameter_mm,max_diameter_mm,perimeter_mm,area_mm2,bridged) and one row per
/// section (bridged 1: on a bridge across a gap, its measures "nan"); empty when `profile` lacks a column.
std::string profileCsv(vtkTable* profile);

}  // namespace medial
