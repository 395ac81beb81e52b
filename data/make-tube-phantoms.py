#!/usr/bin/python3
"""Makes the TSK centerline phantoms (committed under data/volumes/tubes/): run with /usr/bin/python3.

The six synthetic tubes of the paper's Fig. 17, as binary NIfTI volumes (1 inside, 0 outside) with their
analytic axes as VTP polylines (NAME-axis.vtp, points in mm):
    u.nii.gz          a U standing on its bend (radius 5)
    s-plane.nii.gz    an S in the XY plane
    s-3d.nii.gz       an S in 3-D
    s-radius.nii.gz   an S whose radius changes from 3 to 7 along it
    helix.nii.gz      a helix of two turns
    helix-tight.nii.gz  a tighter helix of three turns, anisotropic spacing 0.7 x 0.7 x 1.0 mm
two harder ones (issue 45):
    taper.nii.gz      a tube bent in a wide arc whose radius grows twofold along it (4 to 8 mm)
    ct-spiral.nii.gz  a CT, not a mask: an air-filled spiral tube (radius 4, two turns) in soft tissue,
                      Hounsfield units with partial volume at the wall and Gaussian noise (sigma 20 HU,
                      fixed seed), not clipped at -1024 (as reconstructions stored in float or resampled
                      are not), 0.75 mm voxels, both ends capped inside the volume
and a branching tree (issue 5) with one polyline per branch in its axis file:
    tree.nii.gz       a trunk (radius 5) splitting into two branches (radius 4), one of which splits again
                      (radius 3): five branches
"""
import math
import os

import numpy as np
import vtk
from vtk.util import numpy_support

HERE = os.path.dirname(os.path.abspath(__file__))


def voxelize(curve, radius, size, spacing=(1.0, 1.0, 1.0), samples=600):
    """Voxels within radius(s) of the polyline through curve(s), s in [0, 1]."""
    s = np.linspace(0.0, 1.0, samples + 1)
    axis = np.array([curve(t) for t in s])
    radii = np.array([radius(t) for t in s])
    grid = np.stack(np.meshgrid(*[np.arange(n) * h for n, h in zip(size, spacing)], indexing="ij"), axis=-1)
    points = grid.reshape(-1, 3)
    best = np.full(len(points), np.inf)
    for a, b, ra, rb in zip(axis[:-1], axis[1:], radii[:-1], radii[1:]):
        ab = b - a
        t = np.clip(((points - a) @ ab) / max(ab @ ab, 1e-12), 0.0, 1.0)
        d = np.linalg.norm(points - (a + t[:, None] * ab), axis=1) - (ra + t * (rb - ra))
        best = np.minimum(best, d)
    inside = (best <= 0).reshape(size).astype(np.uint8)
    return inside, axis


def write_nifti(inside, spacing, path):
    image = vtk.vtkImageData()
    image.SetDimensions(*inside.shape)
    image.SetSpacing(*spacing)
    flat = np.ascontiguousarray(inside.transpose(2, 1, 0)).ravel()  # x fastest
    array = numpy_support.numpy_to_vtk(flat, deep=True, array_type=vtk.VTK_UNSIGNED_CHAR)
    image.GetPointData().SetScalars(array)
    writer = vtk.vtkNIFTIImageWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def write_axis(axis, path):
    write_axes([axis], path)


def write_axes(axes, path):
    """One polyline per axis (a branch), in mm."""
    points = vtk.vtkPoints()
    line = vtk.vtkCellArray()
    for axis in axes:
        line.InsertNextCell(len(axis))
        for p in axis:
            line.InsertCellPoint(points.InsertNextPoint(*p))
    polydata = vtk.vtkPolyData()
    polydata.SetPoints(points)
    polydata.SetLines(line)
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(polydata)
    writer.Write()


def u(t):
    leg, r = 25.0, 15.0
    a = t * (2 * leg + math.pi * r)
    if a < leg:
        return (8.0, 20.0, 48.0 - a)
    if a < leg + math.pi * r:
        angle = (a - leg) / r
        return (23.0 - r * math.cos(angle), 20.0, 23.0 - r * math.sin(angle))
    return (38.0, 20.0, 23.0 + a - leg - math.pi * r)


PHANTOMS = [
    ("u", u, lambda t: 5.0, (46, 40, 56), (1.0, 1.0, 1.0)),
    ("s-plane", lambda t: (8 + 50 * t, 30 + 14 * math.sin(2 * math.pi * t), 12.0), lambda t: 5.0, (66, 60, 24), (1.0, 1.0, 1.0)),
    ("s-3d", lambda t: (8 + 50 * t, 30 + 14 * math.sin(2 * math.pi * t), 20 + 10 * math.sin(math.pi * t)),
     lambda t: 5.0, (66, 60, 40), (1.0, 1.0, 1.0)),
    ("s-radius", lambda t: (10 + 50 * t, 30 + 14 * math.sin(2 * math.pi * t), 14.0), lambda t: 3 + 4 * t,
     (70, 60, 28), (1.0, 1.0, 1.0)),
    ("helix", lambda t: (30 + 16 * math.cos(4 * math.pi * t), 30 + 16 * math.sin(4 * math.pi * t), 8 + 50 * t),
     lambda t: 4.0, (60, 60, 66), (1.0, 1.0, 1.0)),
    ("helix-tight", lambda t: (24 + 12 * math.cos(6 * math.pi * t), 24 + 12 * math.sin(6 * math.pi * t), 6 + 50 * t),
     lambda t: 3.5, (69, 69, 62), (0.7, 0.7, 1.0)),
    ("taper", lambda t: (50 - 38 * math.cos(0.8 * math.pi * t), 12 + 38 * math.sin(0.8 * math.pi * t), 14.0),
     lambda t: 4 + 4 * t, (84, 62, 28), (1.0, 1.0, 1.0)),
]


def spiral(t):
    return (25 + 14 * math.cos(4 * math.pi * t), 25 + 14 * math.sin(4 * math.pi * t), 10 + 40 * t)


def make_ct_spiral(folder):
    """The spiral as a CT: -1000 HU inside, 40 HU around, the wall's voxels by the share of them inside
    (their distance to the tube's surface over a voxel), noise sigma 20 HU; int16; caps inside."""
    spacing, size, r = (0.75, 0.75, 0.75), (68, 68, 80), 4.0
    s = np.linspace(0.0, 1.0, 801)
    axis = np.array([spiral(t) for t in s])
    grid = np.stack(np.meshgrid(*[np.arange(n) * h for n, h in zip(size, spacing)], indexing="ij"), axis=-1)
    points = grid.reshape(-1, 3)
    best = np.full(len(points), np.inf)
    for a, b in zip(axis[:-1], axis[1:]):
        ab = b - a
        t = np.clip(((points - a) @ ab) / max(ab @ ab, 1e-12), 0.0, 1.0)
        best = np.minimum(best, np.linalg.norm(points - (a + t[:, None] * ab), axis=1))
    share = np.clip(0.5 - (best - r) / spacing[0], 0.0, 1.0).reshape(size)
    noise = np.random.default_rng(45).normal(0.0, 20.0, size)
    hu = np.round(40.0 - 1040.0 * share + noise).astype(np.int16)
    image = vtk.vtkImageData()
    image.SetDimensions(*size)
    image.SetSpacing(*spacing)
    flat = np.ascontiguousarray(hu.transpose(2, 1, 0)).ravel()
    image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(flat, deep=True, array_type=vtk.VTK_SHORT))
    writer = vtk.vtkNIFTIImageWriter()
    writer.SetFileName(os.path.join(folder, "ct-spiral.nii.gz"))
    writer.SetInputData(image)
    writer.Write()
    write_axis(axis, os.path.join(folder, "ct-spiral-axis.vtp"))
    print("%-12s %s voxels, %d below -600 HU" % ("ct-spiral", "x".join(map(str, size)), int((hu <= -600).sum())))

def bezier(p0, p1, p2):
    """A quadratic Bezier branch from p0 (its junction) through the pull of p1 to p2."""
    return lambda t: tuple((1 - t) ** 2 * a + 2 * (1 - t) * t * b + t * t * c for a, b, c in zip(p0, p1, p2))


# The tree: (curve, radius) per branch; every branch starts on its parent's end (a junction).
TREE = [
    (bezier((40, 30, 6), (40, 30, 25), (40, 30, 42)), 5.0),     # trunk
    (bezier((40, 30, 42), (40, 30, 55), (18, 30, 78)), 4.0),    # left branch
    (bezier((40, 30, 42), (40, 30, 55), (62, 30, 70)), 4.0),    # right branch, which splits again:
    (bezier((62, 30, 70), (68, 30, 80), (68, 44, 100)), 3.0),
    (bezier((62, 30, 70), (68, 30, 80), (70, 16, 100)), 3.0),
]


def make_tree(folder):
    size, spacing = (84, 60, 108), (1.0, 1.0, 1.0)
    inside, axes = None, []
    for curve, r in TREE:
        part, axis = voxelize(curve, lambda t, r=r: r, size, spacing, samples=300)
        inside = part if inside is None else np.maximum(inside, part)
        axes.append(axis)
    write_nifti(inside, spacing, os.path.join(folder, "tree.nii.gz"))
    write_axes(axes, os.path.join(folder, "tree-axis.vtp"))
    print("%-12s %s voxels, %d inside, %d branches" % ("tree", "x".join(map(str, size)), int(inside.sum()), len(axes)))


if __name__ == "__main__":
    folder = os.path.join(HERE, "volumes", "tubes")
    os.makedirs(folder, exist_ok=True)
    for name, curve, radius, size, spacing in PHANTOMS:
        inside, axis = voxelize(curve, radius, size, spacing)
        write_nifti(inside, spacing, os.path.join(folder, name + ".nii.gz"))
        write_axis(axis, os.path.join(folder, name + "-axis.vtp"))
        print("%-12s %s voxels, %d inside" % (name, "x".join(map(str, size)), int(inside.sum())))
    make_ct_spiral(folder)
    make_tree(folder)
