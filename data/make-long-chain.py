#!/usr/bin/python3
"""Writes a long branching chain whose tubes overlap, as an SWC file (the kind a neuron tracing or a dense
vessel tree gives): SQM's test at scale (`medial_bench_sqm --scale`, the SqmAtScale test).

    data/make-long-chain.py NODES OUT.swc [--seed S] [--volume-per-node V] [--flat]

A random walk of steps 0.8-1.2 that turns at most 30 degrees per node, with a side branch of 4-12 nodes
leaving every 10-30 nodes at 50-90 degrees from the chain, radii 0.25-0.6, reflected at the walls of a
box whose volume grows with the node count (8 units per node by default), so that the density of overlaps, and
so the work per node, stays the same from 1,000 to 100,000 nodes. Tubes of different parts cross each
other wherever the walk comes back. With --flat the walk stays in the plane z = 0 (a square of the same
area per node), as 2D neuron tracings and sketches give: every face's box then shares coordinates with
many others, the case that made CGAL's box intersection degrade. Pure Python (no VTK), deterministic for
a seed.
"""
import argparse
import math
import random


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def turned(rng, d, most_degrees, least_degrees=0.0, flat=False):
    """A unit direction between least and most degrees away from d, in a random plane (the xy plane
    when flat)."""
    while True:
        w = unit([rng.gauss(0, 1), rng.gauss(0, 1), 0.0 if flat else rng.gauss(0, 1)])
        side = [w[i] - sum(a * b for a, b in zip(w, d)) * d[i] for i in range(3)]
        if sum(c * c for c in side) > 1e-6:
            break
    side = unit(side)
    angle = math.radians(rng.uniform(least_degrees, most_degrees))
    return unit([math.cos(angle) * d[i] + math.sin(angle) * side[i] for i in range(3)])


def long_chain(count, seed=1, volume_per_node=8.0, flat=False):
    rng = random.Random(seed)
    # half the side of the box (flat: of the square with V^(2/3) per node, a cube's face per node)
    if flat:
        half = 0.5 * (volume_per_node ** (2.0 / 3.0) * count) ** 0.5
    else:
        half = 0.5 * (volume_per_node * count) ** (1.0 / 3.0)
    nodes, parents, radii = [[0.0, 0.0, 0.0]], [-1], [0.5]
    tip, direction = 0, unit([1.0, 0.3, 0.0 if flat else 0.1])

    def step(frm, d):
        p = [nodes[frm][i] + rng.uniform(0.8, 1.2) * d[i] for i in range(3)]
        for i in range(3):  # reflected at the walls
            if abs(p[i]) > half:
                d[i] = -d[i]
                p[i] = nodes[frm][i] + (p[i] - nodes[frm][i]) * -1
        nodes.append(p)
        parents.append(frm)
        radii.append(rng.uniform(0.25, 0.6))
        return len(nodes) - 1

    until_branch = rng.randint(10, 30)
    while len(nodes) < count:
        direction = turned(rng, direction, 30, flat=flat)
        tip = step(tip, direction)
        until_branch -= 1
        if until_branch > 0 or len(nodes) >= count:
            continue
        until_branch = rng.randint(10, 30)
        at, d = tip, turned(rng, direction, 90, 50, flat)
        for _ in range(min(rng.randint(4, 12), count - len(nodes))):
            at = step(at, d)
            d = turned(rng, d, 30, flat=flat)
    return nodes, parents, radii


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("nodes", type=int)
    parser.add_argument("out")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--volume-per-node", type=float, default=8.0,
                        help="the box's volume per node (default 8; smaller: denser, more overlaps)")
    parser.add_argument("--flat", action="store_true", help="a walk in the plane z = 0")
    args = parser.parse_args()
    if args.nodes < 2:
        parser.error("NODES must be at least 2")
    nodes, parents, radii = long_chain(args.nodes, args.seed, args.volume_per_node, args.flat)
    with open(args.out, "w") as out:
        out.write("# %d nodes: data/make-long-chain.py %d --seed %d%s\n"
                  % (len(nodes), args.nodes, args.seed, " --flat" if args.flat else ""))
        for k, (p, r, parent) in enumerate(zip(nodes, radii, parents)):
            out.write("%d 3 %.4f %.4f %.4f %.3f %d\n" % (k + 1, p[0], p[1], p[2], r, parent + 1 if parent >= 0 else -1))


if __name__ == "__main__":
    main()
