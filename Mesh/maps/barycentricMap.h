// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Tutte's barycentric convex map (Sec. 2.2, Eq. 12): every interior node at
// the average of its neighbours, the outer loop on the unit circle. One-to-
// one, but blind to the geometry (non-smooth metric, paper Fig. 14).

#ifndef BARYCENTRIC_MAP_H
#define BARYCENTRIC_MAP_H

#include "discretePatch.h"
#include "patchAssembly.h"
#include "patchMap.h"

namespace reparam {

// Eq. (12): 1/2 per triangle sharing the edge, so an interior edge weighs 1
triangleWeights barycentricWeights(const SPoint3 &x0, const SPoint3 &x1,
                                   const SPoint3 &x2);

// Symmetric: sparse Cholesky, one factorization for u and v
patchMap barycentricMap(const discretePatch &patch);

} // namespace reparam

#endif
