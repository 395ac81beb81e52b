"""The Python API (medial.skeletonize, sqm, centerline, sketch, rig, read): paths, VTK data and numpy input
give the same results; every bad input raises MedialError and nothing reaches stderr."""
import os
import sys
import tempfile
import unittest
import warnings

import numpy as np
from vtkmodules.util import numpy_support

import medial

DATA = os.path.join(os.environ.get("MEDIAL_SOURCE_DIR", "."), "data")
TORUS = os.path.join(DATA, "meshes", "torus.off")
HAND = os.path.join(DATA, "skeletons", "hand.swc")
U_TUBE = os.path.join(DATA, "volumes", "tubes", "u.nii.gz")


class StderrCapture:
    """Captures file descriptor 2 (what C++ prints too, not only sys.stderr)."""

    def __enter__(self):
        sys.stderr.flush()
        self.file = tempfile.TemporaryFile()
        self.saved = os.dup(2)
        os.dup2(self.file.fileno(), 2)
        return self

    def __exit__(self, *exception):
        sys.stderr.flush()
        os.dup2(self.saved, 2)
        os.close(self.saved)
        self.file.seek(0)
        self.text = self.file.read().decode(errors="replace")
        self.file.close()


def mesh_arrays(path):
    polydata = medial.read(path)
    return medial.Mesh(polydata).points.copy(), medial.Mesh(polydata).faces


class Skeletonize(unittest.TestCase):
    def test_path_vtk_and_numpy_give_one_skeleton(self):
        vertices, faces = mesh_arrays(TORUS)
        self.assertEqual(faces.shape[1], 3)
        by_path = medial.skeletonize(TORUS, nodes=12)
        by_vtk = medial.skeletonize(medial.read(TORUS), nodes=12)
        by_numpy = medial.skeletonize((vertices, faces), nodes=12)
        for skeleton in (by_vtk, by_numpy):
            np.testing.assert_allclose(skeleton.nodes, by_path.nodes, atol=1e-9)
            np.testing.assert_array_equal(skeleton.edges, by_path.edges)
        self.assertEqual(by_path.nodes.shape, (12, 3))
        self.assertEqual(by_path.edges.shape, (12, 2))  # the torus's one cycle
        self.assertTrue(np.all(by_path.radius > 0))
        self.assertGreaterEqual(by_path.root, 0)
        self.assertIsNone(by_path.weights)

    def test_weights_rows_sum_to_one_and_save(self):
        skeleton = medial.skeletonize(TORUS, nodes=12, weights=True)
        self.assertEqual(skeleton.weights.shape, (skeleton.mesh.points.shape[0], len(skeleton.edges)))
        np.testing.assert_allclose(skeleton.weights.sum(axis=1), 1.0, atol=1e-6)
        path = skeleton.save(os.path.join(tempfile.mkdtemp(), "torus.vtp"))
        np.testing.assert_allclose(medial.Skeleton(medial.read(path)).nodes, skeleton.nodes)
        rig = medial.rig(skeleton, path=os.path.join(tempfile.mkdtemp(), "torus.glb"), up_axis="z")
        with open(rig, "rb") as file:
            self.assertEqual(file.read(4), b"glTF")

    def test_docstring_defaults_are_the_filters(self):
        fresh = medial.vtkMedialContractionSkeleton()
        self.assertIn("default %d" % fresh.GetTargetNodes(), medial.skeletonize.__doc__)
        self.assertIn("Raises", medial.skeletonize.__doc__)


class Sqm(unittest.TestCase):
    def test_arrays_path_and_skeleton(self):
        hand = medial.Skeleton(medial.read(HAND))
        from_arrays = medial.sqm((hand.nodes, hand.edges, hand.radius))
        from_path = medial.sqm(HAND)
        from_skeleton = medial.sqm(hand)
        np.testing.assert_allclose(from_arrays.points, from_path.points)
        np.testing.assert_allclose(from_skeleton.points, from_path.points)
        self.assertTrue(from_path.is_closed())
        self.assertEqual(from_path.faces.shape[1], 4)
        self.assertGreater((from_path.faces[:, 3] >= 0).mean(), 0.5)  # quad-dominant
        subdivided = medial.sqm(HAND, subdivide=1)
        self.assertGreater(len(subdivided.points), len(from_path.points))
        self.assertEqual(subdivided["SkeletonNode"].shape, (len(subdivided.points),))
        converted = subdivided.to_meshio()
        self.assertEqual(len(converted.points), len(subdivided.points))


class CenterlineOfAVolume(unittest.TestCase):
    def test_numpy_volume_in_zyx_order_matches_the_file(self):
        image = medial.read(U_TUBE)
        nx, ny, nz = image.GetDimensions()
        volume = numpy_support.vtk_to_numpy(image.GetPointData().GetScalars()).reshape(nz, ny, nx)
        from_file = medial.centerline(U_TUBE, label=1)
        from_numpy = medial.centerline(volume, spacing=image.GetSpacing(), origin=image.GetOrigin(), label=1)
        np.testing.assert_allclose(from_numpy.points, from_file.points, atol=1e-6)
        self.assertGreater(from_file.arc_length[-1], 80.0)  # mm along the U
        self.assertEqual(len(from_file.lines), 1)

    def test_spacing_and_origin_are_x_y_z(self):
        volume = np.zeros((20, 30, 80), dtype=bool)  # [z, y, x]: a rod along x
        volume[8:13, 12:17, 5:75] = True
        line = medial.centerline(volume, spacing=(0.5, 1.0, 2.0), origin=(100.0, 0.0, -50.0), label=1,
                                 sections=True)
        extent = line.points.max(axis=0) - line.points.min(axis=0)
        self.assertGreater(extent[0], 25.0)  # along x: about 70 voxels of 0.5 mm
        np.testing.assert_allclose(line.points[:, 1].mean(), 14.0, atol=0.6)
        np.testing.assert_allclose(line.points[:, 2].mean(), -50.0 + 2.0 * 10.0, atol=1.2)
        self.assertGreater(line.points[:, 0].min(), 100.0)
        self.assertEqual(set(line.sections) >= {"ArcLength", "MinDiameter", "MaxDiameter", "Area"}, True)
        self.assertEqual(line.terrain.shape[0], len(line.sections["ArcLength"]))


class SketchAndRig(unittest.TestCase):
    def test_sketch_mesh_bound_and_rigged(self):
        sketch = medial.sketch(os.path.join(DATA, "sketches", "bird.txt"))
        self.assertGreater(len(sketch.nodes), 5)
        self.assertTrue(np.all(sketch.radius > 0))
        self.assertGreater(len(sketch.mesh.points), 100)
        path = medial.rig(sketch, sketch.mesh, os.path.join(tempfile.mkdtemp(), "bird.glb"))
        self.assertGreater(os.path.getsize(path), 1000)


class ReadThroughMeshio(unittest.TestCase):
    def test_a_format_only_meshio_reads(self):
        import meshio
        vertices, faces = mesh_arrays(TORUS)
        path = os.path.join(tempfile.mkdtemp(), "torus.mesh")  # Medit: not a VTK format
        meshio.write(path, meshio.Mesh(vertices, [("triangle", faces)]))
        self.assertEqual(medial.read(path).GetNumberOfPolys(), len(faces))
        self.assertEqual(len(medial.skeletonize(path, nodes=12).nodes), 12)


class BadInputRaises(unittest.TestCase):
    def test_every_error_path_raises_medial_error_and_prints_nothing(self):
        hand = medial.Skeleton(medial.read(HAND))
        torus = medial.skeletonize(TORUS, nodes=12)
        volume = np.zeros((10, 10, 10), dtype=np.uint8)
        volume[3:7, 3:7, 1:9] = 1
        cases = {
            "no such file": lambda: medial.skeletonize("/nonexistent/mesh.off"),
            "unknown extension": lambda: medial.read(__file__),
            "a volume to skeletonize": lambda: medial.skeletonize(U_TUBE),
            "no polygons": lambda: medial.skeletonize(HAND),
            "NaN coordinates": lambda: medial.skeletonize((np.full((3, 3), np.nan), [[0, 1, 2]])),
            "face index out of range": lambda: medial.skeletonize((np.eye(3), [[0, 1, 5]])),
            "nodes below 0": lambda: medial.skeletonize(TORUS, nodes=-3),
            "nodes not a number": lambda: medial.skeletonize(TORUS, nodes="abc"),
            "unknown solver": lambda: medial.skeletonize(TORUS, solver="magic"),
            "no radius": lambda: medial.sqm((hand.nodes, hand.edges)),
            "negative radius": lambda: medial.sqm((hand.nodes, hand.edges, -hand.radius)),
            "subdivide out of range": lambda: medial.sqm(HAND, subdivide=99),
            "label no voxel has": lambda: medial.centerline(volume, label=7),
            "label and threshold": lambda: medial.centerline(volume, label=1, threshold=(0, 1)),
            "empty threshold": lambda: medial.centerline(volume, threshold=(50, 60)),
            "seed outside": lambda: medial.centerline(volume, label=1, seed=(0, 0, 0)),
            "a 2-D array": lambda: medial.centerline(np.zeros((4, 4))),
            "spacing with a file": lambda: medial.centerline(U_TUBE, spacing=(1, 1, 1)),
            "not a sketch": lambda: medial.sketch(TORUS),
            "rig without weights": lambda: medial.rig(hand, path=os.path.join(tempfile.mkdtemp(), "r.glb")),
            "unknown up axis": lambda: medial.rig(torus, TORUS, os.path.join(tempfile.mkdtemp(), "r.glb"),
                                                  up_axis="up"),
        }
        for name, case in cases.items():
            with self.subTest(name), StderrCapture() as stderr, warnings.catch_warnings():
                warnings.simplefilter("error")
                with self.assertRaises(medial.MedialError) as raised:
                    case()
            with self.subTest(name):
                self.assertEqual(stderr.text, "", name)
                self.assertTrue(str(raised.exception), name)
                self.assertNotIn("\n", str(raised.exception), name)
                self.assertNotIn("vtkInformation", str(raised.exception), name)

    def test_unknown_keyword_is_a_type_error(self):
        with self.assertRaises(TypeError):
            medial.skeletonize(TORUS, target_nodes=10)


if __name__ == "__main__":
    sys.exit(unittest.main(verbosity=2).result.wasSuccessful() is False)
