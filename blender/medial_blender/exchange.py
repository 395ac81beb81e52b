"""Blender data to the files `medial` reads: a mesh as binary PLY (vertex order kept, so that results map
back to the vertices), skeletons as .vtp with a Radius per node and a Root."""
import numpy

from . import vtp


class InputError(Exception):
    """The selection cannot be sent to Medial; str() is the message for the user."""


def vertex_positions(mesh, matrix=None):
    """The mesh's vertex coordinates (n x 3), transformed by the 4x4 matrix when given."""
    positions = numpy.empty(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", positions)
    positions = positions.reshape(-1, 3)
    if matrix is not None:
        m = numpy.array(matrix)
        positions = positions @ m[:3, :3].T + m[:3, 3]
    return positions


def triangles(mesh):
    """The mesh's faces as triangles (m x 3 vertex indices), Blender's own triangulation."""
    mesh.calc_loop_triangles()
    result = numpy.empty(len(mesh.loop_triangles) * 3, dtype=numpy.int32)
    mesh.loop_triangles.foreach_get("vertices", result)
    return result.reshape(-1, 3)


def open_edges(mesh):
    """How many edges do not have exactly two faces (the boundary and non-manifold edges)."""
    loop_edges = numpy.empty(len(mesh.loops), dtype=numpy.int64)
    mesh.loops.foreach_get("edge_index", loop_edges)
    faces_per_edge = numpy.bincount(loop_edges, minlength=len(mesh.edges))
    return int(numpy.count_nonzero(faces_per_edge != 2))


def require_closed_mesh(obj):
    mesh = obj.data
    if len(mesh.polygons) == 0:
        raise InputError("%s has no faces: Medial needs a closed surface mesh" % obj.name)
    count = open_edges(mesh)
    if count:
        raise InputError("%s is not closed: %d edge%s without exactly two faces (Select > Select All by Trait > "
                         "Non Manifold shows them)" % (obj.name, count, "" if count == 1 else "s"))


def write_ply(path, positions, faces):
    """Binary little-endian PLY of float64 vertices and triangles."""
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty double x\nproperty double y\n"
              "property double z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % (len(positions), len(faces)))
    records = numpy.empty(len(faces), dtype=[("count", "u1"), ("vertices", "<i4", (3,))])
    records["count"] = 3
    records["vertices"] = faces
    with open(path, "wb") as stream:
        stream.write(header.encode("ascii"))
        stream.write(numpy.ascontiguousarray(positions, dtype="<f8").tobytes())
        stream.write(records.tobytes())


def _merged_nodes(points, tolerance):
    """Indices of points, those closer than tolerance to an earlier one sharing its node."""
    nodes, index = [], []
    for p in points:
        for k, q in enumerate(nodes):
            if numpy.linalg.norm(p - q) <= tolerance:
                index.append(k)
                break
        else:
            index.append(len(nodes))
            nodes.append(p)
    return numpy.array(nodes), index


def armature_skeleton(armature, bones, matrix):
    """The skeleton of an armature's bones: a node at each head and tail (a child's head and its parent's tail
    where they meet: one node), bone i as segment i, Radius from the envelope radii (the largest where
    bones meet), Root at the head of the first bone without a parent. Coordinates through matrix."""
    if not bones:
        raise InputError("%s has no bones to use" % armature.name)
    m = numpy.array(matrix)
    ends = numpy.array([[*b.head_local] for b in bones] + [[*b.tail_local] for b in bones])
    ends = ends @ m[:3, :3].T + m[:3, 3]
    size = float(numpy.linalg.norm(ends.max(axis=0) - ends.min(axis=0))) or 1.0
    nodes, index = _merged_nodes(ends, 1e-5 * size)
    scale = float(numpy.cbrt(abs(numpy.linalg.det(m[:3, :3]))))
    radius = numpy.zeros(len(nodes))
    count = len(bones)
    for i, bone in enumerate(bones):
        radius[index[i]] = max(radius[index[i]], bone.head_radius * scale)
        radius[index[count + i]] = max(radius[index[count + i]], bone.tail_radius * scale)
    lines = [numpy.array([index[i], index[count + i]]) for i in range(count)]
    if any(line[0] == line[1] for line in lines):
        raise InputError("%s has a bone of zero length" % armature.name)
    top = next((i for i, b in enumerate(bones) if b.parent not in bones), 0)
    return vtp.PolyData(nodes, lines, point_data={"Radius": radius}, field_data={"Root": [index[top]]})


def skin_skeleton(obj):
    """The skeleton of a mesh made of edges with Skin modifier radii (the mean of a vertex's two radii, in
    the object's own coordinates, as the modifier takes them), Root at the skin root vertex."""
    mesh = obj.data
    if len(mesh.polygons):
        raise InputError("%s has faces: a skeleton for SQM is a mesh of edges only (or an armature)" % obj.name)
    if len(mesh.edges) == 0:
        raise InputError("%s has no edges: nothing to mesh" % obj.name)
    if len(mesh.skin_vertices) == 0:
        raise InputError("%s has no radii: add a Skin modifier and set its vertex radii (Ctrl A)" % obj.name)
    edges = numpy.empty(len(mesh.edges) * 2, dtype=numpy.int64)
    mesh.edges.foreach_get("vertices", edges)
    used = numpy.unique(edges)
    remap = numpy.full(len(mesh.vertices), -1, dtype=numpy.int64)
    remap[used] = numpy.arange(len(used))
    skin = mesh.skin_vertices[0].data
    radius = numpy.array([sum(skin[int(v)].radius) / 2.0 for v in used])
    if numpy.any(radius <= 0):
        raise InputError("%s has vertices of radius 0 in its Skin modifier" % obj.name)
    roots = [int(remap[v]) for v in used if skin[int(v)].use_root]
    lines = [pair for pair in remap[edges].reshape(-1, 2)]
    return vtp.PolyData(vertex_positions(mesh)[used], lines, point_data={"Radius": radius},
                        field_data={"Root": roots[:1]} if roots else {})
