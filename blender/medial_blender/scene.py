"""Medial's results to Blender objects: an armature from a skeleton, vertex groups from skinning weights,
a mesh object from an SQM mesh. Everything made is linked to the scene only at the end, so that a failure
leaves the scene as it was."""
from collections import deque

import bmesh
import bpy
import mathutils
import numpy


def _tree(node_count, segments, root):
    """Each segment oriented away from root (head, tail) and the segment reaching each node (-1: none), by
    breadth-first search; a segment closing a cycle goes from its end nearer the root."""
    around = [[] for _ in range(node_count)]
    for s, (a, b) in enumerate(segments):
        around[a].append(s)
        around[b].append(s)
    depth = [-1] * node_count
    reaching = [-1] * node_count
    for start in [root] + list(range(node_count)):  # every component, the root's first
        if depth[start] >= 0:
            continue
        depth[start] = 0
        queue = deque([start])
        while queue:
            n = queue.popleft()
            for s in around[n]:
                other = segments[s][0] + segments[s][1] - n
                if depth[other] < 0:
                    depth[other], reaching[other] = depth[n] + 1, s
                    queue.append(other)
    oriented = []
    for s, (a, b) in enumerate(segments):
        if reaching[b] == s or (reaching[a] != s and depth[a] <= depth[b]):
            oriented.append((a, b))
        else:
            oriented.append((b, a))
    return oriented, reaching


def bone_names(oriented):
    """The names `medial skeleton --rig` gives its bones: Bone_<segment>_<head node>_<tail node>."""
    return ["Bone_%d_%d_%d" % (s, a, b) for s, (a, b) in enumerate(oriented)]


def add_armature(context, name, skeleton, root, up, matrix):
    """An armature object, linked to the scene's collection, with a bone per skeleton segment, named as
    bone_names(), parented from the root out and connected where they meet, and a non-deforming bone "Root"
    at the root node pointing up, parent of the bones leaving it. Returns (object, bone names in segment order)."""
    segments = skeleton.segments()
    oriented, reaching = _tree(len(skeleton.points), segments, root)
    names = bone_names(oriented)
    data = bpy.data.armatures.new(name)
    armature = bpy.data.objects.new(name, data)
    armature.matrix_world = matrix
    context.scene.collection.objects.link(armature)  # edit mode needs it in the scene; unlinked on failure
    previous = context.view_layer.objects.active
    context.view_layer.objects.active = armature
    bpy.ops.object.mode_set(mode="EDIT")
    try:
        points = [mathutils.Vector(p) for p in skeleton.points]
        lengths = [(points[a] - points[b]).length for a, b in oriented]
        root_bone = data.edit_bones.new("Root")
        root_bone.head = points[root]
        root_bone.tail = points[root] + mathutils.Vector(up) * (0.5 * float(numpy.median(lengths)))
        root_bone.use_deform = False
        bones = []
        for name_, (a, b) in zip(names, oriented):
            bone = data.edit_bones.new(name_)
            bone.head, bone.tail = points[a], points[b]
            bones.append(bone)
        for bone, (a, _) in zip(bones, oriented):
            parent = reaching[a]
            bone.parent = bones[parent] if parent >= 0 else root_bone
            bone.use_connect = parent >= 0
            bone.align_roll(mathutils.Vector(up))
    finally:
        bpy.ops.object.mode_set(mode="OBJECT")
        context.view_layer.objects.active = previous
    return armature, names


def set_weights(obj, names, weights, max_influences):
    """A vertex group per bone name (replacing groups of that name) holding the vertices' weights: per
    vertex its max_influences largest, renormalised to sum 1 (as the rig writer's --max-influences)."""
    weights = numpy.asarray(weights, dtype=float).reshape(len(obj.data.vertices), -1)
    if weights.shape[1] != len(names):
        raise ValueError("%d weights per vertex for %d bones" % (weights.shape[1], len(names)))
    keep = min(max_influences, len(names))
    strongest = numpy.argpartition(-weights, keep - 1, axis=1)[:, :keep] if keep < len(names) else \
        numpy.tile(numpy.arange(keep), (len(weights), 1))
    kept = numpy.take_along_axis(weights, strongest, axis=1)
    kept[kept < 1e-4] = 0.0
    kept /= numpy.maximum(kept.sum(axis=1, keepdims=True), 1e-12)
    groups = []
    for name in names:
        old = obj.vertex_groups.get(name)
        if old is not None:
            obj.vertex_groups.remove(old)
        groups.append(obj.vertex_groups.new(name=name).index)
    # Through bmesh's deform layer, one flat loop over the non-zero weights: three times as fast as
    # VertexGroup.add per vertex, and twice as fast as a nested loop per vertex.
    rows, columns = numpy.nonzero(kept > 0.0)
    group_of = numpy.asarray(groups)[strongest[rows, columns]]
    mesh = bmesh.new()
    mesh.from_mesh(obj.data)
    deform = mesh.verts.layers.deform.verify()
    mesh.verts.ensure_lookup_table()
    vertices = mesh.verts
    for vertex, group, weight in zip(rows.tolist(), group_of.tolist(), kept[rows, columns].tolist()):
        vertices[vertex][deform][group] = weight
    mesh.to_mesh(obj.data)
    mesh.free()
    obj.data.update()


def bind_to_armature(obj, armature):
    """Parents obj to armature (its place in the world kept) with one Armature modifier for it."""
    world = obj.matrix_world.copy()
    obj.parent = armature
    obj.matrix_parent_inverse = armature.matrix_world.inverted()
    obj.matrix_world = world
    modifier = next((m for m in obj.modifiers if m.type == "ARMATURE" and m.object == armature), None)
    if modifier is None:
        modifier = obj.modifiers.new("Armature", "ARMATURE")
        modifier.object = armature
    modifier.use_vertex_groups = True
    return modifier


def add_mesh(context, name, result, matrix):
    """A new mesh object of the .vtp result's points and polygons, linked to the scene's active collection
    and selected."""
    mesh = bpy.data.meshes.new(name)
    faces = [list(map(int, p)) for p in result.polys]
    mesh.from_pydata(result.points.tolist(), [], faces)
    mesh.validate()
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    obj.matrix_world = matrix
    context.collection.objects.link(obj)
    return obj
