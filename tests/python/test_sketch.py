"""The sketch filter from Python: `import medial`, read the hand stroke, skeleton and inflated mesh, then SQM."""
import os
import sys

import medial
import vtk

source = os.environ["MEDIAL_SOURCE_DIR"]
reader = medial.vtkMedialSketchReader()
reader.SetFileName(os.path.join(source, "data", "sketches", "hand.txt"))
sketch = medial.vtkMedialSketchSkeleton()
sketch.SetInputConnection(reader.GetOutputPort())
sketch.SetSimplificationThreshold(10.0)
sqm = medial.vtkMedialSQM()
sqm.SetInputConnection(sketch.GetOutputPort(0))
sqm.Update()

skeleton = sketch.GetOutput(0)
types = skeleton.GetPointData().GetArray("NodeType")
leaves = sum(1 for i in range(types.GetNumberOfTuples()) if types.GetValue(i) == 0)
if leaves != 6:
    sys.exit("expected 6 leaves (five fingers and the wrist), got %d" % leaves)
if sketch.GetOutput(1).GetNumberOfPolys() == 0 or sqm.GetOutput().GetNumberOfPolys() == 0:
    sys.exit("no inflated mesh or no SQM mesh")

# Bad input: an error, empty output, no exception.
bad = vtk.vtkPolyData()
failing = medial.vtkMedialSketchSkeleton()
failing.SetInputData(bad)
failing.GlobalWarningDisplayOff()
failing.Update()
if failing.GetOutput(0).GetNumberOfPoints() != 0:
    sys.exit("an empty input should give an empty output")
print("sketch from Python: %d nodes, %d leaves" % (skeleton.GetNumberOfPoints(), leaves))
