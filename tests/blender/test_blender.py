"""Blender as the test client: rigs (medial skeleton --rig, and medial rig on a sketch, an SQM mesh and a
contraction skeleton) in .glb and .fbx, and SQM meshes in .obj and .ply, imported by Debian's Blender 3.4
run headless (tests/blender/blender_report.py reports what it got)."""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

MEDIAL = os.environ["MEDIAL_EXECUTABLE"]
SOURCE = os.environ.get("MEDIAL_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
REPORT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "blender_report.py")
CGAL = os.path.join(SOURCE, "data", "external", "cgal", "meshes")
RIGGED = [os.path.join(SOURCE, "data", "meshes", "torus.off")] + [
    os.path.join(CGAL, name + ".off") for name in ("elephant", "dino", "cow")]
SKETCH = os.path.join(SOURCE, "data", "sketches", "bird.txt")
TUBES = [os.path.join(SOURCE, "data", "skeletons", "sqm", name + ".vtp") for name in ("fish", "humanoid", "octopus")]


def medial(*args):
    done = subprocess.run([MEDIAL] + list(args) + ["--quiet"], capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise AssertionError("medial %s: %s" % (" ".join(args), done.stderr))
    return done


def blender_reports(paths):
    # Under scripts/sanitize the sanitizer runtimes are preloaded for the Python interpreter; Blender is
    # not Medial's code and runs without them.
    env = {k: v for k, v in os.environ.items() if k not in ("LD_PRELOAD", "ASAN_OPTIONS")}
    done = subprocess.run(["blender", "-b", "--factory-startup", "--python", REPORT, "--"] + paths,
                          capture_output=True, text=True, timeout=600, env=env)
    reports = {}
    for line in done.stdout.splitlines():
        if line.startswith("MEDIAL-REPORT "):
            report = json.loads(line[len("MEDIAL-REPORT "):])
            reports[report["file"]] = report
    if len(reports) != len(paths):
        raise AssertionError("Blender reported %d of %d files:\n%s" % (len(reports), len(paths), done.stderr[-3000:]))
    return reports


def segment_count(path):
    """Edges of a skeleton .vtp (its polylines split into 2-point segments): the bones of its rig."""
    import vtk
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    lines = reader.GetOutput().GetLines()
    ids, segments = vtk.vtkIdList(), 0
    lines.InitTraversal()
    while lines.GetNextCell(ids):
        segments += ids.GetNumberOfIds() - 1
    return segments


def polydata_counts(path):
    """(lines, polygons, quads) of a .vtp, read with Debian's VTK."""
    import vtk
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    quads = sum(1 for c in range(data.GetNumberOfCells())
                if data.GetCellType(c) in (vtk.VTK_QUAD, vtk.VTK_POLYGON) and data.GetCell(c).GetNumberOfPoints() == 4)
    return data.GetNumberOfLines(), data.GetNumberOfPolys(), quads


class BlenderOpensWhatMedialWrites(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="medial-blender-test-")
        cls.edges, cls.quad_share, paths = {}, {}, []
        for mesh in RIGGED:
            stem = os.path.join(cls.dir, os.path.splitext(os.path.basename(mesh))[0])
            for extension in ("glb", "fbx"):
                medial("skeleton", mesh, "-o", stem + ".vtp", "--rig", stem + "." + extension)
                paths.append(stem + "." + extension)
            cls.edges[stem] = polydata_counts(stem + ".vtp")[0]
        # medial rig binds meshes that other commands made: a sketch's, an SQM mesh (a character made from
        # a skeleton alone) and a contraction skeleton's mesh.
        sketch = os.path.join(cls.dir, "rig-bird")
        medial("sketch", SKETCH, "-o", sketch + "-skeleton.vtp", "--mesh", sketch + "-mesh.vtp")
        humanoid = os.path.join(cls.dir, "rig-humanoid")
        medial("sqm", TUBES[1], "-o", humanoid + "-mesh.obj", "--subdivide", "1")
        dino = os.path.join(cls.dir, "rig-dino")
        medial("skeleton", os.path.join(CGAL, "dino.off"), "-o", dino + "-skeleton.vtp")
        for stem, skeleton, mesh in ((sketch, sketch + "-skeleton.vtp", sketch + "-mesh.vtp"),
                                     (humanoid, TUBES[1], humanoid + "-mesh.obj"),
                                     (dino, dino + "-skeleton.vtp", os.path.join(CGAL, "dino.off"))):
            for extension in ("glb", "fbx"):
                medial("rig", skeleton, mesh, "-o", stem + "." + extension)
                paths.append(stem + "." + extension)
            cls.edges[stem] = segment_count(skeleton)
        for skeleton in TUBES:
            stem = os.path.join(cls.dir, os.path.splitext(os.path.basename(skeleton))[0])
            medial("sqm", skeleton, "-o", stem + ".vtp")
            _, polygons, quads = polydata_counts(stem + ".vtp")
            cls.quad_share[stem] = quads / polygons
            for extension in ("obj", "ply"):
                medial("sqm", skeleton, "-o", stem + "." + extension)
                paths.append(stem + "." + extension)
        cls.reports = blender_reports(paths)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_rigs_have_one_armature_one_root_and_a_bone_per_edge(self):
        for stem, edges in self.edges.items():
            for extension in ("glb", "fbx"):
                r = self.reports[stem + "." + extension]
                with self.subTest(file=r["file"]):
                    self.assertNotIn("error", r)
                    self.assertEqual(r["armatures"], 1)
                    self.assertEqual(r["bones"], edges + 1, "a bone per skeleton edge and the root joint")
                    self.assertEqual(r["roots"], 1)
                    self.assertTrue(r["modifier"], "the mesh is bound to the armature")

    def test_every_vertex_is_weighted_by_at_most_four_bones_summing_to_one(self):
        for stem in self.edges:
            for extension in ("glb", "fbx"):
                r = self.reports[stem + "." + extension]
                with self.subTest(file=r["file"]):
                    self.assertEqual(r["weighted"], r["vertices"])
                    self.assertGreaterEqual(r["min_sum"], 0.99)
                    self.assertLessEqual(r["max_sum"], 1.01)
                    self.assertLessEqual(r["max_influences"], 4)

    def test_posing_a_bone_moves_part_of_the_mesh(self):
        for stem in self.edges:
            for extension in ("glb", "fbx"):
                r = self.reports[stem + "." + extension]
                with self.subTest(file=r["file"]):
                    self.assertGreater(r["moved"], 0, "rotating %s by 30 degrees moved nothing" % r["posed"])
                    self.assertLess(r["moved"], r["vertices"], "it moved every vertex")
                    self.assertTrue(r["finite"])

    def test_fbx_and_glb_give_the_same_rest_pose(self):
        for stem in self.edges:
            glb, fbx = self.reports[stem + ".glb"], self.reports[stem + ".fbx"]
            with self.subTest(mesh=stem):
                self.assertEqual(set(glb["heads"]), set(fbx["heads"]), "the same bone names")
                size = max(abs(c) for head in glb["heads"].values() for c in head) or 1.0
                for name, head in glb["heads"].items():
                    for a, b in zip(head, fbx["heads"][name]):
                        self.assertAlmostEqual(a, b, delta=1e-3 * size, msg=name)
                self.assertEqual(glb["posed"], fbx["posed"])
                self.assertEqual(glb["moved"], fbx["moved"])

    def test_sqm_meshes_are_closed_manifold_with_the_quad_share_medial_reports(self):
        for stem, share in self.quad_share.items():
            for extension in ("obj", "ply"):
                r = self.reports[stem + "." + extension]
                with self.subTest(file=r["file"]):
                    self.assertNotIn("error", r)
                    self.assertEqual(r["boundary_edges"], 0)
                    self.assertEqual(r["non_manifold_edges"], 0)
                    self.assertAlmostEqual(r["quad_share"], share, places=6)


if __name__ == "__main__":
    unittest.main()
