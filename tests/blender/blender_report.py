"""Run inside Blender: blender -b --factory-startup --python blender_report.py -- FILE...
Imports each rig (.glb/.gltf/.fbx) or mesh (.obj/.ply) into an empty scene and prints one JSON line per file
with what a user would check: armatures, bones, root bones, weighted vertices, weight sums, influences,
whether rotating one bone by 30 degrees moves some vertices and not all, and for meshes: closed, manifold,
quad share."""
import json
import math
import os
import sys
import time

import bpy
import bmesh
import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from automatic_weights import rebind_with_automatic_weights  # noqa: E402

numpy.bool = bool  # Debian's Blender 3.4 glTF add-on uses numpy.bool, which numpy 1.24 removed


def clear_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def import_file(path):
    lower = path.lower()
    if lower.endswith((".glb", ".gltf")):
        bpy.ops.import_scene.gltf(filepath=path)
    elif lower.endswith(".fbx"):
        bpy.ops.import_scene.fbx(filepath=path)
    elif lower.endswith(".obj"):
        bpy.ops.wm.obj_import(filepath=path)
    elif lower.endswith(".ply"):
        bpy.ops.import_mesh.ply(filepath=path)
    else:
        raise ValueError("unknown file type: " + path)


def evaluated_vertices(obj):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    mesh = obj.evaluated_get(depsgraph).to_mesh()
    coords = [obj.matrix_world @ v.co for v in mesh.vertices]
    obj.evaluated_get(depsgraph).to_mesh_clear()
    return coords


def rig_report(armatures, meshes):
    arm = armatures[0]
    bones = arm.data.bones
    report = {"armatures": len(armatures), "bones": len(bones),
              "roots": sum(1 for b in bones if b.parent is None)}
    mesh = max(meshes, key=lambda m: len(m.data.vertices))
    groups = {g.index: g.name for g in mesh.vertex_groups}
    names = set(b.name for b in bones)
    sums, influences = [], []
    for v in mesh.data.vertices:
        weights = [g.weight for g in v.groups if groups.get(g.group) in names and g.weight > 0]
        sums.append(sum(weights))
        influences.append(len(weights))
    report.update(vertices=len(mesh.data.vertices), weighted=sum(1 for s in sums if s > 0),
                  min_sum=min(sums), max_sum=max(sums), max_influences=max(influences),
                  modifier=any(m.type == "ARMATURE" and m.object == arm for m in mesh.modifiers))
    # Pose one bone that drives vertices: the one with the most weighted vertices.
    counts = {}
    for v in mesh.data.vertices:
        for g in v.groups:
            if g.weight > 0 and groups.get(g.group) in names:
                counts[groups[g.group]] = counts.get(groups[g.group], 0) + 1
    before = evaluated_vertices(mesh)
    posed = max(counts, key=counts.get) if counts else None
    moved = 0
    finite = True
    if posed:
        pose_bone = arm.pose.bones[posed]
        pose_bone.rotation_mode = "XYZ"
        pose_bone.rotation_euler = (math.radians(30), 0, 0)
        bpy.context.view_layer.update()
        after = evaluated_vertices(mesh)
        scale = max((b - a).length for a in before for b in before[:1]) or 1.0
        moved = sum(1 for a, b in zip(before, after) if (a - b).length > 1e-4 * scale)
        finite = all(math.isfinite(c) for v in after for c in v)
    report.update(posed=posed, moved=moved, finite=finite)
    # Rest pose: where each bone's head sits, for comparing formats.
    report["heads"] = {b.name: [round(c, 4) for c in (arm.matrix_world @ b.head_local)] for b in bones}
    # The armature as Blender built it (world space): each bone's parent, head and tail.
    report["structure"] = {b.name: {"parent": b.parent.name if b.parent else None,
                                    "head": list(arm.matrix_world @ b.head_local),
                                    "tail": list(arm.matrix_world @ b.tail_local)} for b in bones}
    world = [mesh.matrix_world @ v.co for v in mesh.data.vertices]
    report["extent"] = [max(p[c] for p in world) - min(p[c] for p in world) for c in range(3)]
    report["dead"] = sorted(b.name for b in bones if b.name.startswith("Bone_") and not b.name.endswith("_end")
                            and b.name not in counts)
    report.update(automatic_weights(arm, mesh))
    return report


def automatic_weights(arm, mesh):
    """What a rigger gets who re-binds the mesh to the imported armature with Blender's automatic weights
    (Object > Parent > With Automatic Weights, every imported bone deforming): vertices per bone."""
    pose_bone = max(arm.pose.bones, key=lambda b: abs(b.rotation_euler[0]))
    pose_bone.rotation_euler = (0, 0, 0)
    bpy.context.view_layer.update()
    rebind_with_automatic_weights(arm, mesh)
    groups = {g.index: g.name for g in mesh.vertex_groups}
    per_bone = {}
    for v in mesh.data.vertices:
        for g in v.groups:
            if g.weight > 0:
                per_bone[groups[g.group]] = per_bone.get(groups[g.group], 0) + 1
    return {"automatic": per_bone}


def mesh_report(meshes):
    mesh = max(meshes, key=lambda m: len(m.data.vertices))
    bm = bmesh.new()
    bm.from_mesh(mesh.data)
    boundary = sum(1 for e in bm.edges if e.is_boundary)
    non_manifold = sum(1 for e in bm.edges if not e.is_manifold and not e.is_boundary)
    quads = sum(1 for f in bm.faces if len(f.verts) == 4)
    report = {"vertices": len(bm.verts), "faces": len(bm.faces), "boundary_edges": boundary,
              "non_manifold_edges": non_manifold, "quad_share": quads / max(1, len(bm.faces))}
    bm.free()
    return report


def main():
    paths = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    for path in paths:
        clear_scene()
        start = time.monotonic()
        try:
            import_file(path)
        except Exception as e:  # the test reads the error from the report
            print("MEDIAL-REPORT " + json.dumps({"file": path, "error": str(e)}))
            continue
        seconds = time.monotonic() - start
        armatures = [o for o in bpy.data.objects if o.type == "ARMATURE"]
        meshes = [o for o in bpy.data.objects if o.type == "MESH"]
        report = {"file": path, "import_seconds": round(seconds, 3)}
        if not meshes:
            report["error"] = "no mesh imported"
        elif armatures:
            report.update(rig_report(armatures, meshes))
        else:
            report.update(armatures=0)
            report.update(mesh_report(meshes))
        print("MEDIAL-REPORT " + json.dumps(report))


main()
