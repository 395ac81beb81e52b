"""The TSK centerline from Python: a branching tree (one polyline per branch), the sections' profile table and
the unfolded wall on ports 1 and 2, and the centering option, all on the bundled phantoms."""
import os
import unittest

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


if __name__ == "__main__":
    unittest.main()
