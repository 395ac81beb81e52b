"""Run inside Blender: blender -b --factory-startup --python pose_rig.py -- RIG OUT.obj [DEGREES]
Imports a rig (.glb/.fbx) as a user would, turns one limb's bone by DEGREES (default 40) about its own X
axis, and exports the posed (armature-deformed) mesh as OBJ, so that a picture shows the rig bending.
The limb: of the bones whose head lies farther than a third of the armature's size from the root, the one
driving the most vertices. Prints MEDIAL-POSE {json} with the bone and how many vertices moved."""
import json
import math
import sys

import bpy
import numpy

numpy.bool = bool  # Debian's Blender 3.4 glTF add-on uses numpy.bool, which numpy 1.24 removed


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    rig, out = args[0], args[1]
    degrees = float(args[2]) if len(args) > 2 else 40.0
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if rig.lower().endswith(".fbx"):
        bpy.ops.import_scene.fbx(filepath=rig)
    else:
        bpy.ops.import_scene.gltf(filepath=rig)
    arm = next(o for o in bpy.data.objects if o.type == "ARMATURE")
    mesh = max((o for o in bpy.data.objects if o.type == "MESH"), key=lambda m: len(m.data.vertices))
    groups = {g.index: g.name for g in mesh.vertex_groups}
    counts = {}
    for v in mesh.data.vertices:
        for g in v.groups:
            if g.weight > 0.5 and g.group in groups:
                counts[groups[g.group]] = counts.get(groups[g.group], 0) + 1
    # The root node: where the bones under the root joint start (Medial's Root stands on the ground).
    top = [b for b in arm.data.bones if b.parent is not None and b.parent.parent is None]
    root = (top[0] if top else next(b for b in arm.data.bones if b.parent is None)).head_local
    size = max((b.head_local - root).length for b in arm.data.bones) or 1.0
    limbs = [b.name for b in arm.data.bones if (b.head_local - root).length > size / 3 and b.name in counts]
    bone = max(limbs or counts, key=counts.get)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    before = [v.co.copy() for v in mesh.evaluated_get(depsgraph).to_mesh().vertices]
    pose = arm.pose.bones[bone]
    pose.rotation_mode = "XYZ"
    pose.rotation_euler = (math.radians(degrees), 0, 0)
    bpy.context.view_layer.update()
    depsgraph = bpy.context.evaluated_depsgraph_get()
    after = [v.co.copy() for v in mesh.evaluated_get(depsgraph).to_mesh().vertices]
    moved = sum(1 for a, b in zip(before, after) if (a - b).length > 1e-4 * size)
    bpy.ops.object.select_all(action="DESELECT")
    mesh.select_set(True)
    bpy.context.view_layer.objects.active = mesh
    bpy.ops.wm.obj_export(filepath=out, export_selected_objects=True, apply_modifiers=True,
                          export_materials=False)  # Y up, as Medial and glTF
    print("MEDIAL-POSE " + json.dumps({"bone": bone, "degrees": degrees, "moved": moved,
                                       "vertices": len(after)}))


main()
