#!/usr/bin/env python3
"""Seed corpus of scripts/fuzz.sh: small binary STL files, each a case the
reading path and the layout must survive (Python's standard library only).

  tests/fuzz/make-seeds.py FOLDER
"""
import math
import os
import struct
import sys


def stl(facets, count=None):
    """Binary STL bytes of `facets` (triples of corners); `count` the facet
    count the header announces (default: as many as there are)."""
    out = b"seed".ljust(80, b"\0")
    out += struct.pack("<I", len(facets) if count is None else count)
    for f in facets:
        out += struct.pack("<3f", 0.0, 0.0, 0.0)
        for p in f:
            out += struct.pack("<3f", *p)
        out += b"\0\0"
    return out


def cube(side=1.0):
    p = [(side * (k & 1), side * ((k >> 1) & 1), side * ((k >> 2) & 1)) for k in range(8)]
    c = [0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
         2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5]
    return [[p[c[3 * t + j]] for j in range(3)] for t in range(12)]


def bumpy_disk(n=6):
    """A fan of triangles around a raised centre, and a ring around it."""
    ring = [(math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n), 0.0) for k in range(n)]
    top = (0.0, 0.0, 0.7)
    return [[top, ring[k], ring[(k + 1) % n]] for k in range(n)]


def main():
    folder = sys.argv[1]
    os.makedirs(folder, exist_ok=True)
    c = cube()
    seeds = {
        "cube": stl(c),
        "cube-cut-short": stl(c)[:84 + 50 * 7 + 20],
        "cube-count-too-large": stl(c, count=1000),
        "nan-facet": stl(c[:-1] + [[(float("nan"), 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]]),
        "huge": stl(cube(1e30)),
        "degenerate": stl([[(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (2.0, 0.0, 0.0)]] * 4),
        "duplicated": stl(c + c),
        "reversed-half": stl(c[:6] + [[f[0], f[2], f[1]] for f in c[6:]]),
        "cone": stl(bumpy_disk()),
        "empty": stl([]),
    }
    for name, data in seeds.items():
        with open(os.path.join(folder, name + ".stl"), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
