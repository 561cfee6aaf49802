// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// How closely quadrangles follow the input surface, for the topological
// changes of a quadrangle mesh (Mesh/quad/quadDiagonalCollapse.h,
// Mesh/quad/quadNodeSplit.h): a quadrangle's centre is the midpoint of either
// diagonal, as it is not planar.

#ifndef QUAD_FIDELITY_H
#define QUAD_FIDELITY_H

#include <array>
#include <vector>
#include "SPoint3.h"

namespace reparam {

class closestTriangleSearch;

// How far p lies from the quadrangles qs of points x (each taken as the
// four triangles of its two diagonals)
double distanceToQuadrangles(const SPoint3 &p,
                             const std::vector<std::array<int, 4> > &qs,
                             const std::vector<SPoint3> &x);

// The farthest from the input of the quadrangles' centres (the midpoints of
// their two diagonals)
double farthestCentreFromInput(const std::vector<std::array<int, 4> > &qs,
                               const std::vector<SPoint3> &x,
                               const closestTriangleSearch &onInput);

} // namespace reparam

#endif
