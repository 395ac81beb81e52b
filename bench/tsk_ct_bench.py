#!/usr/bin/python3
"""Benchmark: Medial's TSK centerline on full-size CT colon phantoms (medial-make-colon-phantom --size), in
one run per size: reading the uncompressed MetaImage against a raw read of its bytes, the centerline
against one threshold-and-count pass of numpy over the same voxels (the unit the issue counts in), the
peak memory of `medial centerline` against the volume's bytes, and the error to the true axis.
With --peer, scikit-image's skeletonize_3d on the 512 x 512 x 400 structure too.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 bench/tsk_ct_bench.py [--repeat N] [--peer] [--dicom] [SIZE...]
"""
import argparse
import os
import resource
import shutil
import subprocess
import tempfile
import time

import numpy as np
import vtk
from vtk.util import numpy_support

import medial
from tsk_bench import timed  # median seconds of `repeat` runs, and the last result

TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
PHANTOM = os.path.join(TOP, "build", "bin", "medial-make-colon-phantom")
MEDIAL = os.path.join(TOP, "build", "bin", "medial")
SIZES = ["256x256x500", "512x512x400", "512x512x800"]


def raw_read(path):
    with open(path, "rb") as f:
        header = b""
        while not header.endswith(b"ElementDataFile = LOCAL\n"):
            header += f.readline()
        return np.frombuffer(f.read(), dtype=np.int16)


def medial_read(path):
    reader = medial.vtkMedialReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutputDataObject(0)


def centerline(image):
    f = medial.vtkMedialTskCenterline()
    f.SetInputData(image)
    f.SetThreshold(-1024, -600)
    f.Update()
    line = f.GetOutput()
    return np.array([line.GetPoint(i) for i in range(line.GetNumberOfPoints())]), f


def axis_errors(points, axis, spacing):
    """Mean and max distance (voxels of the smallest spacing) from the centerline to the true axis, leaving
    out one radius at each end, and how much of the axis the centerline covers (%)."""
    a, b = axis[:-1, :3], axis[1:, :3]
    ab = b - a
    def distance(p):
        t = np.clip(((p - a) * ab).sum(1) / (ab * ab).sum(1), 0, 1)
        return np.linalg.norm(a + t[:, None] * ab - p, axis=1)
    ends = axis[[0, -1], :3]
    radius = axis[[0, -1], 3]
    keep = (np.linalg.norm(points - ends[0], axis=1) >= radius[0]) & (np.linalg.norm(points - ends[1], axis=1) >= radius[1])
    d = np.array([distance(p).min() for p in points[keep]])
    # Coverage: the axis points within 2 radii of some centerline point.
    covered = np.mean([np.linalg.norm(points - q[:3], axis=1).min() <= 2 * q[3] for q in axis[::10]])
    voxel = spacing.min()
    return d.mean() / voxel, d.max() / voxel, 100 * covered


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--peer", action="store_true")
    parser.add_argument("--dicom", action="store_true", help="also time reading 512x512x400 as a DICOM series")
    parser.add_argument("sizes", nargs="*", default=SIZES)
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="medial-ct-bench-")
    rows = []
    try:
        for size in args.sizes:
            folder = os.path.join(work, size)
            volume = os.path.join(work, size + ".mha")
            dicom = args.dicom and size == "512x512x400"  # a 400-slice series, read as a folder
            subprocess.run([PHANTOM, folder, volume, "--size", size] + ([] if dicom else ["--no-dicom"]),
                           check=True, stdout=subprocess.DEVNULL)
            raw_seconds, raw = timed(args.repeat, lambda: raw_read(volume))
            read_seconds, image = timed(args.repeat, lambda: medial_read(volume))
            if dicom:
                dicom_seconds, _ = timed(args.repeat, lambda: medial_read(folder))
                print("DICOM series of %s (%d files): read in %.2f s, %.1fx the raw read of the MetaImage" % (
                    size, len([n for n in os.listdir(folder) if n.endswith(".dcm")]), dicom_seconds,
                    dicom_seconds / raw_seconds))
            voxels = raw.size
            threshold_seconds, _ = timed(5, lambda: int(((raw >= -1024) & (raw <= -600)).sum()))
            line_seconds, (points, f) = timed(args.repeat, lambda: centerline(image))
            stages = {s: f.GetStageSeconds(s) for s in ("selection", "cleanup", "axis")}
            peak = subprocess.run(["/usr/bin/time", "-f", "%M", MEDIAL, "centerline", volume, "-o",
                                   os.path.join(work, "line.vtp"), "--threshold", "-1024:-600", "--quiet"],
                                  capture_output=True, text=True, check=True).stderr.split()[-1]
            axis = np.loadtxt(os.path.join(folder, "axis.txt"))
            mean, worst, covered = axis_errors(points, axis, np.array(image.GetSpacing()))
            rows.append((size, voxels, raw_seconds, read_seconds, threshold_seconds, line_seconds, stages,
                         int(peak) * 1024 / (2 * voxels), mean, worst, covered))
            if args.peer and size == "512x512x400":
                import scipy.ndimage
                import skimage.morphology
                hu = raw.reshape(image.GetDimensions()[::-1])
                start = time.perf_counter()
                labels, _ = scipy.ndimage.label((hu >= -1024) & (hu <= -600), structure=np.ones((3, 3, 3)))
                border = np.unique(np.concatenate([labels[[0, -1]].ravel(), labels[:, [0, -1]].ravel(),
                                                   labels[:, :, [0, -1]].ravel()]))
                sizes = np.bincount(labels.ravel())
                sizes[border] = 0
                skimage.morphology.skeletonize_3d((labels == np.argmax(sizes)).astype(np.uint8))
                print("scikit-image peer (label + skeletonize_3d) on %s: %.1f s" % (size, time.perf_counter() - start))
            shutil.rmtree(folder)
            os.remove(volume)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("TSK centerline on full-size CT colon phantoms (0.7 x 0.7 x 1.0 mm, int16), medians of %d" % args.repeat)
    print("%-12s %6s %7s %7s %6s %8s %9s %9s %22s %6s %6s %6s %6s" % (
        "size", "Mvox", "raw s", "read s", "x raw", "line s", "passes", "thr s", "select/clean/axis s",
        "mem x", "err vx", "max vx", "cover%"))
    for size, voxels, raw_s, read_s, thr_s, line_s, st, memory, mean, worst, covered in rows:
        print("%-12s %6.1f %7.2f %7.2f %6.2f %8.3f %9.1f %9.3f %22s %6.2f %6.2f %6.2f %6.1f" % (
            size, voxels / 1e6, raw_s, read_s, read_s / raw_s, line_s, line_s / thr_s, thr_s,
            "%.2f/%.2f/%.2f" % (st["selection"], st["cleanup"], st["axis"]), memory, mean, worst, covered))


if __name__ == "__main__":
    main()
