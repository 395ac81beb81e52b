#!/usr/bin/python3
"""Makes the sketch test strokes (committed under data/sketches/): run with /usr/bin/python3.

File format (read by vtkMedialSketchReader): one `x y` line per point of a closed stroke, parts separated
by a blank line, `#` starts a comment. A part may end with four lines of four numbers: the 4x4 matrix that
places the stroke's plane (x, y, 0) in 3-D (row-major; the identity when absent).

    rectangle.txt   400 x 100 rectangle: one bone
    star.txt        five-pointed star (outer radius 300, inner 120): one junction, five terminals
    hand.txt        palm, four fingers and a thumb drawn as one outline
    bird.txt        three parts: a side-view body with head and tail, two wings drawn from above and
                    placed in the horizontal plane through the body (placement matrices)
    unsteady.txt    a bent sausage drawn by an unsteady hand: 2000 points with 3 px of jitter
                    (perimeter ~1970 px as in the paper's Fig. 19)
"""
import math
import os
import random

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "sketches")


def write(name, parts, comment):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("# %s (made by data/make-sketches.py)\n" % comment)
        for k, part in enumerate(parts):
            points, matrix = part if isinstance(part, tuple) else (part, None)
            if k > 0:
                f.write("\n")
            for x, y in points:
                f.write("%.3f %.3f\n" % (x, y))
            if matrix:
                for row in matrix:
                    f.write(" ".join("%g" % v for v in row) + "\n")


def arc(center, radius, start, end, steps):
    return [(center[0] + radius * math.cos(start + (end - start) * i / steps),
             center[1] + radius * math.sin(start + (end - start) * i / steps)) for i in range(steps + 1)]


def finger(first, second, direction, length):
    """A capsule sticking out of an outline walked counter-clockwise from `first` to `second`."""
    dx, dy = direction
    norm = math.hypot(dx, dy)
    dx, dy = dx / norm, dy / norm
    a = (first[0] + length * dx, first[1] + length * dy)
    b = (second[0] + length * dx, second[1] + length * dy)
    center = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    radius = math.hypot(a[0] - b[0], a[1] - b[1]) / 2
    start = math.atan2(a[1] - center[1], a[0] - center[0])
    # turn left (counter-clockwise) from a to b through the tip
    points = [first] + [(first[0] + t * length * dx, first[1] + t * length * dy) for t in (0.33, 0.66)]
    points += arc(center, radius, start, start + math.pi, 12)
    points += [(second[0] + t * length * dx, second[1] + t * length * dy) for t in (0.66, 0.33)] + [second]
    return points


def hand():
    points = [(90, -180), (310, -180), (330, 0), (400, 150), (400, 430)]
    for left, right, length in ((380, 322, 200), (300, 232, 290), (218, 142, 320), (130, 60, 280)):
        points += finger((left, 450), (right, 450), (0, 1), length)
    points += [(20, 440)]
    points += finger((0, 330), (10, 180), (-0.8, 0.6), 210)
    points += [(60, 0)]
    return points


def star():
    return [((300 if i % 2 == 0 else 120) * math.cos(math.pi / 2 + i * math.pi / 5),
             (300 if i % 2 == 0 else 120) * math.sin(math.pi / 2 + i * math.pi / 5)) for i in range(10)]


def bird_body():
    points = []
    for i in range(160):
        t = 2 * math.pi * i / 160
        r = 1 / math.sqrt((math.cos(t) / 240) ** 2 + (math.sin(t) / 100) ** 2)
        r += 110 * math.exp(-((t - 0.45) / 0.22) ** 2)                              # head and neck
        r += 90 * math.exp(-((t - math.pi - 0.1) / 0.12) ** 2)                      # tail
        points.append((r * math.cos(t), r * math.sin(t)))
    return points


def wing_outline():
    # counter-clockwise: along the trailing edge out to the tip, back along the leading edge
    lower = [(x, 10 - 50 * (1 - (x / 420) ** 1.5)) for x in range(20, 421, 20)]
    upper = [(x, 10 + 60 * (1 - (x / 420) ** 2)) for x in range(400, 19, -20)]
    return lower + upper


def unsteady():
    """A bent sausage (centre arc of radius 400 over 115 degrees, 110 px thick, round caps) resampled to
    2000 points, each moved by up to 3 px at random."""
    outline = arc((0, 0), 455, math.radians(30), math.radians(145), 200)
    end = (400 * math.cos(math.radians(145)), 400 * math.sin(math.radians(145)))
    outline += arc(end, 55, math.radians(145), math.radians(145) + math.pi, 40)[1:-1]
    outline += arc((0, 0), 345, math.radians(145), math.radians(30), 150)
    start = (400 * math.cos(math.radians(30)), 400 * math.sin(math.radians(30)))
    outline += arc(start, 55, math.radians(30) + math.pi, math.radians(30) + 2 * math.pi, 40)[1:-1]
    lengths = [math.dist(outline[i], outline[(i + 1) % len(outline)]) for i in range(len(outline))]
    total, n, rng = sum(lengths), 2000, random.Random(7)
    points, edge, travelled = [], 0, 0.0
    for k in range(n):
        target = k * total / n
        while travelled + lengths[edge] < target:
            travelled += lengths[edge]
            edge += 1
        t = (target - travelled) / lengths[edge]
        a, b = outline[edge], outline[(edge + 1) % len(outline)]
        points.append((a[0] + t * (b[0] - a[0]) + rng.uniform(-3, 3), a[1] + t * (b[1] - a[1]) + rng.uniform(-3, 3)))
    return points


def main():
    os.makedirs(HERE, exist_ok=True)
    write("rectangle.txt", [[(0, 0), (400, 0), (400, 100), (0, 100)]], "a 400 x 100 rectangle")
    write("star.txt", [star()], "a five-pointed star")
    write("hand.txt", [hand()], "a hand: palm, four fingers, thumb")
    right = [[0, 1, 0, -20], [0, 0, 1, 20], [1, 0, 0, 0], [0, 0, 0, 1]]   # stroke x -> +z, y -> x
    left = [[0, 1, 0, -20], [0, 0, -1, 20], [-1, 0, 0, 0], [0, 0, 0, 1]]  # stroke x -> -z, y -> x
    write("bird.txt", [bird_body(), (wing_outline(), right), (wing_outline(), left)],
          "a bird: side-view body, two wings drawn from above and placed through the body")
    write("unsteady.txt", [unsteady()], "a bent sausage drawn by an unsteady hand")


if __name__ == "__main__":
    main()
