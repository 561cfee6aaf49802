#!/usr/bin/env python3
"""Writes tutorials/dome.stl: the bundled example of a poor triangulation.

A bumpy dome over the unit disk with two holes, triangulated on a polar grid
whose rings are crowded towards the rim and twisted from ring to ring, so that
the centre has long slivers (kappa < 0.1) like a raw segmentation. Binary STL,
deterministic (no random numbers), consistently oriented (normals up).

    scripts/make-tutorial-stl.py [out.stl]
"""
import math
import struct
import sys

RINGS = 14  # rings of nodes around the centre
SECTORS = 128  # nodes per ring
HOLES = [(5, 8, 10, 22), (9, 12, 70, 84)]  # ring and sector ranges of cells


def height(x, y):
    r2 = x * x + y * y
    return 0.35 * (1.0 - r2) + 0.06 * math.sin(3.0 * math.atan2(y, x)) * r2


def node(i, j):
    if i == 0:
        return (0.0, 0.0, height(0.0, 0.0))
    r = (i / RINGS) ** 0.6
    a = 2.0 * math.pi * (j + 0.37 * i) / SECTORS  # twist between rings
    x, y = r * math.cos(a), r * math.sin(a)
    return (x, y, height(x, y))


def in_hole(i, j):
    return any(i0 <= i < i1 and j0 <= j < j1 for i0, i1, j0, j1 in HOLES)


def triangles():
    for j in range(SECTORS):  # centre fan
        yield node(0, 0), node(1, j), node(1, (j + 1) % SECTORS)
    for i in range(1, RINGS):
        for j in range(SECTORS):
            if in_hole(i, j):
                continue
            a, b = node(i, j), node(i, (j + 1) % SECTORS)
            c, d = node(i + 1, j), node(i + 1, (j + 1) % SECTORS)
            if (i + j) % 2:
                yield a, c, d
                yield a, d, b
            else:
                yield a, c, b
                yield b, c, d


def normal(p, q, r):
    u = [q[k] - p[k] for k in range(3)]
    v = [r[k] - p[k] for k in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
         u[0] * v[1] - u[1] * v[0])
    length = math.sqrt(sum(c * c for c in n))
    return tuple(c / length for c in n)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "tutorials/dome.stl"
    tris = list(triangles())
    with open(out, "wb") as f:
        f.write(b"Reparam tutorial dome: bumpy, two holes, slivers".ljust(80, b"\0"))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", *normal(*t)))
            for p in t:
                f.write(struct.pack("<3f", *p))
            f.write(b"\0\0")
    print(f"{out}: {len(tris)} triangles")


if __name__ == "__main__":
    main()
