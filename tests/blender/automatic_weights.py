"""Run inside Blender: re-binds an imported rig's mesh to its armature with Blender's own automatic weights
(Object > Parent > With Automatic Weights, bone heat), as a rigger would - the rig's weights and armature
modifier removed first. Shared by tests/blender/blender_report.py and bench/rig_blender_bench.py."""
import time

import bpy


def rebind_with_automatic_weights(arm, mesh):
    """Returns the seconds Blender's parent_set took."""
    mesh.vertex_groups.clear()
    for m in list(mesh.modifiers):
        mesh.modifiers.remove(m)
    bpy.ops.object.select_all(action="DESELECT")
    mesh.select_set(True)
    arm.select_set(True)
    bpy.context.view_layer.objects.active = arm
    start = time.perf_counter()
    bpy.ops.object.parent_set(type="ARMATURE_AUTO")
    return time.perf_counter() - start
