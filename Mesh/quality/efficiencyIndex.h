// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// How well the edges of a mesh follow the size field it was made for (Sec. 1
// of the paper, after Frey and George).

#ifndef EFFICIENCY_INDEX_H
#define EFFICIENCY_INDEX_H

#include <array>
#include <functional>
#include <vector>
#include "SPoint3.h"

namespace reparam {

// Eq. (6): l = |b - a| * int_0^1 1 / size(a + t (b - a)) dt, by 3-point
// Gauss-Legendre (exact for a constant size)
double adimensionalLength(const SPoint3 &a, const SPoint3 &b,
                          const std::function<double(const SPoint3 &)> &size);

// Eq. (5): tau = 100 exp(mean d_i) over the edges (pairs of indices into
// points), d = l - 1 for l < 1 and 1 / l - 1 otherwise; 100 % when every
// edge has l = 1. 0 without edges.
double efficiencyIndex(const std::vector<SPoint3> &points,
                       const std::vector<std::array<int, 2> > &edges,
                       const std::function<double(const SPoint3 &)> &size);

// The edges of triangles and quadrangles, each once
std::vector<std::array<int, 2> >
uniqueEdges(const std::vector<std::array<int, 3> > &triangles,
            const std::vector<std::array<int, 4> > &quadrangles);

} // namespace reparam

#endif
