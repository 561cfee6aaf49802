// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Solves L [u v] = 0 at the free nodes with (u, v) prescribed at the fixed
// ones: the system every map with a Dirichlet boundary shares (Eq. 23).

#ifndef DIRICHLET_SOLVE_H
#define DIRICHLET_SOLVE_H

#include <complex>
#include <vector>
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include "reparamStatus.h"

namespace reparam {

enum class sparseFactorization {
  cholesky, // symmetric (Hermitian) positive definite: SimplicialLDLT
  lu // general, real only: KLU, UMFPACK above 10k unknowns
};

// Each column of x is one right-hand side: on input the rows of the fixed
// unknowns are set, on success all are. One factorization serves all columns.
reparamError dirichletSolve(const Eigen::SparseMatrix<double> &L,
                            const std::vector<char> &isFixed,
                            Eigen::MatrixXd &x,
                            sparseFactorization factorization);

// The same for a Hermitian L over complex unknowns (the conformal energy with
// z = u + i v): Cholesky only
reparamError dirichletSolve(const Eigen::SparseMatrix<std::complex<double> > &L,
                            const std::vector<char> &isFixed,
                            Eigen::MatrixXcd &x);

// The same for the maps' layout: uv holds 2 values per node, u and v being
// the two right-hand sides
reparamError dirichletSolve(const Eigen::SparseMatrix<double> &L,
                            const std::vector<char> &isFixed,
                            std::vector<double> &uv,
                            sparseFactorization factorization);

} // namespace reparam

#endif
