// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The finite element conformal map, or least squares conformal map (LSCM,
// Sec. 2.3, Eq. 15-22): minimizes E_D - A with two pinned nodes and a free
// boundary.

#ifndef CONFORMAL_MAP_H
#define CONFORMAL_MAP_H

#include <array>
#include "discretePatch.h"
#include "patchMap.h"

namespace reparam {

// The two nodes of the outer loop farthest apart in 3D (the default pins of
// the paper): exact for loops of up to 2048 nodes, above that the best of a
// few double sweeps (each one finds the farthest node from the last one)
std::array<int, 2> farthestBoundaryPair(const discretePatch &patch);

// The nodes of the outer loop at both ends of the patch's principal axis of
// inertia (largest spread of its nodes): the pins the paper advises when the
// farthest pair folds (Sec. 6.4)
std::array<int, 2> principalAxisPins(const discretePatch &patch);

// Pins pins[0] at (-1, 0) and pins[1] at (1, 0), so that the image has the
// size of the unit disk the convex maps use. Sparse Cholesky of the coupled
// (u, v) system with the 4 pinned unknowns eliminated.
patchMap conformalMap(const discretePatch &patch, std::array<int, 2> pins);
patchMap conformalMap(const discretePatch &patch);

} // namespace reparam

#endif
