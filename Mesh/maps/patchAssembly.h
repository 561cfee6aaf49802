// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The one assembly routine over triangles that the linear maps share: each
// map supplies its element weights w^e_ij, assembled as Eq. (24).

#ifndef PATCH_ASSEMBLY_H
#define PATCH_ASSEMBLY_H

#include <array>
#include <functional>
#include <Eigen/SparseCore>
#include "discretePatch.h"

namespace reparam {

// w[i][j] (i != j): weight of local node j in the equation of local node i;
// the diagonal is unused
typedef std::array<std::array<double, 3>, 3> triangleWeights;
typedef std::function<triangleWeights(const SPoint3 &, const SPoint3 &,
                                      const SPoint3 &)>
  triangleWeightFunction;

// A_ij = -sum_e w^e_ij, A_ii = sum_e sum_j w^e_ij (Eq. 24): row i of A x = 0
// says that x_i is the weighted average of its neighbours
Eigen::SparseMatrix<double>
assembleWeightedLaplacian(const discretePatch &patch,
                          const triangleWeightFunction &weights);

} // namespace reparam

#endif
