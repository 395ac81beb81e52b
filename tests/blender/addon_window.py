"""Run inside Blender with a window (under Xvfb, with --enable-event-simulate) by test_addon.py: the
operators as a user runs them from the panel (invoked: modal, progress in the status bar), Esc cancelling
one, Ctrl Z undoing one, and a screenshot of the panel. Prints MEDIAL-ADDON <json> lines.
Arguments after "--": ZIP MEDIAL ELEPHANT_OBJ BIG_OFF SCREENSHOT_PNG"""
import json
import sys
import time

import bpy

ZIP, MEDIAL, ELEPHANT_OBJ, BIG_OFF, SCREENSHOT = sys.argv[sys.argv.index("--") + 1:]


def report(name, **facts):
    print("MEDIAL-ADDON " + json.dumps(dict(check=name, **facts)), flush=True)


def view3d():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == "VIEW_3D")
    region = next(r for r in area.regions if r.type == "WINDOW")
    return window, area, region


def invoke(operator):
    window, area, region = view3d()
    with bpy.context.temp_override(window=window, area=area, region=region):
        return sorted(operator("INVOKE_DEFAULT"))


def select_only(obj):
    for other in bpy.context.scene.objects:
        if other is not None:
            other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def steps():
    """The session, one step per timer call; yields seconds to wait before the next."""
    bpy.context.window_manager.windows[0].event_simulate(type="ESC", value="PRESS")  # closes the splash
    bpy.ops.preferences.addon_install(filepath=ZIP)
    bpy.ops.preferences.addon_enable(module="medial_blender")
    bpy.context.preferences.addons["medial_blender"].preferences.medial_path = MEDIAL
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    bpy.ops.wm.obj_import(filepath=ELEPHANT_OBJ)
    elephant = bpy.context.selected_objects[0]
    select_only(elephant)
    bpy.ops.ed.undo_push(message="elephant imported")
    yield 0.5

    # Rig from the panel: modal, then finished; the status bar showed the stage meanwhile.
    start = time.perf_counter()
    invoked = invoke(bpy.ops.medial.rig_mesh)
    status = []
    while not bpy.data.objects.get(elephant.name + "_rig") and time.perf_counter() - start < 60:
        status.append(bpy.context.workspace.status_text_set.__name__ and len(bpy.context.window_manager.operators))
        yield 0.1
    armature = bpy.data.objects.get(elephant.name + "_rig")
    report("modal_rig", invoked=invoked, finished=armature is not None, seconds=time.perf_counter() - start,
           groups=len(elephant.vertex_groups), last_operator=bpy.context.window_manager.operators[-1].bl_idname
           if bpy.context.window_manager.operators else None)
    yield 0.5

    # Ctrl Z: one step takes the whole operator back.
    window, area, region = view3d()
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.ed.undo()
    yield 0.5
    elephant = bpy.data.objects.get("elephant")
    report("undo_rig", armatures=sum(1 for o in bpy.context.scene.objects if o.type == "ARMATURE"),
           groups=len(elephant.vertex_groups), modifiers=len(elephant.modifiers), parent=bool(elephant.parent))
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.ed.redo()
    yield 0.5

    # Esc while the big (26,000 vertices contracted as they are) is being rigged.
    from medial_blender import command  # noqa: F401  (the add-on is enabled: its modules are importable)
    bpy.ops.object.select_all(action="DESELECT")
    big_objects = len(bpy.data.objects)
    import bmesh  # the big as a mesh object
    tokens = [t for line in open(BIG_OFF) for t in line.split("#")[0].split()]
    n, m = int(tokens[1]), int(tokens[2])
    numbers = tokens[4:]
    vertices = [tuple(map(float, numbers[3 * i:3 * i + 3])) for i in range(n)]
    faces = [tuple(map(int, numbers[3 * n + 4 * f + 1:3 * n + 4 * f + 4])) for f in range(m)]
    mesh = bpy.data.meshes.new("big")
    mesh.from_pydata(vertices, [], faces)
    big = bpy.data.objects.new("big", mesh)
    bpy.context.collection.objects.link(big)
    big.scale = (0.01, 0.01, 0.01)
    select_only(big)
    big_objects += 1
    start = time.perf_counter()
    invoked = invoke(lambda mode: bpy.ops.medial.rig_mesh(mode, nodes=0))
    yield 0.05
    window.event_simulate(type="ESC", value="PRESS")
    yield 0.5
    cancel_seconds = time.perf_counter() - start
    report("modal_cancel", invoked=invoked, objects_changed=len(bpy.data.objects) - big_objects,
           groups=len(big.vertex_groups), seconds=cancel_seconds)
    bpy.data.objects.remove(big)

    # The picture for docs/blender.md: the elephant's rig, the Medial tab of the sidebar open.
    elephant = bpy.data.objects.get("elephant")
    select_only(elephant)
    space = area.spaces.active
    space.show_region_ui = True
    space.shading.type = "SOLID"
    space.overlay.show_bones = True
    rig = bpy.data.objects.get("elephant_rig")
    if rig:
        rig.show_in_front = True
    import mathutils
    space.region_3d.view_rotation = mathutils.Euler((1.25, 0.0, 0.6)).to_quaternion()
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.view3d.view_selected()
    yield 0.5
    # Blender 3.4 has no API for the sidebar's tab: Ctrl + wheel over the sidebar steps through the tabs
    # (Item, Tool, View, Medial), as a user may; over the strip of tabs, below them, where no field is.
    sidebar = next(r for r in area.regions if r.type == "UI")
    x, y = sidebar.x + sidebar.width - 8, sidebar.y + 40
    for step in range(3):
        window.event_simulate(type="MOUSEMOVE", value="NOTHING", x=x, y=y + step)
        yield 0.2
        window.event_simulate(type="WHEELDOWNMOUSE", value="PRESS", x=x, y=y + step, ctrl=True)
        yield 0.3
    yield 1.0
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.screen.screenshot(filepath=SCREENSHOT)
    report("screenshot", path=SCREENSHOT)
    yield 0.2


def run_steps(session=steps()):
    try:
        return next(session)
    except StopIteration:
        bpy.ops.wm.quit_blender()
    except Exception:
        import traceback
        report("crashed", error=traceback.format_exc())
        bpy.ops.wm.quit_blender()
    return None


bpy.app.timers.register(run_steps, first_interval=1.0)
