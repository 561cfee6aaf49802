#!/usr/bin/env python3
"""The edges of a recipe's mesh against the size asked, by where they lie:
inside a surface (no node on a curve), touching a curve (one node on a
curve or a point) or along or across one (both). Per class: count, mean,
10 / 50 / 90 % quantiles of length / size, and tau (Mesh/quality/
efficiencyIndex.h for a constant size) with that class's deficit left out:
which edges keep tau below the goal.

    python3 bench/edge-lengths.py MESH.msh SIZE

MESH.msh: an ASCII MSH 4.1 file (bench/coverage.sh's REPARAM_COVERAGE_LOGS
keep one per run, SIZE in the .geo beside it: Mesh.MeshSizeMax). Python 3
standard library only.
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import coverage  # noqa: E402


def deficit(length):
    return length - 1.0 if length < 1.0 else 1.0 / length - 1.0


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    path, size = sys.argv[1], float(sys.argv[2])
    dims = {}
    nodes = coverage.read_msh_nodes(path, dims)
    edges = set()
    for t in coverage.as_triangles(coverage.read_msh_surface(path)):
        for j in range(3):
            a, b = t[j], t[(j + 1) % 3]
            edges.add((min(a, b), max(a, b)))
    classes = {0: [], 1: [], 2: []}
    for a, b in edges:
        on_curves = (dims[a] <= 1) + (dims[b] <= 1)
        classes[on_curves].append(math.dist(nodes[a], nodes[b]) / size)
    total = sum(deficit(x) for c in classes.values() for x in c)
    count = sum(len(c) for c in classes.values())
    names = {0: "inside", 1: "touching a curve", 2: "along or across one"}
    print("| edges | count | mean | q10 | q50 | q90 | tau without their deficit (%) |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for k in (0, 1, 2):
        c = sorted(classes[k])
        if not c:
            continue
        q = lambda f: c[int(f * (len(c) - 1))]  # noqa: E731
        own = sum(deficit(x) for x in c)
        print("| %s | %d | %.3f | %.3f | %.3f | %.3f | %.1f |" % (
            names[k], len(c), sum(c) / len(c), q(0.1), q(0.5), q(0.9),
            100.0 * math.exp((total - own) / count)))
    print("\ntau %.1f %% over %d edges" % (100.0 * math.exp(total / count), count))


if __name__ == "__main__":
    main()
