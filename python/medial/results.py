"""What medial's functions return: a Skeleton, a Mesh, a Centerline. Each holds its VTK data (`.polydata`,
for pipelines) and shows it as numpy views (no copies of large arrays)."""
import numpy as np
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData, vtkTable

from medial import convert
from medial.errors import run


def _save(polydata, path):
    from medial.MedialFilters import vtkMedialMarkupsCurveWriter, vtkMedialPolyDataWriter
    path = str(path)
    writer = vtkMedialMarkupsCurveWriter() if path.endswith(".json") else vtkMedialPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(polydata)
    run(writer, path, write=True)
    return path


def _meshio(points, cells, point_data):
    import meshio  # python3-meshio
    return meshio.Mesh(np.asarray(points), cells,
                       point_data={k: np.asarray(v) for k, v in point_data.items() if v is not None})


class Mesh:
    """A surface mesh: `points` (N, 3), `faces` (M, K) with -1 after the corners of smaller polygons
    (K = the largest polygon's size: 3 for triangle meshes, 4 for SQM's quad-dominant ones), `polygons`
    (a list of index arrays), point data by name (`mesh["SkeletonNode"]`)."""

    def __init__(self, polydata):
        self.polydata = polydata

    @property
    def points(self):
        return convert.view(self.polydata.GetPoints().GetData()) if self.polydata.GetPoints() else np.zeros((0, 3))

    @property
    def polygons(self):
        return convert.polygons(self.polydata)

    @property
    def faces(self):
        polygons = self.polygons
        width = max((len(p) for p in polygons), default=3)
        faces = np.full((len(polygons), width), -1, dtype=np.int64)
        for row, polygon in enumerate(polygons):
            faces[row, :len(polygon)] = polygon
        return faces

    def __getitem__(self, name):
        array = self.polydata.GetPointData().GetArray(name)
        if array is None:
            raise KeyError("no point data %r (there are: %s)" % (name, ", ".join(self.point_data_names())))
        return convert.view(array)

    def point_data_names(self):
        data = self.polydata.GetPointData()
        return [data.GetArrayName(i) for i in range(data.GetNumberOfArrays())]

    def is_closed(self):
        """Whether the mesh is a closed 2-manifold (every edge on two faces, every vertex a disc)."""
        from medial.MedialFilters import vtkMedialMeshTopology
        topology = vtkMedialMeshTopology()
        topology.SetInputData(self.polydata)
        run(topology, "mesh topology")
        return bool(topology.GetClosedManifold())

    def save(self, path):
        """Writes .vtp .vtk .obj .ply .stl; returns the path."""
        return _save(self.polydata, path)

    def to_meshio(self):
        return _meshio(self.points, convert.meshio_cells(self.polydata),
                       {name: self[name] for name in self.point_data_names()})

    def __repr__(self):
        return "<medial.Mesh: %d points, %d faces>" % (self.polydata.GetNumberOfPoints(),
                                                        self.polydata.GetNumberOfPolys())


class Skeleton:
    """A curve skeleton: `nodes` (N, 3), `edges` (E, 2), `radius` (N,), `root` (the rig's root node, -1 when
    none is set). From medial.skeletonize also `mesh` (the input with `SkeletonNode` per vertex) and, with
    weights=True, `weights` (V, E): the skinning weight of bone (edge) j at vertex i, rows summing to 1.
    From medial.sketch, `mesh` is the inflated sketch."""

    def __init__(self, polydata, mesh=None, notes=()):
        self.polydata = polydata
        self.mesh = Mesh(mesh) if isinstance(mesh, vtkPolyData) else mesh
        self.notes = list(notes)

    @property
    def nodes(self):
        return convert.view(self.polydata.GetPoints().GetData())

    @property
    def edges(self):
        return convert.line_edges(self.polydata)

    @property
    def radius(self):
        return convert.view(self.polydata.GetPointData().GetArray("Radius"))

    @property
    def root(self):
        field = self.polydata.GetFieldData().GetArray("Root")
        return int(field.GetTuple1(0)) if field is not None and field.GetNumberOfTuples() else -1

    @property
    def weights(self):
        if self.mesh is None:
            return None
        array = self.mesh.polydata.GetPointData().GetArray("SkinWeights")
        return None if array is None else convert.view(array)

    def save(self, path):
        """Writes .vtp (nodes, edges, Radius, Root) .vtk .obj .ply .swc; returns the path."""
        return _save(self.polydata, path)

    def to_meshio(self):
        return _meshio(self.nodes, [("line", self.edges)], {"Radius": self.radius})

    def __repr__(self):
        return "<medial.Skeleton: %d nodes, %d edges, root %d>" % (self.polydata.GetNumberOfPoints(),
                                                                   len(self.edges), self.root)


class Centerline:
    """A centerline in the volume's world frame (mm): `points` (N, 3), `radius` (N,), `arc_length` (N,),
    `lines` (a list of point-index arrays: one per polyline, one per branch with branches=True), `bridged`
    (N,) 1 on bridged gaps; with sections=True `sections` (a dict of numpy columns: ArcLength, MinDiameter,
    MaxDiameter, Perimeter, Area) and `terrain` (the unfolded wall, [section, angle] mm); with surface=True
    `surface` (a Mesh: the lumen). `notes`: what the filter said a user should know."""

    def __init__(self, polydata, sections=None, terrain=None, surface=None, notes=()):
        self.polydata = polydata
        self.sections = _columns(sections) if isinstance(sections, vtkTable) else None
        self.terrain = _terrain(terrain) if isinstance(terrain, vtkImageData) else None
        self.surface = Mesh(surface) if isinstance(surface, vtkPolyData) else None
        self.notes = list(notes)

    @property
    def points(self):
        return convert.view(self.polydata.GetPoints().GetData())

    def _point_array(self, name):
        return convert.view(self.polydata.GetPointData().GetArray(name))

    @property
    def radius(self):
        return self._point_array("Radius")

    @property
    def arc_length(self):
        return self._point_array("ArcLength")

    @property
    def bridged(self):
        return self._point_array("Bridged")

    @property
    def lines(self):
        lines = self.polydata.GetLines()
        offsets, connectivity = convert.view(lines.GetOffsetsArray()), convert.view(lines.GetConnectivityArray())
        return [connectivity[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]

    def save(self, path):
        """Writes .vtp .vtk .obj .ply, or Slicer's markups with .mrk.json; returns the path."""
        return _save(self.polydata, path)

    def __repr__(self):
        length = self.arc_length[-1] if self.polydata.GetNumberOfPoints() else 0.0
        return "<medial.Centerline: %d points, %d lines, %.1f mm>" % (self.polydata.GetNumberOfPoints(),
                                                                      len(self.lines), length)


def _columns(table):
    return {table.GetColumnName(c): convert.view(table.GetColumn(c)) for c in range(table.GetNumberOfColumns())}


def _terrain(image):
    rays, sections, _ = image.GetDimensions()
    return convert.view(image.GetPointData().GetArray("WallDistance")).reshape(sections, rays)
