#!/usr/bin/python3
"""Skeleton, weights and rig of one mesh at growing resolutions: the armadillo (CGAL sample, 26k vertices)
and its Loop subdivisions (104k, 416k, 1.66M vertices; VTK's vtkLoopSubdivisionFilter). One
`medial skeleton MESH --rig RIG.glb --timings` per size: its stages (decimation, contraction, weights...),
the rig's write, the whole process's wall time and peak memory, and the time per vertex against the
smallest size (1.0: linear). The peer for a skeleton is medial_bench_contraction (CGAL's MCF); this one
asks how Medial scales.

usage: /usr/bin/python3 bench/contraction_scale_bench.py [--levels 0,1,2,3] [--mesh MESH.off]
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

import vtk

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MEDIAL = os.path.join(TOP, "build", "bin", "medial")
ARMADILLO = os.path.join(TOP, "data", "external", "cgal", "meshes", "armadillo.off")


def subdivided(mesh, levels, folder):
    """The mesh after `levels` Loop subdivisions, as a .vtp in `folder` (read through Medial's OFF reader)."""
    sys.path.insert(0, os.path.join(TOP, "build", "lib", "python3", "dist-packages"))
    import medial

    reader = medial.vtkMedialReader()
    reader.SetFileName(mesh)
    reader.Update()
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputData(reader.GetOutputDataObject(0))
    triangles.Update()
    data = triangles.GetOutput()
    if levels > 0:
        loop = vtk.vtkLoopSubdivisionFilter()
        loop.SetInputData(data)
        loop.SetNumberOfSubdivisions(levels)
        loop.Update()
        data = loop.GetOutput()
    path = os.path.join(folder, "mesh-%d.vtp" % levels)
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.Write()
    return path, data.GetNumberOfPoints()


def run(path, folder):
    """One `medial skeleton --rig` in a child: its timings, wall seconds and peak memory (MB)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    start = time.monotonic()
    done = subprocess.run([MEDIAL, "skeleton", path, "-o", os.path.join(folder, "s.vtp"), "--rig",
                           os.path.join(folder, "rig.glb"), "--timings", "--quiet"],
                          capture_output=True, text=True)
    seconds = time.monotonic() - start
    if done.returncode != 0:
        sys.exit("medial skeleton failed on %s: %s" % (path, done.stderr))
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return json.loads(done.stdout), seconds, max(peak, before) / 1024.0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--levels", default="0,1,2,3")
    parser.add_argument("--mesh", default=ARMADILLO)
    args = parser.parse_args()
    if not os.path.exists(args.mesh):
        sys.exit("%s is missing: run scripts/fetch-samples" % args.mesh)
    print("medial skeleton --rig on %s and its Loop subdivisions (one run per size)" % os.path.basename(args.mesh))
    print("%9s %8s %8s %8s %8s %8s %8s %9s %9s" % ("vertices", "decim s", "contr s", "weights", "write s",
                                                  "total s", "wall s", "peak MB", "s/vertex"))
    first = None
    with tempfile.TemporaryDirectory() as folder:
        for levels in [int(level) for level in args.levels.split(",")]:
            path, vertices = subdivided(args.mesh, levels, folder)
            timings, wall, peak = run(path, folder)
            per = wall / vertices
            first = first or per
            print("%9d %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %9.0f %9.2f" % (
                vertices, timings.get("skeleton.decimation", 0),
                timings.get("skeleton.contraction", 0) + timings.get("skeleton.factorization", 0),
                timings.get("skeleton.weights", 0), timings.get("write", 0), timings.get("total", 0), wall, peak,
                per / first))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
