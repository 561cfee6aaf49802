#!/usr/bin/env python3
"""The closed pieces of STL inputs near the rule of Mesh/checks/flatPieces.cpp.

    bench/flat-pieces.py FILE.stl ...

Per input: its size (the edge of as many equilateral triangles as its
facets: the layout's noise size) and its pieces (facets joined through
edges, after the pieces of repeated facets only, which the input's repair
drops first). A piece is listed when it is smaller than twice the size or
its mean thickness (3 |volume| / area) is below 2 % of its bounding box's
diagonal; the last column says whether Reparam drops it (closed, smaller
than the size, thinner than 1 %). Python's standard library only.
"""

import collections
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stlfile  # noqa: E402


def facets_of(path):
    corners = stlfile.stl_corners(path)
    index, points, facets = {}, [], []
    for i in range(0, len(corners) - 2, 3):
        ids = []
        for p in corners[i:i + 3]:
            key = tuple(p)
            if key not in index:
                index[key] = len(points)
                points.append(key)
            ids.append(index[key])
        if len(set(ids)) == 3:
            facets.append(ids)
    # pieces made of repeated facets only (pillows) are the repair's
    return points, facets


def pieces_of(facets):
    by_edge = collections.defaultdict(list)
    for i, f in enumerate(facets):
        for k in range(3):
            by_edge[tuple(sorted((f[k], f[(k + 1) % 3])))].append(i)
    parent = list(range(len(facets)))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    for users in by_edge.values():
        for u in users[1:]:
            parent[find(u)] = find(users[0])
    pieces = collections.defaultdict(list)
    for i in range(len(facets)):
        pieces[find(i)].append(i)
    return list(pieces.values()), by_edge


def area(points, f):
    a, b, c = (points[j] for j in f)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
         u[0] * v[1] - u[1] * v[0])
    return 0.5 * math.sqrt(sum(x * x for x in n))


def volume(points, piece, facets):
    o = points[facets[piece[0]][0]]
    v = 0.0
    for i in piece:
        a, b, c = ([p[k] - o[k] for k in range(3)]
                   for p in (points[j] for j in facets[i]))
        v += (a[0] * (b[1] * c[2] - b[2] * c[1])
              - a[1] * (b[0] * c[2] - b[2] * c[0])
              + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
    return v


def main(paths):
    print("| input | size | pieces | piece's facets | closed | diagonal / size "
          "| thickness / diagonal | dropped |")
    print("|---|---:|---:|---:|---|---:|---:|---|")
    for path in paths:
        points, facets = facets_of(path)
        pieces, by_edge = pieces_of(facets)
        repeated = collections.Counter(tuple(sorted(f)) for f in facets)
        pieces = [p for p in pieces
                  if any(repeated[tuple(sorted(facets[i]))] < 2 for i in p)]
        kept = [i for p in pieces for i in p]
        total = sum(area(points, facets[i]) for i in kept)
        size = math.sqrt(4 * total / (math.sqrt(3) * len(kept))) if kept else 0
        name = os.path.basename(path)
        listed = 0
        for p in pieces:
            nodes = {j for i in p for j in facets[i]}
            lo = [min(points[j][k] for j in nodes) for k in range(3)]
            hi = [max(points[j][k] for j in nodes) for k in range(3)]
            diagonal = math.dist(lo, hi)
            a = sum(area(points, facets[i]) for i in p)
            thick = 3 * abs(volume(points, p, facets)) / a if a else 0.0
            closed = all(len(by_edge[tuple(sorted((facets[i][k],
                                                   facets[i][(k + 1) % 3])))])
                         == 2 for i in p for k in range(3))
            if diagonal < 2 * size or thick < 0.02 * diagonal:
                dropped = closed and diagonal < size and thick < 0.01 * diagonal
                print("| %s | %.3g | %d | %d | %s | %.3g | %.3g | %s |" % (
                    name, size, len(pieces), len(p), "yes" if closed else "no",
                    diagonal / size, thick / diagonal if diagonal else 0,
                    "yes" if dropped else "no"))
                listed += 1
        if not listed:
            print("| %s | %.3g | %d | - | - | - | - | - |" % (
                name, size, len(pieces)))


if __name__ == "__main__":
    main(sys.argv[1:])
