#!/usr/bin/env python3
"""Segmentation-like STL files, what a CT or MRI segmentation exports (a
voxel mask thresholded, then surfaced), to check the STL recipe on the
kind of input Reparam is first meant for (bench/coverage.sh runs on them
like on the others):

  bench/make-segmentations.py out_folder [voxels=64]

writes, as binary STL, on a grid of `voxels` voxels a side (1 mm):
  vessel_binary.stl   a vessel (a trunk, two branches, an aneurysm sac) cut
                      open by the volume's border, the mask surfaced by
                      marching tetrahedra: terraces of 45 and 90 degrees
  vessel_smoothed.stl the same mask blurred once (3 x 3 x 3 mean) first,
                      as exporters smooth it
  vessel_slices.stl   the vessel in slices four times thicker than the
                      pixels (0.5 x 0.5 x 2 mm): tall terraces
  vessel_noisy.stl    the image noisy (Gaussian, 0.3 of the contrast) then
                      blurred once: bumps, specks of a few voxels floating
                      around, and pieces open on the volume's border
  vessel_voxels.stl   the mask's voxel faces, two triangles each (exporters
                      with no surfacing)
  bone_binary.stl     a block with two through holes and a closed cavity, a
                      torus beside it, and specks of one and eight voxels
Marching tetrahedra: six tetrahedra a voxel, about its main diagonal (the
same on both sides of every face, so the surface is closed but on the
border); each triangle turned from the inside to the outside. Python's
standard library only; the same arguments give the same files."""

import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stlfile  # noqa: E402

ISO = 0.5 + 1e-3  # never a node's value: no triangle with a corner on a node


def segment_distance(p, a, b):
    ab = [y - x for x, y in zip(a, b)]
    t = sum(u * (q - x) for u, q, x in zip(ab, p, a)) / sum(u * u for u in ab)
    t = max(0.0, min(1.0, t))
    return math.dist(p, [x + t * u for x, u in zip(a, ab)])


def inside_vessel(p, size):
    x = [v / size for v in p]
    tubes = (((0.5, 0.5, 0.08), (0.5, 0.5, 0.5), 0.1),
             ((0.5, 0.5, 0.5), (0.2, 0.5, 0.92), 0.07),
             ((0.5, 0.5, 0.5), (0.8, 0.5, 0.92), 0.06))
    if any(segment_distance(x, a, b) < r for a, b, r in tubes):
        return True
    return math.dist(x, (0.62, 0.56, 0.62)) < 0.12


def inside_bone(p, size):
    x, y, z = (v / size for v in p)
    if 0.1 < x < 0.9 and 0.1 < y < 0.45 and 0.2 < z < 0.8:
        return not (math.hypot(x - 0.3, z - 0.5) < 0.1 or
                    math.hypot(x - 0.7, z - 0.5) < 0.08 or
                    math.dist((x, y, z), (0.5, 0.28, 0.3)) < 0.06)
    return math.hypot(math.hypot(x - 0.5, z - 0.5) - 0.25, y - 0.72) < 0.09


class grid:
    def __init__(self, voxels, spacing):
        extent = voxels * min(spacing)
        self.spacing = spacing
        self.n = [int(round(extent / s)) + 1 for s in spacing]
        self.values = [0.0] * (self.n[0] * self.n[1] * self.n[2])
        self.extent = extent

    def index(self, i, j, k):
        return (k * self.n[1] + j) * self.n[0] + i

    def ijk(self, g):
        return g % self.n[0], g // self.n[0] % self.n[1], g // (self.n[0] * self.n[1])

    def point(self, g):
        return tuple(c * s for c, s in zip(self.ijk(g), self.spacing))

    def fill(self, inside):
        for g in range(len(self.values)):
            self.values[g] = 1.0 if inside(self.point(g), self.extent) else 0.0

    def blur(self):
        n, v = self.n, self.values
        out = v[:]
        for k in range(1, n[2] - 1):
            for j in range(1, n[1] - 1):
                for i in range(1, n[0] - 1):
                    out[self.index(i, j, k)] = sum(
                        v[self.index(i + a, j + b, k + c)]
                        for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)) / 27
        self.values = out

    def cells(self):
        n = self.n
        for k in range(n[2] - 1):
            for j in range(n[1] - 1):
                for i in range(n[0] - 1):
                    yield [self.index(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2))
                           for c in range(8)]


TETRAHEDRA = ((0, 1, 3, 7), (0, 3, 2, 7), (0, 2, 6, 7), (0, 6, 4, 7), (0, 4, 5, 7),
              (0, 5, 1, 7))


def outward(facet, inner, outer):
    """facet turned so that its normal goes from inner to outer."""
    a, b, c = facet
    u = [y - x for x, y in zip(a, b)]
    w = [y - x for x, y in zip(a, c)]
    normal = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    if sum(m * (o - i) for m, i, o in zip(normal, inner, outer)) < 0:
        return (a, c, b)
    return facet


def marching_tetrahedra(g):
    cut = {}

    def on_edge(a, b):
        key = (min(a, b), max(a, b))
        if key not in cut:
            t = (ISO - g.values[a]) / (g.values[b] - g.values[a])
            pa, pb = g.point(a), g.point(b)
            cut[key] = tuple(x + t * (y - x) for x, y in zip(pa, pb))
        return cut[key]

    def mean(nodes):
        return [sum(g.point(v)[m] for v in nodes) / len(nodes) for m in range(3)]

    facets = []
    for cell in g.cells():
        signs = [g.values[v] > ISO for v in cell]
        if all(signs) or not any(signs):
            continue
        for tet in TETRAHEDRA:
            nodes = [cell[c] for c in tet]
            ins = [v for v in nodes if g.values[v] > ISO]
            outs = [v for v in nodes if g.values[v] <= ISO]
            if not ins or not outs:
                continue
            if len(ins) == 2:
                a, b = ins
                c, d = outs
                q = [on_edge(a, c), on_edge(a, d), on_edge(b, d), on_edge(b, c)]
                pieces = [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
            else:
                alone, others = (ins[0], outs) if len(ins) == 1 else (outs[0], ins)
                pieces = [tuple(on_edge(alone, o) for o in others)]
            facets += [outward(f, mean(ins), mean(outs)) for f in pieces]
    return facets


def voxel_faces(g):
    facets = []
    n = g.n
    for k in range(n[2] - 1):
        for j in range(n[1] - 1):
            for i in range(n[0] - 1):
                if g.values[g.index(i, j, k)] < 0.5:
                    continue
                for d in range(3):
                    for s in (-1, 1):
                        q = [i, j, k]
                        q[d] += s
                        if 0 <= q[d] < n[d] - 1 and g.values[g.index(*q)] >= 0.5:
                            continue
                        base = [i, j, k]
                        base[d] += s == 1
                        e1, e2 = (d + 1) % 3, (d + 2) % 3
                        square = []
                        for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):
                            v = base[:]
                            v[e1] += a
                            v[e2] += b
                            square.append(tuple(c * sp for c, sp in zip(v, g.spacing)))
                        if s == -1:
                            square.reverse()
                        facets += [(square[0], square[1], square[2]),
                                   (square[0], square[2], square[3])]
    return facets


def add_specks(g, rng, count):
    """count specks, alternately of one voxel and of 2 x 2 x 2, where the
    mask is empty."""
    for s in range(count):
        i, j, k = (rng.randrange(3, m - 4) for m in g.n)
        if g.values[g.index(i, j, k)]:
            continue
        w = 1 + s % 2
        for a in range(w):
            for b in range(w):
                for c in range(w):
                    g.values[g.index(i + a, j + b, k + c)] = 1.0


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    folder = sys.argv[1]
    voxels = int(sys.argv[2]) if len(sys.argv) > 2 else 64
    os.makedirs(folder, exist_ok=True)
    rng = random.Random(7)
    made = []

    def write(name, facets):
        path = os.path.join(folder, name + ".stl")
        stlfile.write_binary_stl(path, facets, b"Reparam bench: " + name.encode())
        made.append("%s: %d triangles" % (path, len(facets)))

    g = grid(voxels, (1.0, 1.0, 1.0))
    g.fill(inside_vessel)
    write("vessel_binary", marching_tetrahedra(g))
    write("vessel_voxels", voxel_faces(g))
    mask = g.values[:]
    g.blur()
    write("vessel_smoothed", marching_tetrahedra(g))
    g.values = [v + rng.gauss(0.0, 0.3) for v in mask]
    g.blur()
    write("vessel_noisy", marching_tetrahedra(g))
    g = grid(int(voxels * 1.5), (0.5, 0.5, 2.0))
    g.fill(inside_vessel)
    write("vessel_slices", marching_tetrahedra(g))
    g = grid(voxels, (1.0, 1.0, 1.0))
    g.fill(inside_bone)
    add_specks(g, rng, 12)
    write("bone_binary", marching_tetrahedra(g))
    print("\n".join(made))


if __name__ == "__main__":
    main()
