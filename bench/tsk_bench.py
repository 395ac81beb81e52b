#!/usr/bin/python3
"""Benchmark: Medial's TSK centerline against two peers on the paper's tube phantoms, in one run.

Peers: scikit-image's 3-D skeletonize (Lee et al. thinning), and a distance-map minimal path (Dijkstra on
26-connected voxels, step cost length / distance-to-wall^2) between the same end points as Medial's axis.
Beside Medial's centerline, the paper's own curve (the TSK models without Medial's centring passes,
--centering 0): the paper's Table 2 and Medial's improvement on the same phantoms.
Per phantom: median seconds of each (over --repeat runs), mean and max distance to the true axis (mm,
voxels and % of the axis length as in the paper's Table 2), leaving out one radius at each end; and VMTK's
figures as issue 45 reports them (VMTK is not packaged for Debian: not run here).
"colon" is the CT-like colon phantom (build/bin/medial-make-colon-phantom, made in a temporary folder and
read as its DICOM series): Medial thresholds -1024..-600 HU itself; the peers get the same structure (the
threshold, parts touching the border dropped, the largest 26-connected component).
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 bench/tsk_bench.py [--repeat N] [NAME...]
"""
import argparse
import math
import os
import shutil
import statistics
import subprocess
import tempfile
import time

import numpy as np
import scipy.ndimage
import scipy.sparse
import scipy.sparse.csgraph
import skimage.morphology
import vtk
from vtk.util import numpy_support

import medial

HERE = os.path.dirname(os.path.abspath(__file__))
TUBES = os.path.join(HERE, "..", "data", "volumes", "tubes")
RADIUS = {"u": 5, "s-plane": 5, "s-3d": 5, "s-radius": 5, "helix": 4, "helix-tight": 3.5, "taper": 6,
          "ct-spiral": 4, "tree": 4, "colon": 12}
# VMTK's Voronoi centerline (3D Slicer's "Extract Centerline") as issue 45 reports it, mean / max mm with one
# radius at each end left out, run by the issue's author beside Medial (VMTK is not a Debian package, so not
# here). "taper" and "ct-spiral" stand for the issue's "radius varying twofold, 1 mm voxels" and "noisy CT
# spiral, HU, 0.75 mm voxels": phantoms made to that description, not the same files.
VMTK_ISSUE_45 = {"u": (0.09, 0.42), "s-plane": (0.33, 1.04), "helix": (0.07, 0.18), "tree": (0.13, 0.50),
                 "colon": (0.24, 2.58), "taper": (0.094, 0.23), "ct-spiral": (0.067, 0.20)}
CT_PHANTOMS = {"ct-spiral"}  # Hounsfield units: Medial and the peers take the air below -600 HU
PHANTOM_TOOL = os.path.join(HERE, "..", "build", "bin", "medial-make-colon-phantom")


def read_volume(name):
    reader = medial.vtkMedialReader()
    reader.SetFileName(os.path.join(TUBES, name + ".nii.gz"))
    reader.Update()
    image = reader.GetOutputDataObject(0)
    dims = image.GetDimensions()
    array = numpy_support.vtk_to_numpy(image.GetPointData().GetScalars()).reshape(dims[::-1]).transpose(2, 1, 0)
    return image, array > 0, np.array(image.GetSpacing()), np.array(image.GetOrigin())


def air_structure(image):
    """A CT's structure as Medial's automatic selection takes it: at most -600 HU, parts touching the border
    dropped, the largest 26-connected part."""
    dims = image.GetDimensions()
    hu = numpy_support.vtk_to_numpy(image.GetPointData().GetScalars()).reshape(dims[::-1]).transpose(2, 1, 0)
    labels, _ = scipy.ndimage.label(hu <= -600, structure=np.ones((3, 3, 3)))
    border = np.unique(np.concatenate([labels[[0, -1]].ravel(), labels[:, [0, -1]].ravel(), labels[:, :, [0, -1]].ravel()]))
    sizes = np.bincount(labels.ravel())
    sizes[border] = 0
    return labels == np.argmax(sizes)


def read_ct_tube(name):
    """A tube phantom in Hounsfield units, its air as the peers get it."""
    reader = medial.vtkMedialReader()
    reader.SetFileName(os.path.join(TUBES, name + ".nii.gz"))
    reader.Update()
    image = reader.GetOutputDataObject(0)
    return image, air_structure(image), np.array(image.GetSpacing()), np.array(image.GetOrigin())


def read_colon(folder):
    """The colon phantom's DICOM series, its structure as the peers get it, and its true axis."""
    subprocess.run([PHANTOM_TOOL, folder], check=True, stdout=subprocess.DEVNULL)
    reader = medial.vtkMedialReader()
    reader.SetFileName(folder)
    reader.Update()
    image = reader.GetOutputDataObject(0)
    inside = air_structure(image)
    axis = [np.loadtxt(os.path.join(folder, "axis.txt"))[:, :3]]
    return image, inside, np.array(image.GetSpacing()), np.array(image.GetOrigin()), axis


def read_axis(name):
    """The true axis as a list of polylines (one for a tube, one per branch for the tree)."""
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(TUBES, name + "-axis.vtp"))
    reader.Update()
    data = reader.GetOutput()
    lines, ids = [], vtk.vtkIdList()
    data.GetLines().InitTraversal()
    while data.GetLines().GetNextCell(ids):
        lines.append(np.array([data.GetPoint(ids.GetId(k)) for k in range(ids.GetNumberOfIds())]))
    return lines


def distances_to_polylines(points, lines):
    segments = [(line[:-1], line[1:] - line[:-1]) for line in lines]
    best = np.full(len(points), np.inf)
    for i, p in enumerate(points):
        for a, ab in segments:
            t = np.clip(((p - a) * ab).sum(1) / np.maximum((ab * ab).sum(1), 1e-300), 0, 1)
            best[i] = min(best[i], np.linalg.norm(a + t[:, None] * ab - p, axis=1).min())
    return best


def tips(lines):
    """Ends of the axis that are no junction (a branch's first point lies on its parent)."""
    ends = [line[0] for line in lines] + [line[-1] for line in lines]
    return [e for e in ends if sum(distances_to_polylines(e[None], [l])[0] < 1e-6 for l in lines) == 1]


def errors(points, lines, radius, spacing):
    keep = np.ones(len(points), dtype=bool)
    for tip in tips(lines):
        keep &= np.linalg.norm(points - tip, axis=1) >= radius
    d = distances_to_polylines(points[keep], lines)
    length = sum(np.linalg.norm(np.diff(line, axis=0), axis=1).sum() for line in lines)
    voxel = spacing.min()
    return d.mean(), d.max(), d.mean() / voxel, 100 * d.mean() / length


def medial_centerline(image, threshold=None, branches=False, centering=None):
    """Medial's points, and the first and last point of each polyline (the peers' path ends)."""
    f = medial.vtkMedialTskCenterline()
    f.SetInputData(image)
    if centering is not None:
        f.SetCenteringIterations(centering)
    if threshold == "automatic":
        f.SelectAutomatically()  # what a user without --threshold gets: a CT's air
    elif threshold:
        f.SetThreshold(*threshold)
    else:
        f.SetLabel(1)
    f.SetDetectBranches(branches)
    f.Update()
    line = f.GetOutput()
    ends, ids = [], vtk.vtkIdList()
    line.GetLines().InitTraversal()
    while line.GetLines().GetNextCell(ids):
        ends.append((np.array(line.GetPoint(ids.GetId(0))), np.array(line.GetPoint(ids.GetId(ids.GetNumberOfIds() - 1)))))
    return np.array([line.GetPoint(i) for i in range(line.GetNumberOfPoints())]), ends


def skeleton_points(inside, spacing, origin):
    skeleton = skimage.morphology.skeletonize_3d(inside.astype(np.uint8))
    return np.argwhere(skeleton > 0) * spacing + origin


def minimal_path(inside, spacing, origin, start, ends):
    """Dijkstra on the 26-connected voxels from `start` to each of `ends` (one path, or a tree of paths);
    step cost = step length / (distance to the wall)^2."""
    distance = scipy.ndimage.distance_transform_edt(inside, sampling=spacing)
    index = -np.ones(inside.shape, dtype=np.int64)
    voxels = np.argwhere(inside)
    index[tuple(voxels.T)] = np.arange(len(voxels))
    rows, cols, costs = [], [], []
    for offset in [(dx, dy, dz) for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1) if (dx, dy, dz) > (0, 0, 0)]:
        neighbour = voxels + offset
        ok = np.all((neighbour >= 0) & (neighbour < inside.shape), axis=1)
        ok[ok] &= inside[tuple(neighbour[ok].T)]
        a, b = index[tuple(voxels[ok].T)], index[tuple(neighbour[ok].T)]
        step = np.linalg.norm(np.array(offset) * spacing)
        cost = step * 0.5 * (1 / distance[tuple(voxels[ok].T)] ** 2 + 1 / distance[tuple(neighbour[ok].T)] ** 2)
        rows += [a, b]
        cols += [b, a]
        costs += [cost, cost]
    graph = scipy.sparse.csr_matrix((np.concatenate(costs), (np.concatenate(rows), np.concatenate(cols))),
                                    shape=(len(voxels), len(voxels)))
    to_index = lambda p: index[tuple(np.round((p - origin) / spacing).astype(int))]
    s = to_index(start)
    if s < 0:
        return np.zeros((0, 3))
    _, predecessors = scipy.sparse.csgraph.dijkstra(graph, indices=s, return_predecessors=True)
    on_path = set()
    for end in ends:
        e = to_index(end)
        while e >= 0 and e not in on_path:
            on_path.add(e)
            if e == s:
                break
            e = predecessors[e]
    return voxels[sorted(on_path)] * spacing + origin


def timed(repeat, run):
    times, result = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def embed(image, inside, shape=(256, 256, 500)):
    """The colon phantom centred in a CT of `shape` voxels (the paper's 256x256x499 colon CTs): x and y
    grown by repeating the outermost columns (air around the body), z by body slices without the colon
    (its ends' slices with the colon's voxels set to soft tissue)."""
    dims = image.GetDimensions()
    hu = numpy_support.vtk_to_numpy(image.GetPointData().GetScalars()).reshape(dims[::-1]).transpose(2, 1, 0)
    pad = [((n - d) // 2, n - d - (n - d) // 2) for n, d in zip(shape, dims)]
    grown = np.pad(hu, (pad[0], pad[1], (0, 0)), mode="edge")
    first, last = hu[:, :, :1].copy(), hu[:, :, -1:].copy()
    first[inside[:, :, :1]] = 40
    last[inside[:, :, -1:]] = 40
    first, last = [np.pad(s, (pad[0], pad[1], (0, 0)), mode="edge") for s in (first, last)]
    grown = np.concatenate([np.repeat(first, pad[2][0], axis=2), grown, np.repeat(last, pad[2][1], axis=2)], axis=2)
    big = vtk.vtkImageData()
    big.SetDimensions(*grown.shape)
    big.SetSpacing(image.GetSpacing())
    origin = np.array(image.GetOrigin()) - np.array([pad[a][0] for a in range(3)]) * np.array(image.GetSpacing())
    big.SetOrigin(*origin)
    scalars = numpy_support.numpy_to_vtk(np.ascontiguousarray(grown.transpose(2, 1, 0)).ravel(), deep=1,
                                         array_type=image.GetPointData().GetScalars().GetDataType())
    big.GetPointData().SetScalars(scalars)
    return big


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("names", nargs="*", default=list(RADIUS))
    args = parser.parse_args()
    print("TSK centerline (Medial) vs skimage skeletonize_3d vs distance-map minimal path; median of %d runs" % args.repeat)
    print("%-12s | %-34s | %-34s | %-34s | %-34s | %s" % ("phantom", "Medial: s, mean/max mm, vox, %",
                                                       "the paper's curve (no centring)", "skeletonize", "minimal path",
                                                       "VMTK, issue 45: mean/max mm"))
    for name in args.names:
        threshold = None
        if name == "colon":
            if not os.path.exists(PHANTOM_TOOL):
                print("%-12s | skipped: build medial-make-colon-phantom first" % name)
                continue
            folder = tempfile.mkdtemp(prefix="medial-colon-")
            image, inside, spacing, origin, axis = read_colon(folder)
            shutil.rmtree(folder)
            threshold = (-1024, -600)
        elif name in CT_PHANTOMS:
            image, inside, spacing, origin = read_ct_tube(name)
            axis = read_axis(name)
            threshold = "automatic"
        else:
            image, inside, spacing, origin = read_volume(name)
            axis = read_axis(name)
        radius = RADIUS[name]
        row = []
        branches = name == "tree"
        t, (ours, ends) = timed(args.repeat, lambda: medial_centerline(image, threshold, branches))
        row.append((t, errors(ours, axis, radius, spacing)))
        t, (paper, _) = timed(args.repeat, lambda: medial_centerline(image, threshold, branches, centering=0))
        row.append((t, errors(paper, axis, radius, spacing)))
        t, skel = timed(args.repeat, lambda: skeleton_points(inside, spacing, origin))
        row.append((t, errors(skel, axis, radius, spacing)))
        t, path = timed(args.repeat, lambda: minimal_path(inside, spacing, origin, ends[0][0], [e[1] for e in ends]))
        row.append((t, errors(path, axis, radius, spacing) if len(path) else (math.nan,) * 4))
        cells = ["%.4f s %.3f/%.2f mm %.2f vox %.2f%%" % (t, e[0], e[1], e[2], e[3]) for t, e in row]
        vmtk = VMTK_ISSUE_45.get(name)
        cells.append("%.3f/%.2f mm" % vmtk if vmtk else "-")
        print("%-12s | %s" % (name, " | ".join(cells)))
        if name == "colon":
            big = embed(image, inside)
            t, (big_line, _) = timed(args.repeat, lambda: medial_centerline(big, threshold))
            e = errors(big_line, axis, radius, spacing)
            print("%-12s | %.4f s %.3f/%.2f mm %.2f vox %.2f%%   (the colon in %dx%dx%d voxels: goal < 1 s; the paper: "
                  "52 s in Matlab on a 256x256x499 CT)" % ("colon-500", t, e[0], e[1], e[2], e[3], *big.GetDimensions()))


if __name__ == "__main__":
    main()
