// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Dirichlet boundary conditions of the maps onto a convex domain.

#ifndef PATCH_BOUNDARY_H
#define PATCH_BOUNDARY_H

#include <vector>
#include "discretePatch.h"

namespace reparam {

// Eq. (26): the nodes of boundary loop `loop` on the unit circle, at angles
// proportional to their arc length from the loop's first node, counterclockwise
// (the loop's own direction, which leaves the patch on its left). Sets uv
// (2 values per node) and isFixed for those nodes only.
void mapLoopToUnitCircle(const discretePatch &patch, int loop,
                         std::vector<double> &uv, std::vector<char> &isFixed);

} // namespace reparam

#endif
