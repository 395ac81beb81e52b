"""The Python package `medial` next to Debian's `vtk`: run with /usr/bin/python3 and
PYTHONPATH=build/lib/python3/dist-packages."""
import os
import sys
import tempfile
import unittest

import vtk
import medial


class MedialPython(unittest.TestCase):
    def test_mesh_topology_filter_in_a_vtk_pipeline(self):
        sphere = vtk.vtkSphereSource()
        sphere.SetThetaResolution(24)
        sphere.SetPhiResolution(12)
        topology = medial.vtkMedialMeshTopology()
        topology.SetInputConnection(sphere.GetOutputPort())
        topology.Update()
        self.assertIsInstance(topology, vtk.vtkPolyDataAlgorithm)
        self.assertTrue(topology.GetClosedManifold())
        self.assertEqual(topology.GetGenus(), 0)
        self.assertEqual(topology.GetEulerCharacteristic(), 2)
        output = topology.GetOutput()
        self.assertEqual(output.GetNumberOfPolys(), sphere.GetOutput().GetNumberOfPolys())
        self.assertEqual(output.GetFieldData().GetArray("Genus").GetValue(0), 0)

    def test_reader_and_skeleton_validator(self):
        data = os.path.join(os.environ.get("MEDIAL_SOURCE_DIR", "."), "data")
        reader = medial.vtkMedialReader()
        reader.SetFileName(os.path.join(data, "skeletons", "hand.swc"))
        validator = medial.vtkMedialSkeletonValidator()
        validator.SetInputConnection(reader.GetOutputPort())
        validator.RequireRadiusOn()
        validator.Update()
        self.assertEqual(validator.GetProblemCount(), 0)
        self.assertGreater(validator.GetOutput().GetNumberOfLines(), 10)
        self.assertIsNotNone(validator.GetOutput().GetPointData().GetArray("NodeType"))

    def test_contraction_skeleton_of_a_torus(self):
        data = os.path.join(os.environ.get("MEDIAL_SOURCE_DIR", "."), "data")
        reader = medial.vtkMedialReader()
        reader.SetFileName(os.path.join(data, "meshes", "torus.off"))
        skeleton = medial.vtkMedialContractionSkeleton()
        skeleton.SetInputConnection(reader.GetOutputPort())
        skeleton.SetTargetNodes(12)
        skeleton.SetSolver("ldlt-amd")
        skeleton.Update()
        out = skeleton.GetOutput(0)
        self.assertGreaterEqual(out.GetNumberOfPoints(), 3)
        self.assertEqual(out.GetNumberOfLines(), out.GetNumberOfPoints())  # one cycle
        self.assertIsNotNone(out.GetPointData().GetArray("Radius"))
        self.assertIsNotNone(skeleton.GetOutput(1).GetPointData().GetArray("SkeletonNode"))

        # Skinning weights and a rig file, as a rigging user would script them.
        skeleton.ComputeWeightsOn()
        skeleton.Update()
        weights = skeleton.GetOutput(1).GetPointData().GetArray("SkinWeights")
        self.assertEqual(weights.GetNumberOfComponents(), out.GetNumberOfLines())
        rig_path = os.path.join(tempfile.mkdtemp(), "torus.glb")
        writer = medial.vtkMedialRigWriter()
        writer.SetFileName(rig_path)
        writer.SetInputConnection(0, skeleton.GetOutputPort(1))
        writer.SetInputConnection(1, skeleton.GetOutputPort(0))
        self.assertEqual(writer.Write(), 1)
        with open(rig_path, "rb") as rig:
            self.assertEqual(rig.read(4), b"glTF")
        # A Z-up mesh in centimetres stands, in metres; an unknown axis is refused.
        writer.SetUpAxis("z")
        writer.SetScale(0.01)
        self.assertEqual(writer.Write(), 1)
        writer.SetUpAxis("up")
        self.assertEqual(writer.Write(), 0)

    def test_sqm_meshes_a_skeleton_file(self):
        reader = medial.vtkMedialReader()
        data = os.path.join(os.environ.get("MEDIAL_SOURCE_DIR", "."), "data")
        reader.SetFileName(os.path.join(data, "skeletons", "figure.vtp"))
        sqm = medial.vtkMedialSQM()
        sqm.SetInputConnection(reader.GetOutputPort())
        sqm.SetSmoothing("averaging")
        sqm.CapsulesOn()
        sqm.Update()
        mesh = sqm.GetOutput()
        self.assertGreater(mesh.GetNumberOfPolys(), 100)
        quads = sum(1 for c in range(mesh.GetNumberOfCells()) if mesh.GetCell(c).GetNumberOfPoints() == 4)
        self.assertGreater(quads, mesh.GetNumberOfCells() // 2)
        self.assertIsNotNone(mesh.GetPointData().GetArray("SkeletonNode"))

    def test_tsk_centerline_of_a_phantom(self):
        data = os.path.join(os.environ.get("MEDIAL_SOURCE_DIR", "."), "data")
        reader = medial.vtkMedialReader()
        reader.SetFileName(os.path.join(data, "volumes", "tubes", "u.nii.gz"))
        centerline = medial.vtkMedialTskCenterline()
        centerline.SetInputConnection(reader.GetOutputPort())
        centerline.SetLabel(1)
        centerline.Update()
        line = centerline.GetOutput()
        self.assertGreater(line.GetNumberOfPoints(), 50)
        arc = line.GetPointData().GetArray("ArcLength")
        self.assertGreater(arc.GetValue(arc.GetNumberOfTuples() - 1), 80.0)  # mm along the U

    def test_bad_file_gives_error_and_empty_output(self):
        reader = medial.vtkMedialReader()
        reader.SetFileName(os.path.join(tempfile.gettempdir(), "does-not-exist.off"))
        messages = []
        reader.AddObserver("ErrorEvent", lambda caller, event: messages.append(event))
        reader.Update()
        self.assertEqual(len(messages), 1)
        self.assertIn("no such file", reader.GetErrorMessage())
        self.assertEqual(reader.GetOutputDataObject(0).GetNumberOfPoints(), 0)


if __name__ == "__main__":
    sys.exit(unittest.main(verbosity=2).result.wasSuccessful() is False)
