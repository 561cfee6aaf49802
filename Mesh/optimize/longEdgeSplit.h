// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Inner edges of a new surface mesh much longer than the mesh size asked
// there, split at the input point closest to their midpoint. The planar
// mesher sizes triangles through the map's metric, which it samples: where
// a conformal map shrinks a long protrusion of coarse input triangles,
// Frontal-Delaunay left edges 6 times the size, cutting a crease off
// (bench/README.md, Optimization on the input).

#ifndef LONG_EDGE_SPLIT_H
#define LONG_EDGE_SPLIT_H

#include <cstddef>
#include "optimizableMesh.h"

namespace reparam {

class closestTriangleSearch;

// Splits the inner edges of m (not locked) longer than `ratio` times the
// mean of optimizableMesh::size at their ends, longest first, at most one
// per triangle and its neighbours, where no new triangle points against the
// input (reversed: m's triangles turn against the input's) nor is worse than
// the worst triangle of m (or 0.5) and the two it replaces (an edge across a
// strip narrower than the size stays): splits do not lower m's worst kappa,
// except for an edge whose midpoint is farther from the input than a tenth
// of its length (it cuts a crease or a hole's wall off: fidelity first);
// the new nodes are movable. Returns how many (0 if m has no sizes)
std::size_t splitLongEdges(optimizableMesh &m, const surfaceMesh &input,
                           const closestTriangleSearch &onInput, bool reversed,
                           double ratio);

} // namespace reparam

#endif
