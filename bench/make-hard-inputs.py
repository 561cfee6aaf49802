#!/usr/bin/env python3
"""Harder variants of a real STL, to check the patch layout on inputs it was
not developed on (bench/coverage.sh runs on them like on the others):

  bench/make-hard-inputs.py in.stl out_folder [seed]

writes, as binary STL:
  NAME_noisy.stl    every node moved at random by up to 15 % of the mean edge,
                    and 0.5 % of the nodes pushed out by 2 mean edges along
                    their normal (spikes: folded, sliver and tiny patches)
  NAME_messy.stl    2 % of the triangles reversed (inconsistent orientation)
                    and 0.2 % duplicated facing the other way (the closed
                    two-triangle pieces Gmsh's split loop never ends on)
Python's standard library only; the same seed gives the same files."""

import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stlfile  # noqa: E402


def read(path):
    corners = stlfile.stl_corners(path)
    ids, points, triangles = {}, [], []
    for i in range(0, len(corners) - 2, 3):
        t = []
        for p in corners[i : i + 3]:
            if p not in ids:
                ids[p] = len(points)
                points.append(list(p))
            t.append(ids[p])
        triangles.append(t)
    return points, triangles


def write(path, points, triangles):
    stlfile.write_binary_stl(path, [[points[i] for i in t] for t in triangles],
                             b"reparam hard input")


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0]]


def noisy(points, triangles, rng):
    edges = [math.dist(points[t[k]], points[t[(k + 1) % 3]])
             for t in triangles for k in range(3)]
    h = sum(edges) / len(edges)
    normals = [[0.0, 0.0, 0.0] for _ in points]
    for t in triangles:
        n = cross(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]]))
        for i in t:
            for c in range(3):
                normals[i][c] += n[c]
    out = []
    for p, n in zip(points, normals):
        q = [x + rng.uniform(-0.15, 0.15) * h for x in p]
        if rng.random() < 0.005:
            norm = math.sqrt(sum(c * c for c in n)) or 1.0
            q = [x + 2.0 * h * c / norm for x, c in zip(q, n)]
        out.append(q)
    return out, triangles


def messy(points, triangles, rng):
    out = []
    for t in triangles:
        out.append(t[::-1] if rng.random() < 0.02 else t)
        if rng.random() < 0.002:
            out.append(t[::-1])
    return points, out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    source, folder = sys.argv[1], sys.argv[2]
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    os.makedirs(folder, exist_ok=True)
    name = os.path.splitext(os.path.basename(source))[0]
    points, triangles = read(source)
    for label, make in (("noisy", noisy), ("messy", messy)):
        p, t = make(points, triangles, random.Random(seed))
        write(os.path.join(folder, "%s_%s.stl" % (name, label)), p, t)


if __name__ == "__main__":
    main()
