"""The TSK centerline from Python: a branching tree (one polyline per branch), the sections' profile table and
the unfolded wall on ports 1 and 2, the centering option, and the 3D Slicer markups curves, all on the bundled
phantoms."""
import json
import os
import tempfile
import unittest

import numpy as np

import medial
from vtk.util import numpy_support

SOURCE = os.environ.get("MEDIAL_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
TUBES = os.path.join(SOURCE, "data", "volumes", "tubes")


def centerline(name, **options):
    reader = medial.vtkMedialReader()
    reader.SetFileName(os.path.join(TUBES, name + ".nii.gz"))
    tsk = medial.vtkMedialTskCenterline()
    tsk.SetInputConnection(reader.GetOutputPort())
    tsk.SetLabel(1)
    for key, value in options.items():
        getattr(tsk, "Set" + key)(value)
    tsk.Update()
    return tsk


def cell_ids(polydata, cell):
    ids = polydata.GetCell(cell).GetPointIds()
    return [ids.GetId(k) for k in range(ids.GetNumberOfIds())]


class CenterlineFromPython(unittest.TestCase):
    def test_tree_gives_one_polyline_per_branch_and_one_root(self):
        tree = centerline("tree", DetectBranches=True).GetOutput()
        self.assertEqual(tree.GetNumberOfLines(), 5)
        parents = numpy_support.vtk_to_numpy(tree.GetCellData().GetArray("ParentBranch"))
        self.assertEqual(parents.tolist().count(-1), 1)

    def test_sections_profile_and_unfolded_wall(self):
        u = centerline("u", ComputeSections=True, SectionSpacing=2.0)
        profile, terrain = u.GetOutputDataObject(1), u.GetOutputDataObject(2)
        # The mean of the min and max diameter of the middle sections (the U's radius is 5 mm; the minimum
        # alone runs about 1 mm low on the voxel staircase).
        low = numpy_support.vtk_to_numpy(profile.GetColumnByName("MinDiameter"))
        high = numpy_support.vtk_to_numpy(profile.GetColumnByName("MaxDiameter"))
        quarter = len(low) // 4
        middle = 0.5 * (low + high)[quarter: 3 * quarter]
        self.assertTrue(9.3 < middle.mean() < 10.7, "mean diameter %.2f mm, expected about 10" % middle.mean())
        self.assertEqual(terrain.GetDimensions()[:2], (72, profile.GetNumberOfRows()))

    def test_the_papers_curve_without_centering(self):
        paper = centerline("u", CenteringIterations=0).GetOutput().GetNumberOfPoints()
        self.assertGreaterEqual(paper, 50)

    def test_markups_curves_read_back_as_slicer_reads_them(self):
        tree = centerline("tree", DetectBranches=True).GetOutput()
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "tree.mrk.json")
            writer = medial.vtkMedialMarkupsCurveWriter()
            writer.SetFileName(path)
            writer.SetInputData(tree)
            self.assertEqual(writer.Write(), 1)
            with open(path) as f:
                document = json.load(f)
        self.assertRegex(document["@schema"], r"markups-schema-v1\.[0-9]+\.[0-9]+\.json#$")
        curves = document["markups"]
        self.assertEqual(len(curves), tree.GetNumberOfLines())
        radius = numpy_support.vtk_to_numpy(tree.GetPointData().GetArray("Radius"))
        points = numpy_support.vtk_to_numpy(tree.GetPoints().GetData())
        for cell, curve in enumerate(curves):
            self.assertEqual((curve["type"], curve["coordinateSystem"], curve["coordinateUnits"]),
                             ("Curve", "LPS", "mm"))
            ids = cell_ids(tree, cell)
            positions = np.array([p["position"] for p in curve["controlPoints"]])
            self.assertEqual(positions.shape, (len(ids), 3))
            self.assertLess(np.abs(positions - points[ids]).max(), 1e-6, "control points off the line")
            values = {m["name"]: m for m in curve["measurements"]}
            self.assertLess(np.abs(np.array(values["Radius"]["controlPointValues"]) - radius[ids]).max(), 1e-6)
            length = np.linalg.norm(np.diff(positions, axis=0), axis=1).sum()
            self.assertAlmostEqual(values["length"]["value"], length, places=4)
        junction = cell_ids(tree, 0).index(cell_ids(tree, 1)[0])
        self.assertEqual(curves[1]["controlPoints"][0]["position"], curves[0]["controlPoints"][junction]["position"],
                         "a branch starts at its junction on its parent")

    def test_markups_writer_refuses_what_is_not_a_curve(self):
        import vtk
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "none.mrk.json")
            writer = medial.vtkMedialMarkupsCurveWriter()
            writer.SetFileName(path)
            writer.SetInputData(vtk.vtkPolyData())
            errors = []
            writer.AddObserver("ErrorEvent", lambda caller, event: errors.append(event))
            self.assertEqual(writer.Write(), 0)
            self.assertTrue(errors)
            self.assertFalse(os.path.exists(path), "no file is left behind")


if __name__ == "__main__":
    unittest.main()
