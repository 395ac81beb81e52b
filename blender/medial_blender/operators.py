"""The add-on's operators. Each sends the selection to the `medial` command through temporary files, runs
it with a progress bar (Esc cancels; in background Blender it simply waits), then makes its objects: only
then, so that a failure (reported with self.report) leaves the scene unchanged. One undo step each."""
import bpy
import mathutils

from . import command, exchange, scene, vtp

UP_AXES = [(a, a, "the character's up direction in the scene") for a in ("Z", "Y", "X", "-Z", "-Y", "-X")]


def _up_vector(axis):
    vector = mathutils.Vector((0.0, 0.0, 0.0))
    vector["XYZ".index(axis[-1])] = -1.0 if axis.startswith("-") else 1.0
    return vector


def _medial_executable(context):
    addon = context.preferences.addons.get(__package__)
    return command.find_medial(addon.preferences.medial_path if addon else "")


class MedialOperator:
    """prepare() writes the inputs and returns the command's arguments; apply() reads the outputs and
    makes the objects. Runs modal with a timer when there is a window, blocking otherwise."""
    bl_options = {"REGISTER", "UNDO"}
    _timer = None

    def prepare(self, context, job):
        raise NotImplementedError

    def apply(self, context, job):
        raise NotImplementedError

    def _begin(self, context):
        self.job = None
        try:
            self.job = command.Job(_medial_executable(context))
            self.job.start(self.prepare(context, self.job))
        except (command.MedialError, exchange.InputError) as error:
            return self._fail(str(error))
        return None

    def _fail(self, message):
        self.report({"ERROR"}, message)
        if self.job:
            self.job.cleanup()
        return {"CANCELLED"}

    def _end(self, context):
        try:
            self.job.finish()
            self.apply(context, self.job)
            for note in self.job.notes():
                self.report({"INFO"}, note)
        except (command.MedialError, exchange.InputError, ValueError, KeyError, OSError) as error:
            return self._fail(str(error))
        self.job.cleanup()
        return {"FINISHED"}

    def execute(self, context):
        return self._begin(context) or self._end(context)

    def invoke(self, context, event):
        if context.window is None:
            return self.execute(context)
        failed = self._begin(context)
        if failed:
            return failed
        manager = context.window_manager
        self._timer = manager.event_timer_add(0.1, window=context.window)
        manager.progress_begin(0, 100)
        manager.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def _stop_modal(self, context):
        manager = context.window_manager
        manager.event_timer_remove(self._timer)
        manager.progress_end()
        context.workspace.status_text_set(None)

    def modal(self, context, event):
        if event.type == "ESC":
            self._stop_modal(context)
            self.job.cancel()
            return self._fail("Medial: cancelled")
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        if self.job.running():
            context.window_manager.progress_update(int(100 * self.job.progress))
            context.workspace.status_text_set("Medial: %s %d%% (Esc cancels)" % (self.job.stage or "starting",
                                                                                 int(100 * self.job.progress)))
            return {"RUNNING_MODAL"}
        self._stop_modal(context)
        return self._end(context)


def _heat_property():
    return bpy.props.FloatProperty(name="Heat", default=1.0, min=1e-3, max=100.0,
                                   description="c of the heat weights' H = c / d^2, as Blender's bone heat: "
                                               "larger binds vertices more to their nearest bone")


def _influences_property():
    return bpy.props.IntProperty(name="Max Influences", default=4, min=1, max=16,
                                 description="most bones per vertex (the largest weights, renormalised)")


class MEDIAL_OT_rig_mesh(MedialOperator, bpy.types.Operator):
    """Skeleton by mesh contraction and heat weights: a new armature with the mesh bound to it"""
    bl_idname = "medial.rig_mesh"
    bl_label = "Rig Mesh"
    nodes: bpy.props.IntProperty(name="Nodes", default=30, min=0, max=10000,
                                 description="the skeleton's node count (0 keeps all the curve skeleton's)")
    heat: _heat_property()
    max_influences: _influences_property()
    up_axis: bpy.props.EnumProperty(name="Up", items=UP_AXES, default="Z")
    use_transform: bpy.props.BoolProperty(
        name="Apply Transform", default=True,
        description="compute the skeleton of the mesh as it lies in the scene (location, rotation, scale "
                    "applied); off: in the mesh's own coordinates")

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == "MESH" and context.mode == "OBJECT"

    def prepare(self, context, job):
        obj = context.active_object
        exchange.require_closed_mesh(obj)
        matrix = obj.matrix_world if self.use_transform else None
        exchange.write_ply(job.path("mesh.ply"), exchange.vertex_positions(obj.data, matrix),
                           exchange.triangles(obj.data))
        return ["skeleton", "mesh.ply", "-o", "skeleton.vtp", "--segmentation", "weights.vtp", "--weights",
                "--nodes", self.nodes, "--heat", self.heat]

    def apply(self, context, job):
        obj = context.active_object
        skeleton = vtp.read(job.path("skeleton.vtp"))
        weights = vtp.read(job.path("weights.vtp"), only=["SkinWeights"]).point_data["SkinWeights"]
        root = int(skeleton.field_data["Root"][0]) if "Root" in skeleton.field_data else 0
        up = _up_vector(self.up_axis)
        matrix = mathutils.Matrix.Identity(4) if self.use_transform else obj.matrix_world.copy()
        if not self.use_transform:
            up = (obj.matrix_world.to_3x3().inverted() @ up).normalized()
        armature, names = scene.add_armature(context, obj.name + "_rig", skeleton, root, up, matrix)
        try:
            scene.set_weights(obj, names, weights, self.max_influences)
            scene.bind_to_armature(obj, armature)
        except Exception:
            bpy.data.objects.remove(armature)
            raise


class MEDIAL_OT_bind(MedialOperator, bpy.types.Operator):
    """Medial's heat weights for the active armature's deforming bones on the selected mesh, in vertex
    groups named after the bones, with an Armature modifier (where "With Automatic Weights" fails)"""
    bl_idname = "medial.bind"
    bl_label = "Bind to Armature"
    heat: _heat_property()
    max_influences: _influences_property()

    @classmethod
    def poll(cls, context):
        armature = context.active_object
        return (armature is not None and armature.type == "ARMATURE" and context.mode == "OBJECT"
                and any(o.type == "MESH" for o in context.selected_objects))

    def prepare(self, context, job):
        armature = context.active_object
        meshes = [o for o in context.selected_objects if o.type == "MESH"]
        if len(meshes) != 1:
            raise exchange.InputError("select one mesh, then the armature (active)")
        self.mesh_name = meshes[0].name
        exchange.require_closed_mesh(meshes[0])
        self.bones = [b.name for b in armature.data.bones if b.use_deform]
        deforming = [armature.data.bones[name] for name in self.bones]
        skeleton = exchange.armature_skeleton(armature, deforming, armature.matrix_world)
        vtp.write(job.path("skeleton.vtp"), skeleton)
        exchange.write_ply(job.path("mesh.ply"), exchange.vertex_positions(meshes[0].data, meshes[0].matrix_world),
                           exchange.triangles(meshes[0].data))
        return ["rig", "skeleton.vtp", "mesh.ply", "--weights", "weights.vtp", "--heat", self.heat]

    def apply(self, context, job):
        weights = vtp.read(job.path("weights.vtp"), only=["SkinWeights"]).point_data["SkinWeights"]
        obj = bpy.data.objects[self.mesh_name]
        scene.set_weights(obj, self.bones, weights, self.max_influences)
        scene.bind_to_armature(obj, context.active_object)


class MEDIAL_OT_sqm_mesh(MedialOperator, bpy.types.Operator):
    """SQM: a closed quad-dominant mesh around a skeleton (a mesh of edges with Skin modifier radii, or an
    armature with its bones' envelope radii)"""
    bl_idname = "medial.sqm_mesh"
    bl_label = "SQM Mesh"
    subdivide: bpy.props.IntProperty(name="Subdivision", default=0, min=0, max=6,
                                     description="levels of tessellation projected on the swept spheres")
    union: bpy.props.BoolProperty(name="Union", default=False,
                                  description="where tubes of parts that are not neighbours overlap, mesh the "
                                              "boundary of their union (one surface, no self-intersections)")
    capsule: bpy.props.BoolProperty(name="Capsules", default=False,
                                    description="close leaves with capsules instead of cones")

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type in ("MESH", "ARMATURE") and context.mode == "OBJECT"

    def prepare(self, context, job):
        obj = context.active_object
        if obj.type == "ARMATURE":
            skeleton = exchange.armature_skeleton(obj, list(obj.data.bones), mathutils.Matrix.Identity(4))
        else:
            skeleton = exchange.skin_skeleton(obj)
        vtp.write(job.path("skeleton.vtp"), skeleton)
        args = ["sqm", "skeleton.vtp", "-o", "mesh.vtp", "--subdivide", self.subdivide]
        return args + (["--union"] if self.union else []) + (["--capsule"] if self.capsule else [])

    def apply(self, context, job):
        obj = context.active_object
        result = vtp.read(job.path("mesh.vtp"))
        made = scene.add_mesh(context, obj.name + "_sqm", result, obj.matrix_world.copy())
        for other in context.selected_objects:
            other.select_set(False)
        made.select_set(True)
        context.view_layer.objects.active = made


CLASSES = (MEDIAL_OT_rig_mesh, MEDIAL_OT_bind, MEDIAL_OT_sqm_mesh)
