// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The finite element harmonic map (Sec. 2.1, Eq. 7, 21, 23): minimizes the
// Dirichlet energy with the outer loop on the unit circle. Smooth, but the
// cotangent weights go negative on obtuse triangles and the map can flip.

#ifndef HARMONIC_MAP_H
#define HARMONIC_MAP_H

#include "discretePatch.h"
#include "patchAssembly.h"
#include "patchMap.h"

namespace reparam {

// The P1 stiffness matrix of one triangle as weights: w[i][j] = w[j][i] =
// cot(theta_k) / 2, theta_k the angle at the third node k
triangleWeights cotangentWeights(const SPoint3 &x0, const SPoint3 &x1,
                                 const SPoint3 &x2);

// Symmetric positive definite system: sparse Cholesky, one factorization
// for u and v
patchMap harmonicMap(const discretePatch &patch);

} // namespace reparam

#endif
