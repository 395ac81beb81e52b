"""Run inside Blender by test_addon.py: installs medial-blender.zip as a user does, enables it, runs its
operators on sample meshes and prints what it found as MEDIAL-ADDON <json> lines.
Arguments after "--": ZIP MEDIAL ELEPHANT_OBJ MAN_OFF ARMADILLO_OFF"""
import json
import statistics
import subprocess
import sys
import time

import bmesh
import bpy

ZIP, MEDIAL, ELEPHANT_OBJ, MAN_OFF, ARMADILLO_OFF = sys.argv[sys.argv.index("--") + 1:]


def report(name, **facts):
    print("MEDIAL-ADDON " + json.dumps(dict(check=name, **facts)), flush=True)


def read_off(path):
    with open(path) as stream:
        tokens = [t for line in stream for t in line.split("#")[0].split()]
    n, m = int(tokens[1]), int(tokens[2])
    numbers = tokens[4:]
    vertices = [tuple(map(float, numbers[3 * i:3 * i + 3])) for i in range(n)]
    faces, at = [], 3 * n
    for _ in range(m):
        k = int(numbers[at])
        faces.append(tuple(map(int, numbers[at + 1:at + 1 + k])))
        at += 1 + k
    return vertices, faces


def add_object(name, vertices, edges, faces):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, edges, faces)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.collection.objects.link(obj)
    return obj


def make_active(obj, *selected):
    bpy.ops.object.select_all(action="DESELECT")
    for other in (obj,) + selected:
        other.select_set(True)
    bpy.context.view_layer.objects.active = obj


def run(operator, **options):
    """(result, error message or None, seconds)"""
    start = time.perf_counter()
    try:
        result = operator(**options)
        return sorted(result), None, time.perf_counter() - start
    except RuntimeError as error:
        return None, str(error), time.perf_counter() - start


def weighting(obj):
    """(vertices without weight, largest |sum of weights - 1|, bone of largest weight per vertex)"""
    names = {g.index: g.name for g in obj.vertex_groups}
    unweighted, worst, strongest = 0, 0.0, []
    for v in obj.data.vertices:
        groups = [g for g in v.groups if g.weight > 0]
        if not groups:
            unweighted += 1
            strongest.append(None)
            continue
        worst = max(worst, abs(sum(g.weight for g in groups) - 1.0))
        strongest.append(names[max(groups, key=lambda g: g.weight).group])
    return unweighted, worst, strongest


def manifold_facts(obj):
    bm = bmesh.new()
    bm.from_mesh(obj.data)
    facts = dict(faces=len(bm.faces), quads=sum(1 for f in bm.faces if len(f.verts) == 4),
                 open_edges=sum(1 for e in bm.edges if not e.is_manifold or e.is_boundary),
                 bad_vertices=sum(1 for v in bm.verts if not v.is_manifold))
    bm.free()
    return facts


def armature_facts(armature):
    bones = armature.data.bones
    world = armature.matrix_world
    heads = [world @ b.head_local for b in bones]
    extent = [max(h[i] for h in heads) - min(h[i] for h in heads) for i in range(3)]
    return dict(bones=len(bones), deforming=sum(1 for b in bones if b.use_deform),
                root=[b.name for b in bones if b.parent is None], extent=extent,
                root_height=(world @ bones["Root"].head_local).z if "Root" in bones else None,
                root_deforms=bones["Root"].use_deform if "Root" in bones else None)


def install():
    bpy.ops.preferences.addon_install(filepath=ZIP)
    bpy.ops.preferences.addon_enable(module="medial_blender")
    preferences = bpy.context.preferences.addons["medial_blender"].preferences
    preferences.medial_path = MEDIAL
    import medial_blender
    report("install", module=medial_blender.__file__, panel=hasattr(bpy.types, "MEDIAL_PT_panel"),
           operators=[name for name in ("rig_mesh", "bind", "sqm_mesh") if hasattr(bpy.ops.medial, name)])


def check_rig_elephant():
    bpy.ops.wm.obj_import(filepath=ELEPHANT_OBJ)
    elephant = bpy.context.selected_objects[0]
    make_active(elephant)
    result, error, _ = run(bpy.ops.medial.rig_mesh, nodes=25)
    armature = bpy.data.objects.get(elephant.name + "_rig")
    unweighted, worst, _ = weighting(elephant)
    report("rig_elephant", result=result, error=error, vertices=len(elephant.data.vertices),
           armature=armature_facts(armature) if armature else None, parent=elephant.parent.name if elephant.parent else None,
           modifiers=[(m.type, m.object.name if m.object else None) for m in elephant.modifiers],
           groups=len(elephant.vertex_groups), unweighted=unweighted, sum_error=worst)
    # Undo takes the operator back in one step: no armature, no groups, no modifier.
    undo = bpy.ops.ed.undo.poll()
    if undo:
        bpy.ops.ed.undo()
    elephant = bpy.data.objects.get(elephant.name)
    report("undo_rig", can_undo=undo, armatures=sum(1 for o in bpy.data.objects if o.type == "ARMATURE" and o.users_scene),
           groups=len(elephant.vertex_groups) if elephant else None, modifiers=len(elephant.modifiers) if elephant else None)


def check_rig_man():
    """The CGAL man (Z-up, where Blender's bone heat leaves every vertex unweighted): stands, root at the
    hips; the operator timed against the command it runs."""
    vertices, faces = read_off(MAN_OFF)
    man = add_object("man", vertices, [], faces)
    make_active(man)
    from medial_blender import exchange
    exchange.write_ply("/tmp/medial-addon-man.ply", exchange.vertex_positions(man.data, man.matrix_world),
                       exchange.triangles(man.data))
    command = [MEDIAL, "skeleton", "/tmp/medial-addon-man.ply", "-o", "/tmp/medial-addon-man.vtp", "--segmentation",
               "/tmp/medial-addon-man-weights.vtp", "--weights", "--nodes", "30", "--heat", "1.0"]
    # Interleaved, so that a busy machine slows both alike; medians of five.
    times, command_times = [], []
    for attempt in range(5):
        for other in [o for o in bpy.data.objects if o.type == "ARMATURE"]:
            bpy.data.objects.remove(other)
        man.modifiers.clear()
        man.vertex_groups.clear()
        man.parent = None
        make_active(man)
        result, error, seconds = run(bpy.ops.medial.rig_mesh)
        times.append(seconds)
        start = time.perf_counter()
        subprocess.run(command, check=True, capture_output=True)
        command_times.append(time.perf_counter() - start)
    armature = bpy.data.objects.get("man_rig")
    unweighted, worst, _ = weighting(man)
    z = [v[2] for v in vertices]
    report("rig_man", result=result, error=error, armature=armature_facts(armature) if armature else None,
           height=max(z) - min(z), bottom=min(z), unweighted=unweighted, sum_error=worst,
           operator_seconds=statistics.median(times), command_seconds=statistics.median(command_times))


def cylinder(name, rings=16, around=24, height=3.0, radius=0.4):
    import math
    vertices = [(radius * math.cos(2 * math.pi * k / around), radius * math.sin(2 * math.pi * k / around),
                 height * r / (rings - 1)) for r in range(rings) for k in range(around)]
    vertices += [(0.0, 0.0, 0.0), (0.0, 0.0, height)]
    faces = [(r * around + k, r * around + (k + 1) % around, (r + 1) * around + (k + 1) % around,
              (r + 1) * around + k) for r in range(rings - 1) for k in range(around)]
    bottom, top = rings * around, rings * around + 1
    faces += [(bottom, (k + 1) % around, k) for k in range(around)]
    faces += [(top, (rings - 1) * around + k, (rings - 1) * around + (k + 1) % around) for k in range(around)]
    return add_object(name, vertices, [], faces)


def three_bone_armature(name, envelope=0.0):
    data = bpy.data.armatures.new(name)
    armature = bpy.data.objects.new(name, data)
    bpy.context.collection.objects.link(armature)
    make_active(armature)
    bpy.ops.object.mode_set(mode="EDIT")
    parent = None
    for k in range(3):
        bone = data.edit_bones.new("Bone")
        bone.head, bone.tail = (0.0, 0.0, 0.2 + 0.9 * k), (0.0, 0.0, 0.2 + 0.9 * (k + 1))
        if envelope:
            bone.head_radius = bone.tail_radius = envelope
        bone.parent, bone.use_connect, parent = parent, parent is not None, bone
    bpy.ops.object.mode_set(mode="OBJECT")
    return armature


def check_bind():
    body = cylinder("cylinder")
    armature = three_bone_armature("three_bones")
    make_active(armature, body)
    result, error, _ = run(bpy.ops.medial.bind)
    unweighted, worst, strongest = weighting(body)
    names = [b.name for b in armature.data.bones]
    low = [s for v, s in zip(body.data.vertices, strongest) if v.co.z < 0.6]
    high = [s for v, s in zip(body.data.vertices, strongest) if v.co.z > 2.4]
    report("bind", result=result, error=error, groups=sorted(g.name for g in body.vertex_groups), bones=names,
           parent=body.parent.name if body.parent else None, modifiers=[m.type for m in body.modifiers],
           unweighted=unweighted, sum_error=worst, low_first=sum(1 for s in low if s == names[0]) / len(low),
           high_last=sum(1 for s in high if s == names[2]) / len(high))


def skin_tree():
    """A figure of edges: a spine with two arms and two legs, radii set as the Skin modifier takes them."""
    vertices = [(0, 0, 1.0), (0, 0, 1.5), (0, 0, 2.0), (0, 0, 2.4), (-0.5, 0, 1.9), (-1.0, 0, 1.8),
                (0.5, 0, 1.9), (1.0, 0, 1.8), (-0.2, 0, 0.5), (-0.25, 0, 0.0), (0.2, 0, 0.5), (0.25, 0, 0.0)]
    edges = [(0, 1), (1, 2), (2, 3), (2, 4), (4, 5), (2, 6), (6, 7), (0, 8), (8, 9), (0, 10), (10, 11)]
    obj = add_object("skin_tree", vertices, edges, [])
    make_active(obj)
    obj.modifiers.new("Skin", "SKIN")
    for k, skin in enumerate(obj.data.skin_vertices[0].data):
        skin.radius = (0.2, 0.16) if k not in (3,) else (0.25, 0.25)
    return obj


def check_sqm():
    tree = skin_tree()
    result, error, _ = run(bpy.ops.medial.sqm_mesh, subdivide=1)
    made = bpy.data.objects.get("skin_tree_sqm")
    report("sqm_skin", result=result, error=error, **(manifold_facts(made) if made else {}))
    armature = three_bone_armature("enveloped", envelope=0.3)
    make_active(armature)
    result, error, _ = run(bpy.ops.medial.sqm_mesh, subdivide=1, capsule=True)
    made = bpy.data.objects.get("enveloped_sqm")
    report("sqm_armature", result=result, error=error, **(manifold_facts(made) if made else {}))


def check_refusals():
    objects = len(bpy.data.objects)
    bpy.ops.mesh.primitive_plane_add()
    plane = bpy.context.active_object
    objects += 1
    result, error, _ = run(bpy.ops.medial.rig_mesh)
    report("open_plane", result=result, error=error, objects_changed=len(bpy.data.objects) - objects,
           groups=len(plane.vertex_groups), modifiers=len(plane.modifiers))
    edges = add_object("no_radii", [(0, 0, 0), (0, 0, 1), (0, 0, 2)], [(0, 1), (1, 2)], [])
    make_active(edges)
    objects += 1
    result, error, _ = run(bpy.ops.medial.sqm_mesh)
    report("no_radii", result=result, error=error, objects_changed=len(bpy.data.objects) - objects)
    preferences = bpy.context.preferences.addons["medial_blender"].preferences
    preferences.medial_path = "/nonexistent/medial"
    tree = skin_tree()
    objects += 1
    result, error, _ = run(bpy.ops.medial.sqm_mesh)
    report("not_found", result=result, error=error, objects_changed=len(bpy.data.objects) - objects)
    preferences.medial_path = MEDIAL


def check_cancel():
    """Esc in the modal operator calls Job.cancel(): the command stops at once, its folder is removed."""
    import os
    from medial_blender import command
    job = command.Job(MEDIAL)
    job.start(["skeleton", ARMADILLO_OFF, "-o", "skeleton.vtp", "--contraction-vertices", "0", "--weights"])
    time.sleep(1.0)
    was_running = job.running()
    start = time.perf_counter()
    job.cancel()
    stopped = time.perf_counter() - start
    try:
        job.finish()
        message = None
    except command.MedialError as error:
        message = str(error)
    job.cleanup()
    report("cancel", was_running=was_running, stop_seconds=stopped, message=message,
           progress_seen=job.stage, folder_left=os.path.exists(job.folder))


install()
for check in (check_rig_elephant, check_rig_man, check_bind, check_sqm, check_refusals, check_cancel):
    try:
        check()
    except Exception as error:  # reported, so that the other checks still run
        import traceback
        report(check.__name__, crashed=traceback.format_exc())
