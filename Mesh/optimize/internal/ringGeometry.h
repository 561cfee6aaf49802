// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Small geometry of a node's ring (the triangles around it) that the
// optimizer's flips, moves and smoothing sweeps share.

#ifndef OPTIMIZE_RING_GEOMETRY_H
#define OPTIMIZE_RING_GEOMETRY_H

#include <algorithm>
#include <array>
#include <vector>
#include "SPoint3.h"
#include "SVector3.h"

namespace reparam::optimizeInternal {

inline SPoint3 centroidOf(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c)
{
  return SPoint3((a.x() + b.x() + c.x()) / 3., (a.y() + b.y() + c.y()) / 3.,
                 (a.z() + b.z() + c.z()) / 3.);
}

inline double longestEdge(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c)
{
  return std::max(a.distance(b), std::max(b.distance(c), c.distance(a)));
}

// The corners of triangle t with v at `at`
inline void cornersWith(const std::array<int, 3> &t, int v, const SPoint3 &at,
                        const std::vector<SPoint3> &points, SPoint3 c[3])
{
  for(int k = 0; k < 3; k++) c[k] = t[k] == v ? at : points[t[k]];
}

// The plane of a ring, as its triangles turn: the sum over `ring` (indices
// in `triangles`) of (b - a) x (c - a), twice their area-weighted normal
SVector3 ringNormal(const std::vector<SPoint3> &points,
                    const std::vector<std::array<int, 3> > &triangles,
                    const std::vector<int> &ring);

} // namespace reparam::optimizeInternal

#endif
