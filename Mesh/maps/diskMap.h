// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// What the harmonic and the convex combination maps share: the outer loop
// on the unit circle by arc length (Eq. 26), the other loops free (zero
// Neumann), and L [u v] = 0 at the other nodes (Eq. 23), L assembled from
// the map's triangle weights (Eq. 24).

#ifndef DISK_MAP_H
#define DISK_MAP_H

#include "dirichletSolve.h"
#include "discretePatch.h"
#include "patchAssembly.h"
#include "patchMap.h"

namespace reparam {

// `factorization` must suit the weights: cholesky for symmetric ones
patchMap diskMap(const discretePatch &patch,
                 const triangleWeightFunction &weights,
                 sparseFactorization factorization);

} // namespace reparam

#endif
