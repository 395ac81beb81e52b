#!/usr/bin/python3
"""Benchmark: SQM (vtkMedialSQM) against Blender's Skin modifier on the same skeletons, in one run.

Blender's Skin modifier is what a DCC user reaches for to turn a skeleton with radii into a tube mesh. Per
skeleton: faces, quad share, open (border) and non-manifold edges, pairs of faces that cut each other (CGAL's
exact test, vtkMedialMeshTopology), and median seconds of each (Blender's the modifier's evaluation inside
Blender 3.4 run headless, not its start-up), and the time ratio Blender / SQM. The skeletons whose tubes overlap
(data/skeletons/overlapping) get a second SQM row with the union (SetUnion): the only row of the two tools whose
mesh bounds a volume there. A second table compares SQM's refinement (--subdivide 3: tessellation projected
onto the swept spheres, fold repair, overlap count) with Blender's Subdivision Surface modifier (Catmull-Clark,
level 3) on the same base mesh, SQM's own at K = 0: median seconds of each and Blender's first evaluation (its
cold run, caches empty). Needs `blender` on the PATH (Debian's Blender 3.4); without it the script says so
and exits 0.
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 bench/sqm_blender_bench.py [--repeat N] [SKELETON...]
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import vtk

import medial

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data", "skeletons")
DEFAULT = [os.path.join(DATA, "sqm", n + ".vtp") for n in ("worm", "fish", "humanoid", "quadruped", "octopus",
                                                          "cycle", "pretzel")] + \
          [os.path.join(DATA, "figure.vtp"), os.path.join(DATA, "hand.swc")] + \
          [os.path.join(DATA, "overlapping", n + ".vtp") for n in ("crossing", "dense-tree")]

# Runs inside Blender: one object per skeleton with a Skin modifier (radius per vertex, a root per
# component), evaluated `repeat` times; prints one MEDIAL-SKIN line of JSON per skeleton, with the evaluated
# mesh's vertices and polygons (their self-intersections are counted outside Blender).
BLENDER_SCRIPT = r'''
import bpy, json, sys, time
skeletons = json.load(open(sys.argv[sys.argv.index("--") + 1]))
repeat = int(sys.argv[sys.argv.index("--") + 2])

def subdivision_row(s):
    """Catmull-Clark level 3 on SQM's base mesh: one MEDIAL-SUBSURF line."""
    mesh = bpy.data.meshes.new(s["name"] + " base")
    mesh.from_pydata(s["base"]["vertices"], [], s["base"]["polygons"])
    obj = bpy.data.objects.new(s["name"] + " base", mesh)
    bpy.context.collection.objects.link(obj)
    modifier = obj.modifiers.new("subsurf", "SUBSURF")
    modifier.levels = modifier.render_levels = 3
    seconds = []
    for run in range(repeat + 1):
        mesh.update()
        start = time.perf_counter()
        depsgraph = bpy.context.evaluated_depsgraph_get()
        result = obj.evaluated_get(depsgraph).to_mesh()
        seconds.append(time.perf_counter() - start)
        faces = len(result.polygons)
        obj.evaluated_get(depsgraph).to_mesh_clear()
    later = sorted(seconds[1:])
    print("MEDIAL-SUBSURF " + json.dumps({"name": s["name"], "faces": faces, "first": seconds[0],
                                          "seconds": later[len(later) // 2]}), flush=True)
for s in skeletons:
    mesh = bpy.data.meshes.new(s["name"])
    mesh.from_pydata(s["nodes"], s["edges"], [])
    obj = bpy.data.objects.new(s["name"], mesh)
    bpy.context.collection.objects.link(obj)
    obj.modifiers.new("skin", "SKIN")
    layer = mesh.skin_vertices[0].data
    for i, r in enumerate(s["radii"]):
        layer[i].radius = (r, r)
        layer[i].use_root = i in s["roots"]
    seconds = []
    for run in range(repeat):
        mesh.update()
        start = time.perf_counter()
        depsgraph = bpy.context.evaluated_depsgraph_get()
        result = obj.evaluated_get(depsgraph).to_mesh()
        seconds.append(time.perf_counter() - start)
        if run + 1 < repeat:
            obj.evaluated_get(depsgraph).to_mesh_clear()
    faces = len(result.polygons)
    quads = sum(1 for p in result.polygons if len(p.vertices) == 4)
    use = {}
    for p in result.polygons:
        for k in p.edge_keys:
            use[k] = use.get(k, 0) + 1
    print("MEDIAL-SKIN " + json.dumps({"name": s["name"], "faces": faces, "quads": quads,
                                       "open": sum(1 for c in use.values() if c == 1),
                                       "nonmanifold": sum(1 for c in use.values() if c > 2),
                                       "vertices": [list(v.co) for v in result.vertices],
                                       "polygons": [list(p.vertices) for p in result.polygons],
                                       "seconds": sorted(seconds)[len(seconds) // 2]}), flush=True)
    if "base" in s:
        subdivision_row(s)
'''


def read_skeleton(path):
    reader = medial.vtkMedialReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutputDataObject(0)
    nodes = [list(data.GetPoint(i)) for i in range(data.GetNumberOfPoints())]
    radius = data.GetPointData().GetArray("Radius")
    radii = [radius.GetValue(i) for i in range(data.GetNumberOfPoints())]
    edges, ids = [], vtk.vtkIdList()
    for c in range(data.GetNumberOfCells()):
        data.GetCellPoints(c, ids)
        edges += [[ids.GetId(k), ids.GetId(k + 1)] for k in range(ids.GetNumberOfIds() - 1)]
    parent = list(range(len(nodes)))  # one root per component for the Skin modifier

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    for a, b in edges:
        parent[find(a)] = find(b)
    roots = sorted({find(x) for x in range(len(nodes))})
    return data, {"name": os.path.basename(path), "nodes": nodes, "edges": edges, "radii": radii, "roots": roots}


def intersecting_pairs(mesh):
    """Pairs of faces of `mesh` that cut each other (CGAL's exact test) and its topology."""
    topology = medial.vtkMedialMeshTopology()
    topology.SetInputData(mesh)
    topology.CountSelfIntersectionsOn()
    topology.Update()
    return topology


def sqm_row(skeleton, repeat, union=False):
    sqm = medial.vtkMedialSQM()
    sqm.SetInputData(skeleton)
    sqm.SetUnion(union)
    seconds = []
    for _ in range(repeat):
        sqm.Modified()
        start = time.perf_counter()
        sqm.Update()
        seconds.append(time.perf_counter() - start)
    mesh = sqm.GetOutput()
    topology = intersecting_pairs(mesh)
    quads = sum(1 for c in range(mesh.GetNumberOfCells()) if mesh.GetCell(c).GetNumberOfPoints() == 4)
    return {"faces": mesh.GetNumberOfCells(), "quads": quads, "open": topology.GetNumberOfBorderEdges(),
            "nonmanifold": topology.GetNumberOfNonManifoldEdges(),
            "pairs": topology.GetNumberOfIntersectingFacePairs(), "seconds": statistics.median(seconds)}


def mesh_arrays(mesh):
    """Vertices and polygons of a vtkPolyData, as lists."""
    ids = vtk.vtkIdList()
    polygons = []
    for c in range(mesh.GetNumberOfCells()):
        mesh.GetCellPoints(c, ids)
        polygons.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    return {"vertices": [list(mesh.GetPoint(i)) for i in range(mesh.GetNumberOfPoints())], "polygons": polygons}


def refined_row(skeleton, repeat, levels=3):
    """SQM at K = `levels` (median and first seconds), and its base mesh (K = 0) for Blender."""
    sqm = medial.vtkMedialSQM()
    sqm.SetInputData(skeleton)
    sqm.Update()
    base = mesh_arrays(sqm.GetOutput())
    sqm.SetSubdivisionLevels(levels)
    seconds = []
    for _ in range(repeat + 1):
        sqm.Modified()
        start = time.perf_counter()
        sqm.Update()
        seconds.append(time.perf_counter() - start)
    return base, {"faces": sqm.GetOutput().GetNumberOfCells(), "first": seconds[0],
                  "seconds": statistics.median(seconds[1:]),
                  "pairs": intersecting_pairs(sqm.GetOutput()).GetNumberOfIntersectingFacePairs()}


def skin_pairs(report):
    """The intersecting face pairs of Blender's evaluated mesh."""
    points, polygons = vtk.vtkPoints(), vtk.vtkCellArray()
    for v in report["vertices"]:
        points.InsertNextPoint(v)
    for p in report["polygons"]:
        polygons.InsertNextCell(len(p), p)
    mesh = vtk.vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polygons)
    return intersecting_pairs(mesh).GetNumberOfIntersectingFacePairs()


def overlapping(path):
    return os.path.basename(os.path.dirname(os.path.abspath(path))) == "overlapping"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=20)
    parser.add_argument("skeletons", nargs="*", default=DEFAULT)
    args = parser.parse_args()
    if not shutil.which("blender"):
        print("sqm_blender_bench: blender is not installed; Blender's Skin modifier row left out")
        return 0
    rows, refined, skeletons = {}, {}, []
    for path in args.skeletons:
        data, skeleton = read_skeleton(path)
        rows[skeleton["name"]] = sqm_row(data, args.repeat)
        skeleton["base"], refined[skeleton["name"]] = refined_row(data, max(1, min(args.repeat, 5)))
        if overlapping(path):  # the union, beside Blender's same row
            rows[skeleton["name"] + " union"] = sqm_row(data, max(1, min(args.repeat, 3)), union=True)
        skeletons.append(skeleton)
    with tempfile.TemporaryDirectory(prefix="medial-skin-") as folder:
        spec, script = os.path.join(folder, "skeletons.json"), os.path.join(folder, "skin.py")
        with open(spec, "w") as f:
            json.dump(skeletons, f)
        with open(script, "w") as f:
            f.write(BLENDER_SCRIPT)
        env = {k: v for k, v in os.environ.items() if k not in ("LD_PRELOAD", "ASAN_OPTIONS")}
        done = subprocess.run(["blender", "-b", "--factory-startup", "--python", script, "--", spec, str(args.repeat)],
                              capture_output=True, text=True, timeout=1800, env=env)
    skin, subsurf = {}, {}
    for line in done.stdout.splitlines():
        if line.startswith("MEDIAL-SKIN "):
            report = json.loads(line[len("MEDIAL-SKIN "):])
            skin[report["name"]] = report
        elif line.startswith("MEDIAL-SUBSURF "):
            report = json.loads(line[len("MEDIAL-SUBSURF "):])
            subsurf[report["name"]] = report
    print("SQM (vtkMedialSQM) vs Blender 3.4's Skin modifier, median of %d runs" % args.repeat)
    print("%-20s | %8s %6s %5s %5s %5s %6s | %8s %6s %5s %5s %5s %6s | %9s" % (
        "skeleton", "SQM ms", "faces", "quads", "open", "nonm", "pairs", "Skin ms", "faces", "quads", "open", "nonm",
        "pairs", "Skin/SQM"))
    for name, ours in rows.items():
        peer = skin.get(name.replace(" union", ""))
        if not peer:
            print("%-20s | Blender reported nothing:\n%s" % (name, done.stderr[-2000:]))
            continue
        if "pairs" not in peer:
            peer["pairs"] = skin_pairs(peer)
        print("%-20s | %8.2f %6d %4.0f%% %5d %5d %6d | %8.2f %6d %4.0f%% %5d %5d %6d | %9.2f" % (
            name, 1e3 * ours["seconds"], ours["faces"], 100.0 * ours["quads"] / max(1, ours["faces"]), ours["open"],
            ours["nonmanifold"], ours["pairs"], 1e3 * peer["seconds"], peer["faces"],
            100.0 * peer["quads"] / max(1, peer["faces"]), peer["open"], peer["nonmanifold"], peer["pairs"],
            peer["seconds"] / ours["seconds"]))
    print("\nSQM --subdivide 3 vs Blender's Subdivision Surface (Catmull-Clark, level 3) on SQM's base mesh,"
          " median of the runs after the first")
    print("%-20s | %8s %8s %7s %6s | %8s %8s %7s | %8s %8s" % (
        "skeleton", "SQM ms", "first ms", "faces", "pairs", "CC ms", "first ms", "faces", "SQM/CC", "first"))
    for name, ours in refined.items():
        peer = subsurf.get(name)
        if not peer:
            continue
        print("%-20s | %8.1f %8.1f %7d %6d | %8.1f %8.1f %7d | %8.2f %8.2f" % (
            name, 1e3 * ours["seconds"], 1e3 * ours["first"], ours["faces"], ours["pairs"], 1e3 * peer["seconds"],
            1e3 * peer["first"], peer["faces"], ours["seconds"] / peer["seconds"], ours["first"] / peer["first"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
