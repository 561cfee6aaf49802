#!/usr/bin/env python3
"""Writes a large scan-like STL: a mesh's triangles each cut into 4 by its
edge midpoints, `levels` times, every node then moved by a pseudo-random
offset of up to `noise` times the new mean edge (the same for a node in
every triangle around it): issue 15's 1M-triangle scan from armadillo
(86k triangles, 2 levels: 1.38M).

    bench/make-large-scan.py in.stl out.stl [levels=2] [noise=0.1]
"""
import hashlib
import math
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stlfile  # noqa: E402


def subdivided(triangles):
    out = []
    for a, b, c in triangles:
        ab, bc, ca = (tuple((x + y) / 2 for x, y in zip(p, q))
                      for p, q in ((a, b), (b, c), (c, a)))
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return out


def offset(p, amplitude):
    """A pseudo-random offset of p, a function of its coordinates."""
    h = hashlib.blake2b(struct.pack("<3f", *p), digest_size=12).digest()
    u = struct.unpack("<3I", h)
    return tuple(p[k] + amplitude * (2.0 * u[k] / 0xFFFFFFFF - 1.0)
                 for k in range(3))


def main():
    source, out = sys.argv[1], sys.argv[2]
    levels = int(sys.argv[3]) if len(sys.argv) > 3 else 2
    noise = float(sys.argv[4]) if len(sys.argv) > 4 else 0.1
    corners = stlfile.stl_corners(source)
    triangles = [tuple(corners[i:i + 3]) for i in range(0, len(corners) - 2, 3)]
    for _ in range(levels):
        triangles = subdivided(triangles)
    edge = sum(math.dist(t[0], t[1]) for t in triangles[::97]) / len(triangles[::97])
    # float32 coordinates, as the file stores them: a node shared by
    # triangles gets one offset
    moved = {}
    def move(p):
        key = struct.pack("<3f", *p)
        if key not in moved:
            moved[key] = offset(struct.unpack("<3f", key), noise * edge)
        return moved[key]
    triangles = [tuple(move(p) for p in t) for t in triangles]
    stlfile.write_binary_stl(out, triangles, b"Reparam bench: large scan")
    print("%d triangles, mean edge %g, noise %g" % (len(triangles), edge, noise * edge))


if __name__ == "__main__":
    main()
