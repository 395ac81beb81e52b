"""What the functions accept: a path, VTK data, one of Medial's results, numpy arrays, or a trimesh or
meshio mesh; each becomes the VTK data the filter takes, or raises MedialError saying why not."""
import os

import numpy as np
from vtkmodules.vtkCommonDataModel import vtkDataSet, vtkImageData, vtkPolyData

from medial import convert
from medial.errors import MedialError, run


def read(path, *, rig_skeleton=False):
    """Reads any file Medial knows into VTK data.

    Parameters
    ----------
    path : str or os.PathLike
        A mesh or skeleton (.off .obj .ply .stl .vtp .vtk .vtu .g .gltf .glb .fbx .swc), a sketch (.txt) or
        a volume (.nii .nii.gz .mha .mhd .nrrd .nhdr .gipl .dcm, a DICOM folder, .inr .inr.gz .vti .inv3).
        Any other format that meshio (python3-meshio) reads is read through meshio.
    rig_skeleton : bool, default False
        For a rig (.fbx, .glb): its skeleton instead of its mesh.

    Returns
    -------
    vtkPolyData or vtkImageData
        Volumes keep their spacing, origin and direction (mm).

    Raises
    ------
    MedialError
        A missing file, an unknown format, unreadable content, an empty mesh or an invalid skeleton.
    """
    from medial.MedialFilters import vtkMedialReader
    name = os.fspath(path)
    if isinstance(name, bytes):
        name = name.decode()
    if not vtkMedialReader.CanReadFile(name) and os.path.isfile(name):
        meshio_data = _read_with_meshio(name)
        if meshio_data is not None:
            return meshio_data
    reader = vtkMedialReader()
    reader.SetFileName(name)
    reader.SetRigSkeleton(bool(rig_skeleton))
    run(reader, name)
    return reader.GetOutputDataObject(0)


def _read_with_meshio(name):
    try:
        import meshio
    except ImportError:
        return None
    try:
        mesh = meshio.read(name)
    except Exception as error:  # meshio raises its own ReadError, and KeyError for unknown extensions
        raise MedialError("%s: meshio cannot read it either: %s" % (name, error)) from None
    faces = [cell for block in mesh.cells if block.type.startswith(("triangle", "quad", "polygon"))
             for cell in block.data]
    if not faces:
        raise MedialError("%s: no surface cells (triangles, quads, polygons) in it" % name)
    return convert.polydata_from_mesh(mesh.points[:, :3] if mesh.points.shape[1] >= 3
                                      else np.pad(mesh.points, ((0, 0), (0, 1))), faces)


def mesh(value, what="mesh"):
    """A surface vtkPolyData from a path, VTK data, a Mesh, (V, F), or an object with `vertices` and `faces`
    (trimesh) or `points` and `cells` (meshio)."""
    if convert.is_path(value):
        value = read(value)
    data = convert.as_dataset(value)
    if data is None and isinstance(value, (tuple, list)) and len(value) == 2:
        data = convert.polydata_from_mesh(*value)
    elif data is None and hasattr(value, "vertices") and hasattr(value, "faces"):
        data = convert.polydata_from_mesh(np.asarray(value.vertices), np.asarray(value.faces))
    elif data is None and hasattr(value, "points") and hasattr(value, "cells"):
        data = convert.polydata_from_mesh(value.points[:, :3], [c for block in value.cells for c in block.data])
    if isinstance(data, vtkImageData):
        raise MedialError("%s: a volume, not a surface mesh" % what)
    if data is None or not isinstance(data, vtkDataSet):
        raise MedialError("%s: expected a path, VTK data or (V, F) arrays, got %s" % (what, type(value).__name__))
    if not isinstance(data, vtkPolyData):
        data = _surface(data)
    if data.GetNumberOfPolys() + data.GetNumberOfStrips() == 0:
        raise MedialError("%s: no polygons (a surface mesh is needed)" % what)
    return data


def _surface(dataset):
    from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(dataset)
    run(surface, "the mesh's surface")
    return surface.GetOutput()


def skeleton(value, what="skeleton"):
    """A skeleton vtkPolyData from a path, VTK data, a Skeleton, or (nodes, edges[, radius[, root]])."""
    if convert.is_path(value):
        value = read(value)
    data = convert.as_dataset(value)
    if data is None and isinstance(value, (tuple, list)) and 2 <= len(value) <= 4:
        data = convert.polydata_from_skeleton(*value)
    if not isinstance(data, vtkPolyData):
        raise MedialError("%s: expected a path, a Skeleton, vtkPolyData or (nodes, edges, radius), got %s"
                          % (what, type(value).__name__))
    if data.GetNumberOfLines() == 0:
        raise MedialError("%s: no edges (line cells)" % what)
    return data


def volume(value, spacing=None, origin=None, direction=None, what="volume"):
    """A vtkImageData from a path, vtkImageData, or a numpy array indexed [z, y, x] with spacing and origin
    in x, y, z order."""
    if isinstance(value, np.ndarray):
        return convert.image_from_array(value, spacing if spacing is not None else (1.0, 1.0, 1.0),
                                        origin if origin is not None else (0.0, 0.0, 0.0), direction)
    if spacing is not None or origin is not None or direction is not None:
        raise MedialError("spacing, origin and direction go with a numpy volume; a file or vtkImageData has "
                          "its own")
    if convert.is_path(value):
        value = read(value)
    if not isinstance(value, vtkImageData):
        raise MedialError("%s: expected a path, vtkImageData or a 3-D numpy array, got %s"
                          % (what, type(value).__name__))
    return value
