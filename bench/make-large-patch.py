#!/usr/bin/env python3
"""Writes a smooth bumpy square patch of about N triangles as a binary STL:
the bench's "100k-triangle patch" for the per-map speed targets.

    bench/make-large-patch.py out.stl [N=100000]
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stlfile  # noqa: E402

out = sys.argv[1]
target = int(sys.argv[2]) if len(sys.argv) > 2 else 100000
n = int(math.ceil(math.sqrt(target / 2.0)))


def point(i, j):
    x, y = i / n, j / n
    return (x, y, 0.15 * math.sin(3.0 * x) * math.cos(4.0 * y))


triangles = []
for j in range(n):
    for i in range(n):
        a, b = point(i, j), point(i + 1, j)
        c, d = point(i, j + 1), point(i + 1, j + 1)
        triangles += [(a, b, d), (a, d, c)]
stlfile.write_binary_stl(out, triangles, b"Reparam bench: bumpy square patch")
