#!/usr/bin/python3
"""Makes the SQM test skeletons (committed under data/skeletons/sqm/): run with /usr/bin/python3.

    worm.vtp        linear, 23 nodes, no branch node (SQM extension 2)
    humanoid.vtp    62 nodes: spine, head, arms with a knuckle bar and five fingers, legs with feet
    octopus.vtp     131 nodes: a body and eight curling tentacles of 16 nodes
    quadruped.vtp   150 nodes: spine, neck, head, ears, tail, four legs with toes
    fish.vtp        ellipsoid nodes (EllipsoidAxes), root at the head, a leaf (extensions 1 and 3)
    leafroot.vtp    a branching skeleton whose Root is a leaf (extension 1)
    cycle.vtp       14 nodes: a loop of 10 with a tail of 4 (extension 5)
    pretzel.vtp     34 nodes, three independent cycles: a loop crossed by two chords at different heights

and the skeletons whose tubes overlap (under data/skeletons/overlapping/, for `medial sqm --union`):

    crossing.vtp    two straight tubes of radius 0.5 crossing each other (two components)
    dense-tree.vtp  150 nodes, a random tree grown in a box, radii 0.2-1.0: branches pass through others
"""
import math
import os
import random

import vtk

HERE = os.path.dirname(os.path.abspath(__file__))


class Builder:
    def __init__(self):
        self.nodes, self.edges, self.axes = [], [], []

    def node(self, p, r, parent=None, axes=None):
        self.nodes.append((p[0], p[1], p[2], r))
        self.axes.append(axes)
        if parent is not None:
            self.edges.append((parent, len(self.nodes) - 1))
        return len(self.nodes) - 1

    def chain(self, parent, points, radii):
        for p, r in zip(points, radii):
            parent = self.node(p, r, parent)
        return parent

    def polydata(self, root):
        points = vtk.vtkPoints()
        points.SetDataTypeToDouble()
        radius = vtk.vtkDoubleArray()
        radius.SetName("Radius")
        for x, y, z, r in self.nodes:
            points.InsertNextPoint(x, y, z)
            radius.InsertNextValue(r)
        lines = vtk.vtkCellArray()
        for a, b in self.edges:
            lines.InsertNextCell(2, [a, b])
        skeleton = vtk.vtkPolyData()
        skeleton.SetPoints(points)
        skeleton.SetLines(lines)
        skeleton.GetPointData().AddArray(radius)
        if any(a is not None for a in self.axes):
            axes = vtk.vtkDoubleArray()
            axes.SetName("EllipsoidAxes")
            axes.SetNumberOfComponents(9)
            for (x, y, z, r), a in zip(self.nodes, self.axes):
                axes.InsertNextTuple(a if a is not None else (r, 0, 0, 0, r, 0, 0, 0, r))
            skeleton.GetPointData().AddArray(axes)
        root_array = vtk.vtkIntArray()
        root_array.SetName("Root")
        root_array.InsertNextValue(root)
        skeleton.GetFieldData().AddArray(root_array)
        return skeleton


def line(start, direction, count, step):
    return [tuple(start[i] + direction[i] * step * (k + 1) for i in range(3)) for k in range(count)]


def worm():
    b = Builder()
    head = b.node((0, 0, 0), 0.3)
    pts = [(0.45 * (k + 1), 0.5 * math.sin(0.45 * (k + 1)), 0.2 * math.sin(0.2 * (k + 1))) for k in range(22)]
    b.chain(head, pts, [0.3 - 0.009 * k for k in range(22)])
    return b.polydata(head)


def humanoid():
    b = Builder()
    pelvis = b.node((0, 0, 0), 0.14)
    spine = b.chain(pelvis, [(0, 0.15, 0), (0, 0.3, 0.01), (0, 0.45, 0)], [0.13, 0.13, 0.14])
    chest = spine
    neck = b.chain(chest, [(0, 0.62, 0.0), (0, 0.70, 0.0)], [0.06, 0.055])
    b.chain(neck, [(0, 0.82, 0.02), (0, 0.92, 0.02)], [0.1, 0.08])
    for side in (-1, 1):
        wrist = b.chain(chest, [(side * 0.18, 0.56, 0), (side * 0.3, 0.5, 0.01), (side * 0.42, 0.42, 0.02),
                                (side * 0.52, 0.34, 0.05), (side * 0.6, 0.27, 0.08)],
                        [0.065, 0.055, 0.05, 0.045, 0.04])
        # A knuckle bar across the hand, five knuckles 0.035 apart, and a finger from each, parallel.
        # Fingers fanning out of the wrist node itself would make cones that overlap over their whole
        # length (they converge on one centre); tubes of different branches must not overlap, or no mesh
        # of them can avoid cutting itself. Knuckle radius 0.016: two of them leave 0.003 between fingers.
        along = (side * 0.7, -0.7, 0.0)
        n = math.sqrt(sum(c * c for c in along))
        along = tuple(c / n for c in along)
        middle = (side * 0.6 + along[0] * 0.05, 0.27 + along[1] * 0.05, 0.08)
        knuckle = {0: b.chain(wrist, [middle], [0.018])}
        for step in (1, -1):
            for f in (step, 2 * step):
                point = (middle[0], middle[1], middle[2] + 0.035 * f)
                knuckle[f] = b.chain(knuckle[f - step], [point], [0.016])
        for f in range(-2, 3):
            b.chain(knuckle[f], line(b.nodes[knuckle[f]][:3], along, 2, 0.04), [0.014, 0.012])
        foot = b.chain(pelvis, [(side * 0.1, -0.08, 0), (side * 0.11, -0.3, 0.01), (side * 0.12, -0.5, 0.03),
                                (side * 0.12, -0.7, 0.02), (side * 0.12, -0.9, 0)],
                       [0.09, 0.08, 0.065, 0.055, 0.045])
        b.chain(foot, [(side * 0.12, -0.94, 0.08), (side * 0.12, -0.95, 0.16)], [0.045, 0.04])
    return b.polydata(pelvis)


def octopus():
    b = Builder()
    body = b.node((0, 0, 0), 0.6)
    b.chain(body, [(0, 0.7, 0), (0, 1.2, 0)], [0.55, 0.45])
    for t in range(8):
        phi = 2 * math.pi * t / 8
        pts, radii = [], []
        for k in range(16):
            s = (k + 1) / 16.0
            reach = 0.5 + 2.6 * s
            curl = phi + 1.2 * s * s
            pts.append((reach * math.cos(curl), -0.3 - 0.8 * s + 0.5 * s ** 3, reach * math.sin(curl)))
            radii.append(0.16 * (1 - 0.8 * s))
        b.chain(body, pts, radii)
    return b.polydata(body)


def quadruped():
    b = Builder()
    spine_pts = [(0.1 * k, 0.0, 0.0) for k in range(20)]
    hips = b.node(spine_pts[0], 0.32)
    previous = hips
    spine = [hips]
    for p in spine_pts[1:]:
        previous = b.node(p, 0.3, previous)
        spine.append(previous)
    shoulders = spine[-1]
    # Neck, head and ears.
    head = b.chain(shoulders, line((1.9, 0, 0), (0.6, 0.8, 0), 9, 0.1), [0.18 - 0.006 * k for k in range(9)])
    head = b.chain(head, line((2.44, 0.72, 0), (1, 0, 0), 4, 0.1), [0.2, 0.19, 0.15, 0.1])
    for side in (-1, 1):  # ears apart by more than their radii
        b.chain(head, line((2.84, 0.72, side * 0.07), (-0.3, 0.7, side * 0.5), 4, 0.06), [0.06, 0.05, 0.04, 0.03])
    # Tail.
    tail = [(-0.1 * (k + 1), 0.05 * (k + 1) ** 0.8, 0.02 * k) for k in range(20)]
    b.chain(hips, tail, [0.1 - 0.0045 * k for k in range(20)])
    # Legs: from the first and last spine nodes; toes at each paw.
    for base, x in ((hips, 0.0), (shoulders, 1.9)):
        for side in (-1, 1):
            # The legs leave the body from its sides (0.2 off the spine), so the two legs of a pair stay
            # further apart than their radii.
            paw = b.chain(base, line((x, 0, side * 0.2), (0, -1, side * 0.1), 10, 0.1), [0.12 - 0.006 * k for k in range(10)])
            for toe in (-1, 1):
                b.chain(paw, line((x, -1.0, side * 0.3), (0.8, -0.3, toe * 0.4), 1, 0.08), [0.03])
    # Extra spine bump: a dorsal fin-like ridge.
    b.chain(spine[10], [(1.0, 0.4, 0.0)], [0.05])
    return b.polydata(hips)


def fish():
    b = Builder()
    def ellipsoid(length, height, width):
        return (length, 0, 0, 0, height, 0, 0, 0, width)
    head = b.node((0, 0, 0), 0.25, axes=ellipsoid(0.25, 0.3, 0.2))
    previous = head
    body_nodes = []
    for k in range(8):
        s = (k + 1) / 8.0
        h = 0.35 + 0.35 * math.sin(math.pi * s) - 0.3 * s
        previous = b.node((0.35 * (k + 1), 0.03 * math.sin(3 * s), 0), 0.2, previous, ellipsoid(0.2, max(h, 0.08), 0.12 * (1 - 0.6 * s)))
        body_nodes.append(previous)
    # Tail fin and two pectoral fins.
    for dy in (1, -1):
        b.chain(previous, [(3.0, 0.25 * dy, 0), (3.25, 0.5 * dy, 0)], [0.08, 0.05])
    for side in (-1, 1):
        b.chain(body_nodes[1], [(0.8, -0.2, side * 0.25), (0.95, -0.3, side * 0.45)], [0.05, 0.03])
    b.chain(body_nodes[3], [(1.4, 0.55, 0), (1.6, 0.75, 0)], [0.06, 0.03])
    return b.polydata(head)


def leafroot():
    b = Builder()
    tip = b.node((0, -1.5, 0), 0.15)
    stem = b.chain(tip, [(0, -1.0, 0), (0, -0.5, 0), (0, 0, 0)], [0.2, 0.22, 0.25])
    for angle in (0, 2.1, 4.2):
        b.chain(stem, [(0.5 * math.cos(angle), 0.4, 0.5 * math.sin(angle)),
                       (1.0 * math.cos(angle), 0.8, 1.0 * math.sin(angle))], [0.15, 0.1])
    return b.polydata(tip)


def cycle():
    b = Builder()
    ring = [b.node((1.2 * math.cos(2 * math.pi * k / 10), 1.2 * math.sin(2 * math.pi * k / 10), 0), 0.25) for k in range(10)]
    for k in range(10):
        b.edges.append((ring[k], ring[(k + 1) % 10]))
    b.chain(ring[0], [(1.2 + 0.5 * (k + 1), 0, 0) for k in range(4)], [0.22, 0.2, 0.18, 0.15])
    return b.polydata(ring[0])


def pretzel():
    b = Builder()
    ring = [b.node((2 * math.cos(2 * math.pi * k / 24), 2 * math.sin(2 * math.pi * k / 24), 0), 0.2) for k in range(24)]
    for k in range(24):
        b.edges.append((ring[k], ring[(k + 1) % 24]))
    for start, end, height in ((0, 12, 0.45), (6, 18, -0.45)):
        a, z = ring[start], ring[end]
        pa, pz = b.nodes[a][:3], b.nodes[z][:3]
        points = [tuple(pa[i] + (pz[i] - pa[i]) * (k + 1) / 6.0 for i in range(2)) + (height * math.sin(math.pi * (k + 1) / 6.0),)
                  for k in range(5)]
        last = b.chain(a, points, [0.16] * 5)
        b.edges.append((last, z))
    return b.polydata(ring[0])


def crossing():
    b = Builder()
    first = b.node((-3, 0, 0), 0.5)
    b.chain(first, line((-3, 0, 0), (1, 0, 0), 6, 1.0), [0.5] * 6)
    second = b.node((0.5, -3, 0.3), 0.5)
    b.chain(second, line((0.5, -3, 0.3), (0, 1, 0), 6, 1.0), [0.5] * 6)
    return b.polydata(first)


def dense_tree(count=150, seed=7):
    """A tree grown by attaching each node to a random earlier one (recent ones more often, so that branches
    grow long), a step of 1.4-2.0 in a direction at least 45 degrees from the node's other edges, kept
    inside a box of side 9: branches of different parts cross. Radii uniform in [0.2, 1.0]."""
    rng = random.Random(seed)
    b = Builder()
    b.node((0, 0, 0), rng.uniform(0.2, 1.0))
    directions = {0: []}
    while len(b.nodes) < count:
        parent = len(b.nodes) - 1 - int(len(b.nodes) * rng.random() ** 3)
        if len(directions[parent]) >= 3:
            continue
        d = [rng.gauss(0, 1) for _ in range(3)]
        n = math.sqrt(sum(c * c for c in d))
        d = [c / n for c in d]
        if any(sum(a * c for a, c in zip(d, e)) > math.cos(math.radians(45)) for e in directions[parent]):
            continue
        step = rng.uniform(1.4, 2.0)
        p = [b.nodes[parent][i] + step * d[i] for i in range(3)]
        if any(abs(c) > 4.5 for c in p):
            continue
        child = b.node(p, rng.uniform(0.2, 1.0), parent)
        directions[parent].append(d)
        directions[child] = [[-c for c in d]]
    return b.polydata(0)


def write_vtp(polydata, path):
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(polydata)
    writer.SetDataModeToAscii()
    writer.Write()


if __name__ == "__main__":
    folder = os.path.join(HERE, "skeletons", "sqm")
    os.makedirs(folder, exist_ok=True)
    for name, make in (("worm", worm), ("humanoid", humanoid), ("octopus", octopus), ("quadruped", quadruped),
                       ("fish", fish), ("leafroot", leafroot), ("cycle", cycle), ("pretzel", pretzel)):
        skeleton = make()
        write_vtp(skeleton, os.path.join(folder, name + ".vtp"))
        print("%-10s %4d nodes" % (name, skeleton.GetNumberOfPoints()))
    folder = os.path.join(HERE, "skeletons", "overlapping")
    os.makedirs(folder, exist_ok=True)
    for name, make in (("crossing", crossing), ("dense-tree", dense_tree)):
        skeleton = make()
        write_vtp(skeleton, os.path.join(folder, name + ".vtp"))
        print("%-10s %4d nodes" % (name, skeleton.GetNumberOfPoints()))
