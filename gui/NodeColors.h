// NodeColors: an object's mesh colored by an integer label per point (its skeleton node, part or
// cluster), distinct colors for neighbouring ids.
#pragma once

#include <vtkSmartPointer.h>

class vtkActor;
class vtkLookupTable;

namespace medial::gui {

// Distinct colors for ids 0..count-1 (golden-ratio hues), so that neighbouring ids differ.
vtkSmartPointer<vtkLookupTable> segmentColors(int count);

// Colors `actor` by its input's point array `name` (ids 0..count-1); false when the actor has no mapper.
bool colorByLabel(vtkActor* actor, const char* name, int count);

}  // namespace medial::gui
