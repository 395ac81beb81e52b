"""Blender as the test client: rigs (medial skeleton --rig, and medial rig on a sketch, an SQM mesh and a
contraction skeleton) in .glb and .fbx, and SQM meshes in .obj and .ply, imported by Debian's Blender 3.4
run headless (tests/blender/blender_report.py reports what it got)."""
import heapq
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
# Turned and scaled rigs: the man is Z-up (1 tall, 0.42 wide, 0.30 deep), the armadillo 151 units tall.
ORIENTED = {os.path.join(CGAL, "man.off"): ["--up-axis", "z"],
            os.path.join(CGAL, "armadillo.off"): ["--scale", "0.012"]}
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


def distance(a, b):
    return sum((p - q) ** 2 for p, q in zip(a, b)) ** 0.5


def skeleton_from_bones(structure):
    """The skeleton Blender's bones make (Bone_<edge>_<head>_<tail>, lengths head to tail): the root node's
    distance along the bones to the farthest leaf, the longest path between two leaves, the root node;
    (None, None, root) for a skeleton with fewer than two leaves (a cycle has no farthest leaf)."""
    neighbours, root = {}, None
    for name, bone in structure.items():
        if not name.startswith("Bone_") or name.endswith("_end"):
            continue
        _, _, head, tail = name.split("_")
        length = distance(bone["head"], bone["tail"])
        neighbours.setdefault(int(head), []).append((int(tail), length))
        neighbours.setdefault(int(tail), []).append((int(head), length))
        if bone["parent"] == "Root":
            root = int(head)
    leaves = [n for n, around in neighbours.items() if len(around) == 1]
    if len(leaves) < 2:
        return None, None, root

    def distances(source):
        best, queue = {source: 0.0}, [(0.0, source)]
        while queue:
            d, node = heapq.heappop(queue)
            if d > best[node]:
                continue
            for nxt, length in neighbours[node]:
                if d + length < best.get(nxt, float("inf")):
                    best[nxt] = d + length
                    heapq.heappush(queue, (d + length, nxt))
        return best
    longest = max(distances(leaf).get(other, 0) for leaf in leaves for other in leaves)
    from_root = distances(root)
    return max(from_root.get(leaf, 0) for leaf in leaves), longest, root


class BlenderOpensWhatMedialWrites(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="medial-blender-test-")
        cls.edges, cls.quad_share, paths = {}, {}, []
        for mesh in RIGGED + list(ORIENTED):
            stem = os.path.join(cls.dir, os.path.splitext(os.path.basename(mesh))[0])
            for extension in ("glb", "fbx"):
                medial("skeleton", mesh, "-o", stem + ".vtp", "--rig", stem + "." + extension, *ORIENTED.get(mesh, []))
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
                    names = set(r["structure"])
                    bones = [n for n in names if n.startswith("Bone_") and not n.endswith("_end")]
                    self.assertEqual(len(bones), edges, "a bone per skeleton edge")
                    self.assertIn("Root", names)
                    self.assertIn("Root_end", names)
                    for name in names - set(bones) - {"Root", "Root_end"}:
                        self.assertTrue(name.endswith("_end") and name[:-4] in bones, name)
                        self.assertEqual(r["structure"][name]["parent"], name[:-4])
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

    def test_the_root_is_the_bodys_centre(self):
        """Root's child bones start at the root node, whose farthest node along the skeleton is at most 0.65
        of the longest path (the hips of a figure, never a hand)."""
        for stem in self.edges:
            for extension in ("glb", "fbx"):
                r = self.reports[stem + "." + extension]
                with self.subTest(file=r["file"]):
                    farthest, longest, root = skeleton_from_bones(r["structure"])
                    self.assertIsNotNone(root, "no bone hangs from Root")
                    if longest is None:
                        continue  # a cycle (the torus): every node is as central
                    self.assertLessEqual(farthest, 0.65 * longest + 1e-9,
                                         "root node %d: %.3f to the farthest leaf, the longest path %.3f" % (
                                             root, farthest, longest))

    def test_every_bone_ends_at_its_node_and_weighs_a_vertex(self):
        for stem in self.edges:
            for extension in ("glb", "fbx"):
                r = self.reports[stem + "." + extension]
                with self.subTest(file=r["file"]):
                    size = max(r["extent"])
                    for name, bone in r["structure"].items():
                        if name.startswith("Bone_") and name.endswith("_end"):
                            leaf = r["structure"][name[:-4]]
                            if extension == "glb" and distance(leaf["head"], bone["head"]) < 0.004:
                                continue  # Blender's glTF importer guesses bones shorter than 4 mm
                            self.assertLessEqual(distance(leaf["tail"], bone["head"]), 0.02 * size, name)
                    self.assertEqual(r["dead"], [], "bones that drive no vertex")

    def test_blenders_automatic_weights_give_the_root_nothing(self):
        for stem in self.edges:
            for extension in ("glb", "fbx"):
                r = self.reports[stem + "." + extension]
                with self.subTest(file=r["file"]):
                    self.assertNotIn("Root", r["automatic"], "Blender's bone heat weighted Root")
                    self.assertNotIn("Root_end", r["automatic"])

    def test_rigs_stand_and_have_the_size_asked_for(self):
        man = os.path.join(self.dir, "man")
        armadillo = os.path.join(self.dir, "armadillo")
        for extension in ("glb", "fbx"):
            x, y, z = self.reports[man + "." + extension]["extent"]
            self.assertGreater(z, 2 * max(x, y), "the Z-up man stands in Blender (Z up)")
            extent = self.reports[armadillo + "." + extension]["extent"]
            self.assertAlmostEqual(extent[2], 151.0 * 0.012, delta=0.02 * 151 * 0.012)

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
