"""The sketch filter from Python: `import medial`, read the hand strokes through vtkMedialReader, skeleton and
inflated mesh, then SQM; bad input gives an error and an empty output, never an exception."""
import os
import unittest

import vtk
import medial

SKETCHES = os.path.join(os.environ.get("MEDIAL_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")),
                        "data", "sketches")


def watch_errors(algorithm):
    """The messages of the ErrorEvents (what vtkErrorMacro reports) `algorithm` fires from now on. With an
    observer the message goes to it instead of the terminal. (GlobalWarningDisplayOff would silence the
    event itself.)"""
    messages = []

    def on_error(caller, event, message):
        messages.append(message)
    on_error.CallDataType = vtk.VTK_STRING
    algorithm.AddObserver("ErrorEvent", on_error)
    return messages


class SketchFromPython(unittest.TestCase):
    def test_hand_gives_six_leaves_a_mesh_and_an_sqm_mesh(self):
        reader = medial.vtkMedialReader()
        reader.SetFileName(os.path.join(SKETCHES, "hand.txt"))
        sketch = medial.vtkMedialSketchSkeleton()
        sketch.SetInputConnection(reader.GetOutputPort())
        sketch.SetSimplificationThreshold(10.0)
        sqm = medial.vtkMedialSQM()
        sqm.SetInputConnection(sketch.GetOutputPort(0))
        sqm.Update()
        skeleton = sketch.GetOutput(0)
        types = skeleton.GetPointData().GetArray("NodeType")
        leaves = sum(1 for i in range(types.GetNumberOfTuples()) if types.GetValue(i) == 0)
        self.assertEqual(leaves, 6, "five fingers and the wrist")
        self.assertGreater(sketch.GetOutput(1).GetNumberOfPolys(), 0, "the inflated mesh")
        self.assertGreater(sqm.GetOutput().GetNumberOfPolys(), 0, "the SQM mesh")

    def test_bird_is_one_watertight_mesh_bound_to_its_skeleton(self):
        """The character pipeline from Python: sketch -> one mesh -> skin binding -> rig file; and the steps."""
        reader = medial.vtkMedialReader()
        reader.SetFileName(os.path.join(SKETCHES, "bird.txt"))
        sketch = medial.vtkMedialSketchSkeleton()
        sketch.SetInputConnection(reader.GetOutputPort())
        sketch.RecordStagesOn()
        binding = medial.vtkMedialSkinBinding()
        binding.SetInputConnection(0, sketch.GetOutputPort(1))
        binding.SetSkeletonConnection(sketch.GetOutputPort(0))
        binding.Update()
        regions = vtk.vtkPolyDataConnectivityFilter()
        regions.SetInputData(sketch.GetOutput(1))
        regions.SetExtractionModeToAllRegions()
        regions.Update()
        self.assertEqual(regions.GetNumberOfExtractedRegions(), 1, "body and wings joined")
        weights = binding.GetOutput(0).GetPointData().GetArray("SkinWeights")
        self.assertEqual(weights.GetNumberOfTuples(), sketch.GetOutput(1).GetNumberOfPoints())
        self.assertEqual(binding.GetNodesOutside(), 0)
        self.assertIsNotNone(sketch.GetStageSkeleton("straight-skeleton"))

    def test_input_without_strokes_is_an_error_with_empty_outputs(self):
        failing = medial.vtkMedialSketchSkeleton()
        failing.SetInputData(vtk.vtkPolyData())
        errors = watch_errors(failing)
        failing.Update()
        self.assertEqual(len(errors), 1, "one error reported")
        self.assertIn("no stroke", errors[0])
        self.assertEqual(failing.GetOutput(0).GetNumberOfPoints(), 0)
        self.assertEqual(failing.GetOutput(1).GetNumberOfPoints(), 0)

    def test_a_stroke_that_crosses_itself_is_an_error(self):
        bowtie = vtk.vtkPolyData()
        points = vtk.vtkPoints()
        for x, y in [(0, 0), (100, 100), (100, 0), (0, 100)]:
            points.InsertNextPoint(x, y, 0)
        lines = vtk.vtkCellArray()
        lines.InsertNextCell(5, [0, 1, 2, 3, 0])
        bowtie.SetPoints(points)
        bowtie.SetLines(lines)
        failing = medial.vtkMedialSketchSkeleton()
        failing.SetInputData(bowtie)
        errors = watch_errors(failing)
        failing.Update()
        self.assertEqual(len(errors), 1)
        self.assertEqual(failing.GetOutput(0).GetNumberOfPoints(), 0)


if __name__ == "__main__":
    unittest.main()
