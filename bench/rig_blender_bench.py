#!/usr/bin/python3
"""Benchmark: Medial's skinning weights against Blender's automatic weights (bone heat) on the same mesh
and the same skeleton, in one run.

Per mesh: `medial skeleton MESH -o S.vtp` (the contraction's skeleton, default options), then
`medial rig S.vtp MESH -o R.glb --timings`; Blender 3.4 (headless) imports R.glb and measures Medial's
weights as imported, then removes them and binds the mesh to the same imported armature with
Object > Parent > With Automatic Weights (Root and the `_end` joints made non-deforming first, as a rigger
would), and measures those. Columns, for each of the two:
  seconds   Medial: the weights stage of `medial rig` (median of --repeat runs); Blender: the parent_set call
  moved     vertices a posed bone moves, mean over the bones: those whose weights for the bone and the bones
            below it sum to more than 1 % (a 30 degree turn moves them by more than 0.5 % of their distance
            to the joint)
  nearer    of those, the vertices whose nearest bone (Euclidean, to the bone segments) is not the bone or
            one below it, mean over the bones: what moves that should not
  unweighted  vertices no deforming bone weighs
  infl      most bones weighing one vertex
  dead      deforming bones that weigh no vertex
Prints a Markdown table and the ratios Blender / Medial of time, moved and nearer (medians over the meshes).
Needs `blender` on the PATH; without it the script says so and exits 0.
    /usr/bin/python3 bench/rig_blender_bench.py [--medial build/bin/medial] [--repeat N] [MESH...]
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
CGAL = os.path.join(HERE, "..", "data", "external", "cgal", "meshes")
DEFAULT = [os.path.join(CGAL, n + ".off") for n in ("elephant", "dino", "cow", "man", "armadillo", "hand",
                                                    "camel", "elk", "triceratops", "diplodocus")]

# Runs inside Blender: for each rig, the measures of its own weights, then of Blender's automatic weights on
# the imported armature. Prints one MEDIAL-RIG line of JSON per rig.
BLENDER_SCRIPT = r'''
import bpy, json, statistics, sys
import numpy
sys.path.insert(0, sys.argv[sys.argv.index("--") + 2])
from automatic_weights import rebind_with_automatic_weights
numpy.bool = bool  # Debian's Blender 3.4 glTF add-on uses numpy.bool, which numpy 1.24 removed

def deforming(arm):
    return [b for b in arm.data.bones if b.name.startswith("Bone_") and not b.name.endswith("_end")]

def weights(mesh, bones):
    column = {b.name: i for i, b in enumerate(bones)}
    group = {g.index: column.get(g.name, -1) for g in mesh.vertex_groups}
    w = numpy.zeros((len(mesh.data.vertices), len(bones)))
    for v in mesh.data.vertices:
        for g in v.groups:
            c = group.get(g.group, -1)
            if c >= 0 and g.weight > 0:
                w[v.index, c] = g.weight
    return w

def segment_distances(points, heads, tails):
    d = tails - heads
    t = numpy.clip(((points[:, None, :] - heads[None]) * d[None]).sum(2) / numpy.maximum((d * d).sum(1), 1e-30),
                   0, 1)
    closest = heads[None] + t[..., None] * d[None]
    return numpy.linalg.norm(points[:, None, :] - closest, axis=2)

def measures(mesh, arm, bones, points, nearest):
    w = weights(mesh, bones)
    sums = w.sum(1)
    normalized = w / numpy.where(sums > 0, sums, 1)[:, None]
    index = {b.name: i for i, b in enumerate(bones)}
    moved, nearer = [], []
    for b in bones:
        below = [index[b.name]] + [index[c.name] for c in b.children_recursive if c.name in index]
        moves = normalized[:, below].sum(1) > 0.01
        moved.append(int(moves.sum()))
        nearer.append(int((moves & ~numpy.isin(nearest, below)).sum()))
    return {"moved": statistics.mean(moved), "nearer": statistics.mean(nearer),
            "unweighted": int((sums == 0).sum()), "influences": int((w > 0).sum(1).max()),
            "dead": int(((w > 0).sum(0) == 0).sum())}

for path in json.load(open(sys.argv[sys.argv.index("--") + 1])):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=path)
    arm = next(o for o in bpy.data.objects if o.type == "ARMATURE")
    mesh = max((o for o in bpy.data.objects if o.type == "MESH"), key=lambda m: len(m.data.vertices))
    bones = deforming(arm)
    to_arm = arm.matrix_world.inverted() @ mesh.matrix_world
    points = numpy.array([list(to_arm @ v.co) for v in mesh.data.vertices])
    heads = numpy.array([list(b.head_local) for b in bones])
    tails = numpy.array([list(b.tail_local) for b in bones])
    for b in bones:  # a leaf bone's true end is its end joint's head
        end = arm.data.bones.get(b.name + "_end")
        if end is not None:
            tails[bones.index(b)] = list(end.head_local)
    nearest = segment_distances(points, heads, tails).argmin(1)
    report = {"file": path, "vertices": len(points), "bones": len(bones),
              "medial": measures(mesh, arm, bones, points, nearest)}
    for b in arm.data.bones:
        b.use_deform = b in bones
    report["blender_seconds"] = rebind_with_automatic_weights(arm, mesh)
    report["blender"] = measures(mesh, arm, bones, points, nearest)
    print("MEDIAL-RIG " + json.dumps(report), flush=True)
'''


def medial_weights(medial, mesh, directory, repeat):
    """The contraction's skeleton of `mesh`, its rig, and the median seconds of the rig's weights."""
    stem = os.path.join(directory, os.path.splitext(os.path.basename(mesh))[0])
    subprocess.run([medial, "skeleton", mesh, "-o", stem + ".vtp", "--quiet"], check=True)
    seconds = []
    for _ in range(repeat):
        done = subprocess.run([medial, "rig", stem + ".vtp", mesh, "-o", stem + ".glb", "--quiet", "--timings"],
                              check=True, capture_output=True, text=True)
        stages = json.loads(done.stdout.strip().splitlines()[-1])
        seconds.append(stages.get("weights", stages.get("total")))
    return stem + ".glb", statistics.median(seconds)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("meshes", nargs="*", default=DEFAULT)
    parser.add_argument("--medial", default=os.path.join(HERE, "..", "build", "bin", "medial"))
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    if not shutil.which("blender"):
        print("blender is not installed: nothing to compare with")
        return 0
    directory = tempfile.mkdtemp(prefix="medial-rig-bench-")
    rigs, medial_seconds = [], {}
    for mesh in args.meshes:
        rig, seconds = medial_weights(args.medial, mesh, directory, args.repeat)
        rigs.append(rig)
        medial_seconds[rig] = seconds
    script, listing = os.path.join(directory, "bench.py"), os.path.join(directory, "rigs.json")
    with open(script, "w") as f:
        f.write(BLENDER_SCRIPT)
    with open(listing, "w") as f:
        json.dump(rigs, f)
    helpers = os.path.join(HERE, "..", "tests", "blender")  # automatic_weights.py
    done = subprocess.run(["blender", "-b", "--factory-startup", "--python", script, "--", listing, helpers],
                          capture_output=True, text=True)
    reports = [json.loads(line[len("MEDIAL-RIG "):]) for line in done.stdout.splitlines()
               if line.startswith("MEDIAL-RIG ")]
    if len(reports) != len(rigs):
        print(done.stdout[-3000:], done.stderr[-3000:], file=sys.stderr)
        return 1
    print("| mesh | vertices | bones | seconds Medial / Blender | moved per bone Medial / Blender "
          "| nearer another bone Medial / Blender | unweighted Medial / Blender | infl. | dead bones |")
    print("|---|---|---|---|---|---|---|---|---|")
    ratios = {"time": [], "moved": [], "nearer": []}
    for r in reports:
        m, b = r["medial"], r["blender"]
        seconds = medial_seconds[r["file"]]
        print("| %s | %d | %d | %.2f / %.2f | %.0f / %.0f | %.0f / %.0f | %d / %d | %d / %d | %d / %d |" % (
            os.path.splitext(os.path.basename(r["file"]))[0], r["vertices"], r["bones"], seconds,
            r["blender_seconds"], m["moved"], b["moved"], m["nearer"], b["nearer"], m["unweighted"],
            b["unweighted"], m["influences"], b["influences"], m["dead"], b["dead"]))
        ratios["time"].append(r["blender_seconds"] / max(seconds, 1e-9))
        ratios["moved"].append(b["moved"] / max(m["moved"], 1e-9))
        ratios["nearer"].append(b["nearer"] / max(m["nearer"], 1e-9))
    print("\nmedian ratios Blender / Medial: time %.1f, moved per bone %.2f, nearer another bone %.2f" % tuple(
        statistics.median(ratios[k]) for k in ("time", "moved", "nearer")))
    shutil.rmtree(directory, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
