// NodeColours: an object's mesh coloured by an integer label per point (its skeleton node, part or
// cluster), distinct colours for neighbouring ids.
#pragma once

#include <vtkSmartPointer.h>

class vtkActor;
class vtkLookupTable;

namespace medial::gui {

// Distinct colours for ids 0..count-1 (golden-ratio hues), so that neighbouring ids differ.
vtkSmartPointer<vtkLookupTable> segmentColours(int count);

// Colours `actor` by its input's point array `name` (ids 0..count-1); false when the actor has no mapper.
bool colourByLabel(vtkActor* actor, const char* name, int count);

}  // namespace medial::gui
