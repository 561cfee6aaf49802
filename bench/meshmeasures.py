"""Quality and distances of a triangle mesh against the surface it was made
from, by the definitions of Reparam's report (Mesh/quality), for meshes that
have no report (another remesher's) and for the Hausdorff distance's two
sides apart. Python's standard library only."""

import collections
import math

import stlfile


def welded_surface(stl):
    """(points, triangles) of an STL: corners with identical coordinates
    welded into one point."""
    corners = stlfile.stl_corners(stl)
    ids, triangles = {}, []
    for i in range(0, len(corners) - 2, 3):
        triangles.append(tuple(ids.setdefault(p, len(ids))
                               for p in corners[i : i + 3]))
    points = [None] * len(ids)
    for p, i in ids.items():
        points[i] = p
    return points, triangles


def diagonal(points):
    lo = [min(p[i] for p in points) for i in range(3)]
    hi = [max(p[i] for p in points) for i in range(3)]
    return math.sqrt(sum((hi[i] - lo[i]) ** 2 for i in range(3)))


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def kappa(a, b, c):
    """Eq. (3) of Mesh/quality/triangleQuality.h: 4 sin a sin b sin c /
    (sin a + sin b + sin c), from the sines at each corner."""
    p = (a, b, c)
    sines = []
    for i in range(3):
        u, v = _sub(p[(i + 1) % 3], p[i]), _sub(p[(i + 2) % 3], p[i])
        lu, lv = math.sqrt(_dot(u, u)), math.sqrt(_dot(v, v))
        if lu == 0.0 or lv == 0.0:
            return 0.0
        n = _cross(u, v)
        sines.append(math.sqrt(_dot(n, n)) / (lu * lv))
    total = sum(sines)
    return 0.0 if total == 0.0 else 4.0 * sines[0] * sines[1] * sines[2] / total


def kappa_min_mean(points, triangles):
    values = [kappa(*(points[i] for i in t)) for t in triangles]
    if not values:
        return None, None
    return min(values), sum(values) / len(values)


def tau(points, triangles, size):
    """Eq. (5) of Mesh/quality/efficiencyIndex.h for a constant size: 100
    exp(mean d) over the unique edges, d = l - 1 for l < 1, else 1 / l - 1,
    l = length / size."""
    edges = set()
    for t in triangles:
        for j in range(3):
            a, b = t[j], t[(j + 1) % 3]
            edges.add((a, b) if a < b else (b, a))
    if not edges:
        return None
    total = 0.0
    for a, b in edges:
        d = _sub(points[a], points[b])
        length = math.sqrt(_dot(d, d)) / size
        total += length - 1.0 if length < 1.0 else 1.0 / length - 1.0
    return 100.0 * math.exp(total / len(edges))


def closest_squared(p, a, b, c):
    """Squared distance from p to the triangle (a, b, c), by the region of
    the triangle's plane p projects to (vertex, edge or face)."""
    ab, ac, ap = _sub(b, a), _sub(c, a), _sub(p, a)
    d1, d2 = _dot(ab, ap), _dot(ac, ap)
    if d1 <= 0.0 and d2 <= 0.0:
        return _dot(ap, ap)
    bp = _sub(p, b)
    d3, d4 = _dot(ab, bp), _dot(ac, bp)
    if d3 >= 0.0 and d4 <= d3:
        return _dot(bp, bp)
    cp = _sub(p, c)
    d5, d6 = _dot(ab, cp), _dot(ac, cp)
    if d6 >= 0.0 and d5 <= d6:
        return _dot(cp, cp)
    vc = d1 * d4 - d3 * d2
    if vc <= 0.0 and d1 >= 0.0 and d3 <= 0.0:
        return _segment_rest(ap, ab, d1 / (d1 - d3))
    vb = d5 * d2 - d1 * d6
    if vb <= 0.0 and d2 >= 0.0 and d6 <= 0.0:
        return _segment_rest(ap, ac, d2 / (d2 - d6))
    va = d3 * d6 - d5 * d4
    if va <= 0.0 and d4 - d3 >= 0.0 and d5 - d6 >= 0.0:
        bc = _sub(c, b)
        return _segment_rest(bp, bc, (d4 - d3) / ((d4 - d3) + (d5 - d6)))
    total = va + vb + vc
    if total == 0.0:  # a flat triangle: its corners are close enough
        return min(_dot(ap, ap), _dot(bp, bp), _dot(cp, cp))
    v, w = vb / total, vc / total
    r = tuple(ap[i] - ab[i] * v - ac[i] * w for i in range(3))
    return _dot(r, r)


def _segment_rest(offset, direction, t):
    r = tuple(offset[i] - direction[i] * t for i in range(3))
    return _dot(r, r)


class TriangleGrid:
    """The triangles of a mesh in a uniform grid of cubic buckets (each in
    every bucket its bounding box meets), for the closest triangle to a
    point: rings of buckets around it until no farther ring can be closer."""

    def __init__(self, points, triangles):
        self.points, self.triangles = points, triangles
        extent = 0.0
        for t in triangles:
            for i in range(3):
                values = [points[n][i] for n in t]
                extent += max(values) - min(values)
        self.cell = max(extent / (3.0 * max(len(triangles), 1)), 1e-300)
        self.buckets = collections.defaultdict(list)
        for index, t in enumerate(triangles):
            lo = self._key([min(points[n][i] for n in t) for i in range(3)])
            hi = self._key([max(points[n][i] for n in t) for i in range(3)])
            for x in range(lo[0], hi[0] + 1):
                for y in range(lo[1], hi[1] + 1):
                    for z in range(lo[2], hi[2] + 1):
                        self.buckets[(x, y, z)].append(index)
        # bounding spheres: most triangles of a bucket are ruled out by one
        # distance to the sphere's center
        self.spheres = []
        for t in triangles:
            center = tuple(sum(points[n][i] for n in t) / 3.0 for i in range(3))
            radius = max(math.dist(center, points[n]) for n in t)
            self.spheres.append((center, radius))
        keys = list(self.buckets) or [(0, 0, 0)]
        self.lo = [min(k[i] for k in keys) for i in range(3)]
        self.hi = [max(k[i] for k in keys) for i in range(3)]

    def _key(self, p):
        return tuple(int(math.floor(p[i] / self.cell)) for i in range(3))

    def _ring(self, key, r):
        x0, y0, z0 = key
        for x in range(x0 - r, x0 + r + 1):
            for y in range(y0 - r, y0 + r + 1):
                edge = abs(x - x0) == r or abs(y - y0) == r
                for z in ((range(z0 - r, z0 + r + 1)) if edge
                          else (z0 - r, z0 + r) if r else (z0,)):
                    bucket = self.buckets.get((x, y, z))
                    if bucket:
                        yield bucket

    def _inside(self, p, key, r):
        """Distance from p to the outside of the rings up to r around it."""
        return min(min(p[i] - (key[i] - r) * self.cell,
                       (key[i] + r + 1) * self.cell - p[i]) for i in range(3))

    def closest(self, p):
        """(distance, triangle index) of the closest triangle to p."""
        key = self._key(p)
        far = max(max(abs(key[i] - self.lo[i]), abs(key[i] - self.hi[i]))
                  for i in range(3))
        best, which = math.inf, None
        for r in range(far + 1):
            for bucket in self._ring(key, r):
                for index in bucket:
                    center, radius = self.spheres[index]
                    near = math.dist(p, center) - radius
                    if near > 0.0 and near * near >= best:
                        continue
                    a, b, c = (self.points[n] for n in self.triangles[index])
                    d = closest_squared(p, a, b, c)
                    if d < best:
                        best, which = d, index
            if which is not None and math.sqrt(best) <= self._inside(p, key, r):
                break
        return math.sqrt(best), which


def samples(points, triangles):
    """The nodes the triangles use and their centroids, as Reparam's report
    samples."""
    used = sorted(set(n for t in triangles for n in t))
    centroids = [tuple(sum(points[n][i] for n in t) / 3.0 for i in range(3))
                 for t in triangles]
    return [points[n] for n in used] + centroids


def one_sided_hausdorff(points, triangles, grid):
    """Largest distance from the samples of (points, triangles) to the mesh
    in `grid`."""
    return max((grid.closest(p)[0] for p in samples(points, triangles)),
               default=None)


def normal(a, b, c):
    return _cross(_sub(b, a), _sub(c, a))


def consistently_oriented(triangles):
    """Whether no directed edge is used twice (then neighbours agree)."""
    directed = collections.Counter()
    for t in triangles:
        for j in range(3):
            directed[(t[j], t[(j + 1) % 3])] += 1
    return all(n == 1 for n in directed.values())


def against_input(points, triangles, input_points, input_triangles, grid):
    """Triangles whose normal points against the input triangle closest to
    their centroid, the mesh taken the way most of it points (a remesher may
    reverse the whole), or None when the input's own facets disagree."""
    if not consistently_oriented(input_triangles):
        return None
    against = 0
    for t in triangles:
        a, b, c = (points[n] for n in t)
        centroid = tuple((a[i] + b[i] + c[i]) / 3.0 for i in range(3))
        _, closest = grid.closest(centroid)
        if closest is None:
            continue
        under = normal(*(input_points[n] for n in input_triangles[closest]))
        against += _dot(normal(a, b, c), under) < 0.0
    return min(against, len(triangles) - against)
