#!/usr/bin/python3
"""The TSK centerline from Python: a branching tree (one polyline per branch), the sections' profile table and
the unfolded wall on ports 1 and 2, and the centering option, all on the bundled phantoms."""
import os
import sys

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


def main():
    failures = []
    tree = centerline("tree", DetectBranches=True).GetOutput()
    if tree.GetNumberOfLines() != 5:
        failures.append("tree: %d polylines, expected 5" % tree.GetNumberOfLines())
    parents = numpy_support.vtk_to_numpy(tree.GetCellData().GetArray("ParentBranch"))
    if sorted(parents.tolist()).count(-1) != 1:
        failures.append("tree: parents %s, expected one root" % parents.tolist())

    u = centerline("u", ComputeSections=True, SectionSpacing=2.0)
    profile, terrain = u.GetOutputDataObject(1), u.GetOutputDataObject(2)
    # The mean of the min and max diameter of the middle sections (the U's radius is 5 mm; the minimum alone
    # runs about 1 mm low on the voxel staircase).
    low = numpy_support.vtk_to_numpy(profile.GetColumnByName("MinDiameter"))
    high = numpy_support.vtk_to_numpy(profile.GetColumnByName("MaxDiameter"))
    quarter = len(low) // 4
    middle = 0.5 * (low + high)[quarter: 3 * quarter]
    if not (9.3 < middle.mean() < 10.7):
        failures.append("u: mean diameter %.2f mm, expected about 10" % middle.mean())
    if terrain.GetDimensions()[:2] != (72, profile.GetNumberOfRows()):
        failures.append("u: terrain %s for %d sections" % (terrain.GetDimensions(), profile.GetNumberOfRows()))

    paper = centerline("u", CenteringIterations=0).GetOutput().GetNumberOfPoints()
    if paper < 50:
        failures.append("u without centering: %d points" % paper)

    for failure in failures:
        print("FAIL:", failure)
    print("tree: %d branches; u: %d sections, mean diameter %.2f mm" %
          (tree.GetNumberOfLines(), profile.GetNumberOfRows(), middle.mean()))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
