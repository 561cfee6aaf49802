// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <Eigen/SparseCholesky>
#include <Spectra/SymGEigsSolver.h>
#include "generalizedEigenSolve.h"

namespace {

  // B is singular, so Spectra's shift-invert mode (B positive definite)
  // does not apply. Instead, with K = L - shift B positive definite,
  //   L x = lambda B x  <=>  B x = nu K x,  nu = 1 / (lambda - shift),
  // i.e. the largest nu of B x = nu K x, Spectra's regular inverse mode with
  // K in the role of its "B". The known null vectors of L (eigenvectors with
  // the largest nu) are projected out of every K^-1 product: the projector
  // is K-orthogonal and commutes with K^-1 B, so the operator stays
  // self-adjoint and the largest nu left is the one we want.

  // y = B x
  struct diagonalProduct {
    typedef double Scalar;
    const Eigen::VectorXd &B;
    Eigen::Index rows() const { return B.size(); }
    Eigen::Index cols() const { return B.size(); }
    void perform_op(const double *x, double *y) const
    {
      Eigen::Map<Eigen::VectorXd>(y, B.size()) =
        B.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(x, B.size()));
    }
  };

  // solve: y = P K^-1 x; perform_op: y = K x
  struct projectedInverse {
    typedef double Scalar;
    const Eigen::SparseMatrix<double> &K;
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > &factor;
    const Eigen::MatrixXd &kernel; // columns K-orthonormal
    Eigen::MatrixXd Kkernel; // K * kernel
    mutable int solves = 0;
    Eigen::Index rows() const { return K.rows(); }
    Eigen::Index cols() const { return K.rows(); }
    void solve(const double *x, double *y) const
    {
      Eigen::Map<Eigen::VectorXd> out(y, K.rows());
      out = factor.solve(Eigen::Map<const Eigen::VectorXd>(x, K.rows()));
      out -= kernel * (Kkernel.transpose() * out);
      solves++;
    }
    void perform_op(const double *x, double *y) const
    {
      Eigen::Map<Eigen::VectorXd>(y, K.rows()) =
        K * Eigen::Map<const Eigen::VectorXd>(x, K.rows());
    }
  };

} // namespace

eigenpairResult smallestGeneralizedEigenpair(const Eigen::SparseMatrix<double> &L,
                                             const Eigen::VectorXd &B,
                                             const Eigen::MatrixXd &kernel,
                                             double shift)
{
  eigenpairResult result;
  const Eigen::Index n = L.rows();
  if(n < 3 || kernel.cols() >= n - 1) {
    result.error = reparamFailure(reparamStatus::solverFailed,
                                  "eigenproblem too small");
    return result;
  }
  Eigen::SparseMatrix<double> K = L;
  for(Eigen::Index i = 0; i < n; i++)
    if(B[i] != 0.) K.coeffRef(i, i) -= shift * B[i];
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > factor(K);
  if(factor.info() != Eigen::Success) {
    result.error = reparamFailure(reparamStatus::solverFailed,
                                  "factorization of the shifted matrix");
    return result;
  }
  // K-orthonormal basis of the kernel (Gram-Schmidt in the K inner product)
  Eigen::MatrixXd Q = kernel;
  for(Eigen::Index c = 0; c < Q.cols(); c++) {
    for(Eigen::Index d = 0; d < c; d++)
      Q.col(c) -= Q.col(d) * Q.col(d).dot(K * Q.col(c));
    double norm2 = Q.col(c).dot(K * Q.col(c));
    if(!(norm2 > 0.)) {
      result.error = reparamFailure(reparamStatus::solverFailed,
                                    "dependent kernel vectors");
      return result;
    }
    Q.col(c) /= std::sqrt(norm2);
  }
  projectedInverse op{K, factor, Q, K * Q};
  diagonalProduct bop{B};

  // The eigenvalues of a conformal energy come in pairs (a map and its
  // rotation by 90 degrees): ask for 2 so that the pair does not slow the
  // convergence, keep the first
  const Eigen::Index nev = 2;
  const Eigen::Index ncv = std::min<Eigen::Index>(n - kernel.cols(), 20);
  Spectra::SymGEigsSolver<diagonalProduct, projectedInverse,
                          Spectra::GEigsMode::RegularInverse>
    solver(bop, op, nev, ncv);
  // A deterministic start (Spectra's default is random): the same patch
  // gives the same map
  Eigen::VectorXd start = Eigen::VectorXd::LinSpaced(n, 1., 2.);
  for(Eigen::Index i = 0; i < n; i += 2) start[i] = -start[i];
  start -= Q * (op.Kkernel.transpose() * start);
  solver.init(start.data());
  solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-10);
  result.iterations = (int)solver.num_iterations();
  result.solves = op.solves;
  if(solver.info() != Spectra::CompInfo::Successful) {
    result.error = reparamFailure(reparamStatus::solverFailed,
                                  "Lanczos iterations did not converge");
    return result;
  }
  const double nu = solver.eigenvalues()[0];
  result.lambda = shift + 1. / nu;
  result.x = solver.eigenvectors().col(0);
  // Spectra normalizes in the K inner product: renormalize for B
  double xBx = result.x.dot(B.cwiseProduct(result.x));
  if(!(xBx > 0.) || !result.x.allFinite()) {
    result.error = reparamFailure(reparamStatus::solverFailed,
                                  "eigenvector without boundary component");
    return result;
  }
  result.x /= std::sqrt(xBx);
  return result;
}
