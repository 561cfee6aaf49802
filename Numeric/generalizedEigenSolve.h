// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The eigenproblem of the spectral conformal map (Eq. 29): L x = lambda B x
// with L Hermitian positive semi-definite (the conformal energy over
// z = u + i v) and B real diagonal, positive on some unknowns only
// (singular). Spectra's Lanczos on a sparse Cholesky factor.

#ifndef GENERALIZED_EIGEN_SOLVE_H
#define GENERALIZED_EIGEN_SOLVE_H

#include <complex>
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include "reparamStatus.h"

namespace reparam {

struct eigenpairResult {
  reparamError error;
  Eigen::VectorXcd x; // B-normalized: x^H B x = 1
  double lambda = 0.;
  int iterations = 0; // Lanczos restarts
  int solves = 0; // back substitutions with the factor
};

// The eigenpair of smallest lambda among the vectors B-orthogonal to the
// columns of `kernel`, which must span known null vectors of L with
// kernel^H B kernel invertible (the translations of a map). shift < 0 makes
// L - shift B definite; it should be of the order of the eigenvalue sought.
eigenpairResult smallestGeneralizedEigenpair(
  const Eigen::SparseMatrix<std::complex<double> > &L, const Eigen::VectorXd &B,
  const Eigen::MatrixXcd &kernel, double shift);

} // namespace reparam

#endif
