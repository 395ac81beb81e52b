"""The Blender add-on (blender/medial_blender) in Debian's Blender 3.4: installed from build/medial-blender.zip
as a user does (BLENDER_USER_SCRIPTS in a temporary folder), its operators run on sample meshes.
  test_addon.py background   blender -b: results, refusals, cancelling a job, timing against the command
  test_addon.py window       a Blender window (X needed; exit 77 without): invoked from the panel (modal,
                             progress), Esc, undo, and a screenshot of the panel (MEDIAL_ADDON_SCREENSHOT)
The checks inside Blender are tests/blender/addon_checks.py and addon_window.py."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
MEDIAL = os.environ["MEDIAL_EXECUTABLE"]
ZIP = os.environ["MEDIAL_BLENDER_ZIP"]
SOURCE = os.environ.get("MEDIAL_SOURCE_DIR", os.path.join(HERE, "..", ".."))
CGAL = os.path.join(SOURCE, "data", "external", "cgal", "meshes")
MODE = sys.argv.pop(1) if len(sys.argv) > 1 else "background"


def off_to_obj(off, obj):
    """An OBJ of an OFF mesh, for Blender's OBJ importer (the way most meshes reach Blender)."""
    with open(off) as stream:
        tokens = [t for line in stream for t in line.split("#")[0].split()]
    n, m = int(tokens[1]), int(tokens[2])
    numbers = tokens[4:]
    with open(obj, "w") as out:
        for i in range(n):
            out.write("v %s %s %s\n" % tuple(numbers[3 * i:3 * i + 3]))
        at = 3 * n
        for _ in range(m):
            k = int(numbers[at])
            out.write("f " + " ".join(str(int(v) + 1) for v in numbers[at + 1:at + 1 + k]) + "\n")
            at += 1 + k


def run_blender(script, args, window=False):
    folder = tempfile.mkdtemp(prefix="medial-addon-test-")
    # The add-on is installed into this folder, as Edit > Preferences > Add-ons > Install does; the sanitizer
    # runtimes of scripts/sanitize are not for Blender.
    env = {k: v for k, v in os.environ.items() if k not in ("LD_PRELOAD", "ASAN_OPTIONS")}
    env["BLENDER_USER_SCRIPTS"] = os.path.join(folder, "scripts")
    command = ["blender", "--factory-startup"] + (["--enable-event-simulate"] if window else ["-b"])
    done = subprocess.run(command + ["--python", script, "--"] + args, capture_output=True, text=True,
                          timeout=600, env=env, cwd=folder)
    facts = {}
    for line in done.stdout.splitlines():
        if line.startswith("MEDIAL-ADDON "):
            fact = json.loads(line[len("MEDIAL-ADDON "):])
            facts[fact["check"]] = fact
    return facts, done.stdout[-4000:] + done.stderr[-4000:]


class AddOnTest(unittest.TestCase):
    facts = None

    def fact(self, name):
        self.assertIn(name, self.facts, "Blender did not report %s:\n%s" % (name, self.output))
        fact = self.facts[name]
        self.assertNotIn("crashed", fact, fact.get("crashed"))
        return fact


@unittest.skipUnless(MODE == "background", "background mode")
class Background(AddOnTest):
    @classmethod
    def setUpClass(cls):
        folder = tempfile.mkdtemp(prefix="medial-addon-meshes-")
        elephant = os.path.join(folder, "elephant.obj")
        off_to_obj(os.path.join(CGAL, "elephant.off"), elephant)
        cls.facts, cls.output = run_blender(os.path.join(HERE, "addon_checks.py"), [
            ZIP, MEDIAL, elephant, os.path.join(CGAL, "man.off"), os.path.join(CGAL, "armadillo.off")])

    def test_installs_from_the_zip(self):
        fact = self.fact("install")
        self.assertIn(os.path.join("scripts", "addons", "medial_blender"), fact["module"])
        self.assertTrue(fact["panel"])
        self.assertEqual(fact["operators"], ["rig_mesh", "bind", "sqm_mesh"])

    def check_rig(self, fact, vertices=None):
        self.assertEqual(fact["result"], ["FINISHED"], fact["error"])
        armature = fact["armature"]
        self.assertEqual(armature["root"], ["Root"])  # one hierarchy under the non-deforming root
        self.assertFalse(armature["root_deforms"])
        self.assertEqual(armature["deforming"], armature["bones"] - 1)
        self.assertEqual(fact["unweighted"], 0)  # every vertex weighted
        self.assertLess(fact["sum_error"], 1e-4)
        return armature

    def test_rig_of_an_imported_obj(self):
        fact = self.fact("rig_elephant")
        armature = self.check_rig(fact)
        self.assertGreaterEqual(armature["deforming"], 24)  # 25 nodes asked for; the trunk may close a cycle
        self.assertEqual(fact["groups"], armature["deforming"])
        self.assertEqual(fact["parent"], "elephant_rig")
        self.assertEqual(fact["modifiers"], [["ARMATURE", "elephant_rig"]])
        # The OBJ importer turns the Y-up elephant to stand in Z-up Blender: so does its rig.
        self.assertEqual(max(range(3), key=lambda i: armature["extent"][i]), 2)

    def test_rig_of_the_man_stands_rooted_at_the_hips(self):
        fact = self.fact("rig_man")
        armature = self.check_rig(fact)
        self.assertEqual(max(range(3), key=lambda i: armature["extent"][i]), 2)
        hips = (fact["armature"]["root_height"] - fact["bottom"]) / fact["height"]
        self.assertTrue(0.4 <= hips <= 0.65, "root at %.2f of the height" % hips)

    def test_rig_costs_at_most_a_fifth_more_than_the_command(self):
        fact = self.fact("rig_man")
        overhead = fact["operator_seconds"] / fact["command_seconds"] - 1
        print("rig_mesh on the man: operator %.3f s, command %.3f s (medians of 5, interleaved), overhead %.1f %%"
              % (fact["operator_seconds"], fact["command_seconds"], 100 * overhead))
        self.assertLessEqual(overhead, 0.2)

    def test_bind_to_a_hand_made_armature(self):
        fact = self.fact("bind")
        self.assertEqual(fact["result"], ["FINISHED"], fact["error"])
        self.assertEqual(fact["groups"], sorted(fact["bones"]))
        self.assertEqual(fact["parent"], "three_bones")
        self.assertEqual(fact["modifiers"], ["ARMATURE"])
        self.assertEqual(fact["unweighted"], 0)
        self.assertLess(fact["sum_error"], 1e-4)
        self.assertGreaterEqual(fact["low_first"], 0.95)  # the bottom follows the first bone
        self.assertGreaterEqual(fact["high_last"], 0.95)  # the top the last

    def check_sqm(self, fact):
        self.assertEqual(fact["result"], ["FINISHED"], fact["error"])
        self.assertEqual(fact["open_edges"], 0)  # closed, manifold
        self.assertEqual(fact["bad_vertices"], 0)
        self.assertGreaterEqual(fact["quads"] / fact["faces"], 0.9)

    def test_sqm_of_skin_modifier_edges(self):
        self.check_sqm(self.fact("sqm_skin"))

    def test_sqm_of_an_armature_with_envelopes(self):
        self.check_sqm(self.fact("sqm_armature"))

    def check_refused(self, fact, words):
        self.assertIsNone(fact["result"])
        self.assertIn(words, fact["error"])
        self.assertEqual(fact["objects_changed"], 0)

    def test_an_open_plane_is_refused(self):
        fact = self.fact("open_plane")
        self.check_refused(fact, "is not closed")
        self.assertEqual((fact["groups"], fact["modifiers"]), (0, 0))

    def test_a_skeleton_without_radii_is_refused(self):
        self.check_refused(self.fact("no_radii"), "has no radii")

    def test_medial_not_found_is_reported(self):
        self.check_refused(self.fact("not_found"), "medial not found at /nonexistent/medial")

    def test_cancelling_stops_the_command(self):
        fact = self.fact("cancel")
        self.assertTrue(fact["was_running"])
        self.assertEqual(fact["message"], "cancelled")
        self.assertLess(fact["stop_seconds"], 3.0)
        self.assertTrue(fact["progress_seen"])  # progress lines arrived through the pipe
        self.assertFalse(fact["folder_left"])


@unittest.skipUnless(MODE == "window", "window mode")
class Window(AddOnTest):
    @classmethod
    def setUpClass(cls):
        folder = tempfile.mkdtemp(prefix="medial-addon-meshes-")
        elephant = os.path.join(folder, "elephant.obj")
        off_to_obj(os.path.join(CGAL, "elephant.off"), elephant)
        screenshot = os.environ.get("MEDIAL_ADDON_SCREENSHOT", os.path.join(folder, "medial-panel.png"))
        cls.facts, cls.output = run_blender(os.path.join(HERE, "addon_window.py"), [
            ZIP, MEDIAL, elephant, os.path.join(CGAL, "refined_elephant.off"), screenshot], window=True)
        cls.screenshot = screenshot

    def test_invoked_from_the_panel_runs_modal_and_finishes(self):
        fact = self.fact("modal_rig")
        self.assertEqual(fact["invoked"], ["RUNNING_MODAL"])
        self.assertTrue(fact["finished"])
        self.assertGreater(fact["groups"], 20)

    def test_one_undo_step_takes_the_rig_back(self):
        fact = self.fact("undo_rig")
        self.assertEqual((fact["armatures"], fact["groups"], fact["modifiers"], fact["parent"]), (0, 0, 0, False))

    def test_escape_cancels_and_leaves_the_scene_unchanged(self):
        fact = self.fact("modal_cancel")
        self.assertEqual(fact["invoked"], ["RUNNING_MODAL"])
        self.assertEqual((fact["objects_changed"], fact["groups"]), (0, 0))

    def test_screenshot_of_the_panel(self):
        self.fact("screenshot")
        self.assertGreater(os.path.getsize(self.screenshot), 50000)


if __name__ == "__main__":
    if MODE == "window" and not os.environ.get("DISPLAY"):
        print("no DISPLAY: the window tests need an X server")
        sys.exit(77)
    unittest.main(verbosity=2)
