#!/usr/bin/python3
"""Makes Medial's bundled samples (committed in data/): run with /usr/bin/python3 (Debian's VTK).

    data/meshes/torus.off         closed genus-1 triangle mesh (OFF, 1,152 faces)
    data/meshes/capsule.vtp       closed genus-0 triangle mesh (VTP): a bent, elongated ellipsoid
    data/skeletons/figure.vtp     humanoid skeleton with Radius and Root (docs/ARCHITECTURE.md section 4)
    data/skeletons/hand.swc       hand skeleton as SWC (wrist, palm, five fingers)
"""
import math
import os

import vtk

HERE = os.path.dirname(os.path.abspath(__file__))


def write_off(polydata, path):
    points = polydata.GetPoints()
    polys = polydata.GetPolys()
    ids = vtk.vtkIdList()
    faces = []
    polys.InitTraversal()
    while polys.GetNextCell(ids):
        faces.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (points.GetNumberOfPoints(), len(faces)))
        for i in range(points.GetNumberOfPoints()):
            out.write("%.6f %.6f %.6f\n" % points.GetPoint(i))
        for f in faces:
            out.write("%d %s\n" % (len(f), " ".join(map(str, f))))


def torus():
    """A torus (R = 1, r = 0.35) as a regular 48 x 12 grid of quads split into triangles."""
    rings, sides = 48, 12
    points = vtk.vtkPoints()
    for i in range(rings):
        u = 2 * math.pi * i / rings
        for j in range(sides):
            v = 2 * math.pi * j / sides
            rr = 1.0 + 0.35 * math.cos(v)
            points.InsertNextPoint(rr * math.cos(u), rr * math.sin(u), 0.35 * math.sin(v))
    polys = vtk.vtkCellArray()
    for i in range(rings):
        for j in range(sides):
            a = i * sides + j
            b = ((i + 1) % rings) * sides + j
            c = ((i + 1) % rings) * sides + (j + 1) % sides
            d = i * sides + (j + 1) % sides
            polys.InsertNextCell(3, [a, b, c])
            polys.InsertNextCell(3, [a, c, d])
    mesh = vtk.vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    return mesh


def capsule():
    """An ellipsoid stretched to 0.4 x 0.4 x 2 and bent along a circle of radius 2: closed, genus 0."""
    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(32)
    sphere.SetPhiResolution(48)
    sphere.Update()
    # Stretch the sphere into a capsule and bend it: (x, y, z) -> along an arc of radius 2.
    points = vtk.vtkPoints()
    src = sphere.GetOutput()
    for i in range(src.GetNumberOfPoints()):
        x, y, z = src.GetPoint(i)
        x, y, z = x * 0.8, y * 0.8, z * 4.0  # 0.4 radius, 2.0 long
        angle = z / 2.0 * (math.pi / 4)
        radius = 2.0 + x
        points.InsertNextPoint(radius * math.cos(angle) - 2.0, y, radius * math.sin(angle))
    mesh = vtk.vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(src.GetPolys())
    return mesh


def skeleton_polydata(nodes, edges, root):
    points = vtk.vtkPoints()
    points.SetDataTypeToDouble()
    radius = vtk.vtkDoubleArray()
    radius.SetName("Radius")
    for x, y, z, r in nodes:
        points.InsertNextPoint(x, y, z)
        radius.InsertNextValue(r)
    lines = vtk.vtkCellArray()
    for a, b in edges:
        lines.InsertNextCell(2, [a, b])
    skeleton = vtk.vtkPolyData()
    skeleton.SetPoints(points)
    skeleton.SetLines(lines)
    skeleton.GetPointData().AddArray(radius)
    root_array = vtk.vtkIntArray()
    root_array.SetName("Root")
    root_array.InsertNextValue(root)
    skeleton.GetFieldData().AddArray(root_array)
    return skeleton


def figure():
    """A standing humanoid (1.8 units tall), pelvis as root."""
    nodes, edges = [], []

    def node(x, y, z, r, parent=None):
        nodes.append((x, y, z, r))
        if parent is not None:
            edges.append((parent, len(nodes) - 1))
        return len(nodes) - 1

    pelvis = node(0.0, 0.0, 0.0, 0.13)
    spine = node(0.0, 0.22, 0.0, 0.12, pelvis)
    chest = node(0.0, 0.45, 0.0, 0.15, spine)
    neck = node(0.0, 0.64, 0.0, 0.055, chest)
    node(0.0, 0.80, 0.02, 0.11, neck)
    for side in (-1, 1):
        shoulder = node(side * 0.19, 0.56, 0.0, 0.065, chest)
        elbow = node(side * 0.42, 0.40, 0.02, 0.05, shoulder)
        wrist = node(side * 0.60, 0.27, 0.08, 0.04, elbow)
        node(side * 0.66, 0.20, 0.12, 0.045, wrist)
        hip = node(side * 0.11, -0.06, 0.0, 0.09, pelvis)
        knee = node(side * 0.12, -0.48, 0.03, 0.065, hip)
        ankle = node(side * 0.12, -0.90, 0.0, 0.045, knee)
        node(side * 0.12, -0.94, 0.14, 0.04, ankle)
    return skeleton_polydata(nodes, edges, pelvis)


def write_hand_swc(path):
    """SWC: wrist (root) -> palm -> five fingers of three to four segments; types 1 soma-like, 3 finger."""
    rows = [(1, 1, 0.0, 0.0, 0.0, 0.9, -1), (2, 1, 0.0, 2.0, 0.0, 1.1, 1)]
    next_id = 3
    bases = [(-1.6, 1.4, 0.6), (-1.0, 3.1, 0.0), (-0.3, 3.4, 0.0), (0.4, 3.3, 0.0), (1.1, 2.9, 0.0)]
    lengths = [(1.1, 0.9, 0.7), (1.4, 0.9, 0.7), (1.5, 1.0, 0.8), (1.4, 0.9, 0.7), (1.1, 0.7, 0.6)]
    # Neighbouring finger bases 0.71-0.81 apart: their radii sum to less, so their tubes do not overlap
    # (overlapping tubes of different branches make any tube mesh cut itself).
    radii = [0.42, 0.33, 0.34, 0.33, 0.30]
    for finger, ((bx, by, bz), segs, r) in enumerate(zip(bases, lengths, radii)):
        parent = 2
        x, y, z = bx, by, bz
        dx, dy = (-0.8, 0.6) if finger == 0 else (0.12 * (finger - 2), 1.0)
        norm = math.hypot(dx, dy)
        dx, dy = dx / norm, dy / norm
        rows.append((next_id, 3, x, y, z, r, parent))
        parent, next_id = next_id, next_id + 1
        for k, length in enumerate(segs):
            x, y = x + dx * length, y + dy * length
            rows.append((next_id, 3, x, y, z, r * (0.9 - 0.1 * k), parent))
            parent, next_id = next_id, next_id + 1
    with open(path, "w") as out:
        out.write("# Hand skeleton made by data/make-samples.py: id type x y z radius parent\n")
        for row in rows:
            out.write("%d %d %.4f %.4f %.4f %.4f %d\n" % row)


def write_vtp(polydata, path, ascii=False):
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(polydata)
    if ascii:
        writer.SetDataModeToAscii()
    writer.Write()


if __name__ == "__main__":
    write_off(torus(), os.path.join(HERE, "meshes", "torus.off"))
    write_vtp(capsule(), os.path.join(HERE, "meshes", "capsule.vtp"))
    write_vtp(figure(), os.path.join(HERE, "skeletons", "figure.vtp"), ascii=True)
    write_hand_swc(os.path.join(HERE, "skeletons", "hand.swc"))
    print("samples written under", HERE)
