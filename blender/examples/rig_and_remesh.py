"""The add-on as a script user drives it, run by scripts/demo inside headless Blender: installs
medial-blender.zip, imports a character (OBJ), rigs it (medial.rig_mesh), meshes the new armature with SQM
(medial.sqm_mesh) and writes the scene (.blend) and the SQM mesh (.obj).
Arguments after "--": ZIP MEDIAL MESH.obj OUT_STEM   (writes OUT_STEM.blend and OUT_STEM-sqm.obj)"""
import os
import sys

import addon_utils
import bpy

ZIP, MEDIAL, MESH, OUT_STEM = map(os.path.abspath, sys.argv[sys.argv.index("--") + 1:])

bpy.ops.preferences.addon_install(filepath=ZIP)
addon_utils.enable("medial_blender", default_set=True)
bpy.context.preferences.addons["medial_blender"].preferences.medial_path = MEDIAL

bpy.ops.wm.obj_import(filepath=MESH)  # Y-up file: Blender turns it Z-up, so the character stands
character = bpy.context.selected_objects[0]
bpy.context.view_layer.objects.active = character
if bpy.ops.medial.rig_mesh(nodes=20) != {"FINISHED"}:
    sys.exit("medial.rig_mesh failed")
armature = character.parent
deforming = [bone for bone in armature.data.bones if bone.use_deform]
print("MEDIAL-DEMO %s: %d bones (%d deforming), %d vertex groups, Armature modifier: %s"
      % (armature.name, len(armature.data.bones), len(deforming), len(character.vertex_groups),
         any(m.type == "ARMATURE" for m in character.modifiers)))

bpy.ops.object.select_all(action="DESELECT")
bpy.context.view_layer.objects.active = armature
armature.select_set(True)
if bpy.ops.medial.sqm_mesh(subdivide=1) != {"FINISHED"}:
    sys.exit("medial.sqm_mesh failed")
tube = bpy.context.view_layer.objects.active
quads = sum(1 for polygon in tube.data.polygons if len(polygon.vertices) == 4)
print("MEDIAL-DEMO %s: %d faces, %d quads" % (tube.name, len(tube.data.polygons), quads))

bpy.ops.object.select_all(action="DESELECT")
tube.select_set(True)
bpy.ops.wm.obj_export(filepath=OUT_STEM + "-sqm.obj", export_selected_objects=True, export_materials=False)
if bpy.ops.wm.save_as_mainfile(filepath=OUT_STEM + ".blend") != {"FINISHED"}:
    sys.exit("cannot write " + OUT_STEM + ".blend")
