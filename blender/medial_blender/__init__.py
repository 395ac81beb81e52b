"""Medial in Blender: rig a mesh (skeleton by contraction and heat weights), bind a mesh to your own
armature with Medial's heat weights, and mesh a skeleton with SQM. Runs the `medial` command."""
import bpy

from . import operators

bl_info = {
    "name": "Medial",
    "author": "Medial developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > Medial",
    "description": "Auto-rig, bind with heat weights and SQM tube meshes with the medial command",
    "category": "Rigging",
}


class MedialPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__
    medial_path: bpy.props.StringProperty(
        name="medial command", subtype="FILE_PATH", default="",
        description="the medial executable; empty: the one on PATH")

    def draw(self, context):
        self.layout.prop(self, "medial_path")


class MEDIAL_PT_panel(bpy.types.Panel):
    bl_label = "Medial"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Medial"

    def draw(self, context):
        layout = self.layout
        column = layout.column(align=True)
        column.label(text="Active mesh:")
        column.operator("medial.rig_mesh", icon="ARMATURE_DATA")
        column.separator()
        column.label(text="Mesh selected, armature active:")
        column.operator("medial.bind", icon="GROUP_BONE")
        column.separator()
        column.label(text="Skin edges or armature:")
        column.operator("medial.sqm_mesh", icon="MOD_SKIN")


CLASSES = (MedialPreferences, MEDIAL_PT_panel) + operators.CLASSES


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)


def unregister():
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
