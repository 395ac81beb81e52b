"""Numpy arrays to VTK data and back: meshes from (V, F), skeletons from (nodes, edges, radius), volumes from
[z, y, x] arrays. Numpy views where VTK's memory layout allows it, so that large arrays are not copied."""
import os

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIntArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkDataSet, vtkImageData, vtkPolyData

from medial.errors import MedialError


def is_path(value):
    return isinstance(value, (str, bytes, os.PathLike))


def view(vtk_array):
    """A numpy view of a VTK data array (None stays None)."""
    return None if vtk_array is None else numpy_support.vtk_to_numpy(vtk_array)


def points_array(coordinates, what):
    """(N, 3) coordinates as float64 vtkPoints, without a copy when they already are float64 and contiguous."""
    array = np.ascontiguousarray(coordinates, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != 3:
        raise MedialError("%s must be an (N, 3) array, got shape %s" % (what, array.shape))
    if not np.all(np.isfinite(array)):
        raise MedialError("%s hold NaN or infinite coordinates" % what)
    points = vtkPoints()
    points.SetData(numpy_support.numpy_to_vtk(array, deep=False))
    return points


def cell_array(cells, size, count, what):
    """A vtkCellArray of `cells`: an (M, size) integer array, or a list of index sequences of any sizes,
    each index below `count`."""
    if isinstance(cells, np.ndarray) or (len(cells) and np.ndim(cells[0]) == 1
                                          and len({len(c) for c in cells}) == 1):
        connectivity = np.asarray(cells, dtype=np.int64)
        if connectivity.ndim != 2 or (size and connectivity.shape[1] != size):
            raise MedialError("%s must be an (M, %s) array, got shape %s" % (what, size or "K", connectivity.shape))
        offsets = np.arange(0, connectivity.size + 1, max(connectivity.shape[1], 1), dtype=np.int64)
        connectivity = connectivity.ravel()
    else:
        sizes = [len(c) for c in cells]
        offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
        connectivity = np.concatenate([np.asarray(c, dtype=np.int64) for c in cells]) if cells else np.zeros(0, np.int64)
    if connectivity.size and (connectivity.min() < 0 or connectivity.max() >= count):
        raise MedialError("%s refer to points outside 0..%d" % (what, count - 1))
    array = vtkCellArray()
    array.SetData(numpy_support.numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_support.numpy_to_vtkIdTypeArray(connectivity, deep=True))
    return array


def polydata_from_mesh(vertices, faces):
    """A surface vtkPolyData from (V, F): V (N, 3) coordinates, F an (M, 3) or (M, 4) index array or a list
    of polygons of any sizes."""
    mesh = vtkPolyData()
    points = points_array(vertices, "the mesh's vertices")
    mesh.SetPoints(points)
    mesh.SetPolys(cell_array(faces, 0, points.GetNumberOfPoints(), "the mesh's faces"))
    return mesh


def polydata_from_skeleton(nodes, edges, radius=None, root=None):
    """The skeleton vtkPolyData of docs/ARCHITECTURE.md §4: nodes, 2-point lines, point data Radius, field
    data Root."""
    skeleton = vtkPolyData()
    points = points_array(nodes, "the skeleton's nodes")
    skeleton.SetPoints(points)
    skeleton.SetLines(cell_array(edges, 2, points.GetNumberOfPoints(), "the skeleton's edges"))
    if radius is not None:
        radii = np.ascontiguousarray(radius, dtype=np.float64).ravel()
        if radii.size != points.GetNumberOfPoints():
            raise MedialError("radius has %d values for %d nodes" % (radii.size, points.GetNumberOfPoints()))
        array = numpy_support.numpy_to_vtk(radii, deep=True, array_type=vtkDoubleArray().GetDataType())
        array.SetName("Radius")
        skeleton.GetPointData().AddArray(array)
    if root is not None and root >= 0:
        field = vtkIntArray()
        field.SetName("Root")
        field.InsertNextValue(int(root))
        skeleton.GetFieldData().AddArray(field)
    return skeleton


def image_from_array(volume, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), direction=None):
    """A vtkImageData from a numpy volume indexed [z, y, x] (as ITK's GetArrayFromImage and nibabel's
    transposed data), with spacing and origin in x, y, z order (as ITK's GetSpacing) and direction a 3x3
    matrix whose columns are the x, y and z axes (ITK's GetDirection). Boolean masks become 0/1 bytes. No
    copy when the array is C-contiguous."""
    array = np.asarray(volume)
    if array.ndim != 3:
        raise MedialError("a volume must be a 3-D array indexed [z, y, x], got shape %s" % (array.shape,))
    if array.dtype == bool:
        array = array.astype(np.uint8)
    array = np.ascontiguousarray(array)
    if len(tuple(spacing)) != 3 or not all(s > 0 for s in spacing):
        raise MedialError("spacing must be three positive numbers (x, y, z), got %s" % (tuple(spacing),))
    if len(tuple(origin)) != 3:
        raise MedialError("origin must be three numbers (x, y, z), got %s" % (tuple(origin),))
    image = vtkImageData()
    nz, ny, nx = array.shape
    image.SetDimensions(nx, ny, nz)
    image.SetSpacing(*[float(s) for s in spacing])
    image.SetOrigin(*[float(o) for o in origin])
    if direction is not None:
        matrix = np.asarray(direction, dtype=np.float64)
        if matrix.shape != (3, 3):
            raise MedialError("direction must be a 3x3 matrix, got shape %s" % (matrix.shape,))
        image.SetDirectionMatrix(*matrix.ravel())
    scalars = numpy_support.numpy_to_vtk(array.ravel(), deep=False)
    scalars.SetName("Scalars")
    image.GetPointData().SetScalars(scalars)
    return image


def as_dataset(value):
    """`value` when it is VTK data; its polydata when it is one of Medial's results; else None."""
    if isinstance(value, vtkDataSet):
        return value
    return getattr(value, "polydata", None)


def meshio_cells(polydata):
    """The polygons of `polydata` as meshio cell blocks: triangles, quads, and larger polygons."""
    blocks = {}
    for polygon in polygons(polydata):
        kind = {3: "triangle", 4: "quad"}.get(len(polygon), "polygon%d" % len(polygon))
        blocks.setdefault(kind, []).append(polygon)
    return [(kind, np.array(cells, dtype=np.int64)) for kind, cells in blocks.items()]


def polygons(polydata):
    """The polygon cells as a list of index arrays."""
    polys = polydata.GetPolys()
    if polys is None or polys.GetNumberOfCells() == 0:
        return []
    offsets = view(polys.GetOffsetsArray())
    connectivity = view(polys.GetConnectivityArray())
    return [connectivity[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def line_edges(polydata):
    """The line cells as an (E, 2) array of 2-point segments (polylines are split)."""
    lines = polydata.GetLines()
    if lines is None or lines.GetNumberOfCells() == 0:
        return np.zeros((0, 2), dtype=np.int64)
    offsets = view(lines.GetOffsetsArray()).astype(np.int64)
    connectivity = view(lines.GetConnectivityArray()).astype(np.int64)
    if np.all(np.diff(offsets) == 2):
        return connectivity.reshape(-1, 2)
    edges = [np.stack([connectivity[a:b - 1], connectivity[a + 1:b]], axis=1) for a, b in zip(offsets[:-1], offsets[1:])]
    return np.concatenate(edges) if edges else np.zeros((0, 2), dtype=np.int64)
