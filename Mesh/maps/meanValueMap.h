// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Floater's mean-value convex combination map (Sec. 2.2): one-to-one for any
// triangulation once the outer boundary is on a convex curve.

#ifndef MEAN_VALUE_MAP_H
#define MEAN_VALUE_MAP_H

#include "discretePatch.h"
#include "patchAssembly.h"
#include "patchMap.h"

namespace reparam {

// Eq. (14): weights of one triangle; w[i][j] = tan(alpha_i / 2) / |x_i - x_j|
// with alpha_i the triangle's angle at node i
triangleWeights meanValueWeights(const SPoint3 &x0, const SPoint3 &x1,
                                 const SPoint3 &x2);

// The outer loop on the unit circle (Eq. 26), the other loops free (zero
// Neumann), interior nodes the mean-value average of their neighbours. The
// matrix is not symmetric: sparse LU, one factorization for u and v.
// Requires a disk-like patch (makeDiscretePatch succeeded).
patchMap meanValueMap(const discretePatch &patch);

} // namespace reparam

#endif
