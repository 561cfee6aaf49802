// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <Eigen/SparseCholesky>
#include <Spectra/SymEigsSolver.h>
#include "generalizedEigenSolve.h"

namespace reparam {

namespace {

  // B is singular, so Spectra's shift-invert mode (B positive definite)
  // does not apply. Instead, with K = L - shift B positive definite,
  //   L x = lambda B x  <=>  B x = nu K x,  nu = 1 / (lambda - shift),
  // i.e. the largest nu of B x = nu K x. With the factor P K P^T = L D L^H,
  // y = D^1/2 L^H P x turns it into the standard Hermitian problem
  //   M y = nu y,  M = D^-1/2 L^-1 P B P^T L^-H D^-1/2,
  // one back substitution per product and Euclidean inner products (Spectra's
  // regular inverse mode needs a product with K for each of them, measured
  // 40 % of the time). The known null vectors of L (eigenvectors with the
  // largest nu) are projected out of every product: the projection commutes
  // with M, so the largest nu left is the one we want.
  //
  // Spectra is real: it sees the complex unknowns as interleaved real pairs
  // (re, im), the layout of std::complex, in which a Hermitian matrix is
  // real symmetric. Every eigenvalue is then double (y and i y).

  typedef Eigen::SparseMatrix<std::complex<double> > complexSparse;

  Eigen::Map<const Eigen::VectorXcd> asComplex(const double *x, Eigen::Index n)
  {
    return Eigen::Map<const Eigen::VectorXcd>(
      reinterpret_cast<const std::complex<double> *>(x), n);
  }
  Eigen::Map<Eigen::VectorXcd> asComplex(double *x, Eigen::Index n)
  {
    return Eigen::Map<Eigen::VectorXcd>(
      reinterpret_cast<std::complex<double> *>(x), n);
  }

  struct reducedOperator {
    typedef double Scalar;
    const Eigen::SimplicialLDLT<complexSparse> &factor;
    const Eigen::VectorXd &B;
    Eigen::VectorXd invSqrtD;
    Eigen::MatrixXcd kernel; // in y, orthonormal columns
    mutable Eigen::VectorXcd work, coefficients;
    mutable int solves = 0;
    Eigen::Index rows() const { return 2 * B.size(); }
    Eigen::Index cols() const { return 2 * B.size(); }
    // In the real view the kernel is spanned by its columns q and by i q:
    // their complex span, hence complex (not real) inner products
    // (no temporary of the vector's size: a product per Lanczos step)
    template <class Vector> void project(Vector &&y) const
    {
      coefficients.noalias() = kernel.adjoint() * y;
      y.noalias() -= kernel * coefficients;
    }
    // y = D^1/2 L^H P x
    Eigen::VectorXcd reduce(const Eigen::VectorXcd &x) const
    {
      Eigen::VectorXcd y = factor.permutationP() * x;
      y = factor.matrixU() * y;
      return y.cwiseQuotient(invSqrtD.cast<std::complex<double> >());
    }
    // x = P^T L^-H D^-1/2 y
    Eigen::VectorXcd expand(const Eigen::VectorXcd &y) const
    {
      Eigen::VectorXcd x = invSqrtD.cwiseProduct(y);
      factor.matrixU().solveInPlace(x);
      return factor.permutationPinv() * x;
    }
    void perform_op(const double *x, double *y) const
    {
      const Eigen::Index n = B.size();
      work = invSqrtD.cwiseProduct(asComplex(x, n));
      factor.matrixU().solveInPlace(work);
      // P B P^T is diagonal: B permuted
      for(Eigen::Index i = 0; i < n; i++)
        work[i] *= B[factor.permutationPinv().indices()[i]];
      factor.matrixL().solveInPlace(work);
      Eigen::Map<Eigen::VectorXcd> out = asComplex(y, n);
      out = invSqrtD.cwiseProduct(work);
      project(out);
      solves++;
    }
  };

} // namespace

eigenpairResult smallestGeneralizedEigenpair(
  const Eigen::SparseMatrix<std::complex<double> > &L, const Eigen::VectorXd &B,
  const Eigen::MatrixXcd &kernel, double shift)
{
  eigenpairResult result;
  const Eigen::Index n = L.rows();
  if(n < 3 || kernel.cols() >= n - 1) {
    result.error =
      reparamFailure(reparamStatus::solverFailed, "eigenproblem too small");
    return result;
  }
  complexSparse K = L;
  for(Eigen::Index i = 0; i < n; i++)
    if(B[i] != 0.) K.coeffRef(i, i) -= shift * B[i];
  Eigen::SimplicialLDLT<complexSparse> factor(K);
  if(factor.info() != Eigen::Success ||
     !(factor.vectorD().real().minCoeff() > 0.)) {
    result.error = reparamFailure(reparamStatus::solverFailed,
                                  "factorization of the shifted matrix");
    return result;
  }
  reducedOperator op{factor, B,
                     factor.vectorD().real().cwiseSqrt().cwiseInverse(),
                     Eigen::MatrixXcd(n, kernel.cols())};
  // Orthonormal basis of the kernel's image in y (Gram-Schmidt)
  for(Eigen::Index c = 0; c < kernel.cols(); c++) {
    Eigen::VectorXcd q = op.reduce(kernel.col(c));
    for(Eigen::Index d = 0; d < c; d++)
      q -= op.kernel.col(d) * op.kernel.col(d).dot(q);
    double norm = q.norm();
    if(!(norm > 0.)) {
      result.error =
        reparamFailure(reparamStatus::solverFailed, "dependent kernel vectors");
      return result;
    }
    op.kernel.col(c) = q / norm;
  }

  // Each eigenvalue is double in the real view: ask for 2 so that the pair
  // does not slow the convergence, keep the first. 10 Lanczos vectors: 18
  // back substitutions on a 100k-triangle patch, against 17 with 16, 21 with
  // 20 and 31 with 30, for the memory of 10.
  const Eigen::Index nev = 2;
  const Eigen::Index ncv = std::min<Eigen::Index>(2 * (n - kernel.cols()), 10);
  Spectra::SymEigsSolver<reducedOperator> solver(op, nev, ncv);
  // A deterministic start (Spectra's default is random): the same patch
  // gives the same map
  Eigen::VectorXd start = Eigen::VectorXd::LinSpaced(2 * n, 1., 2.);
  for(Eigen::Index i = 0; i < 2 * n; i += 2) start[i] = -start[i];
  op.project(asComplex(start.data(), n));
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
  Eigen::VectorXd y = solver.eigenvectors().col(0);
  result.x = op.expand(asComplex(y.data(), n));
  double xBx = result.x.dot(B.cwiseProduct(result.x)).real();
  if(!(xBx > 0.) || !result.x.allFinite()) {
    result.error = reparamFailure(reparamStatus::solverFailed,
                                  "eigenvector without boundary component");
    return result;
  }
  result.x /= std::sqrt(xBx);
  return result;
}
} // namespace reparam

