// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Solves L [u v] = 0 at the free nodes with (u, v) prescribed at the fixed
// ones: the system every map with a Dirichlet boundary shares (Eq. 23).

#ifndef DIRICHLET_SOLVE_H
#define DIRICHLET_SOLVE_H

#include <vector>
#include <Eigen/SparseCore>
#include "reparamStatus.h"

enum class sparseFactorization {
  cholesky, // symmetric positive definite: SimplicialLDLT
  lu // general: KLU
};

// uv holds 2 values per node; on input those of the fixed nodes are set,
// on success all are. One factorization serves both coordinates.
reparamError dirichletSolve(const Eigen::SparseMatrix<double> &L,
                            const std::vector<char> &isFixed,
                            std::vector<double> &uv,
                            sparseFactorization factorization);

#endif
