// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Spectra/SymEigsSolver.h>
#include "fiedlerVector.h"

namespace reparam {

namespace {

  // y = P (L + delta I)^-1 P x, P the projection orthogonal to the constant
  // vector (the kernel of L): its largest eigenvalue is 1 / (lambda2 +
  // delta), for the Fiedler vector. delta only makes L definite for the
  // factorization; it shifts every eigenvalue alike and leaves the vectors.
  struct deflatedInverse {
    typedef double Scalar;
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > &factor;
    Eigen::Index n;
    mutable Eigen::VectorXd b; // one right-hand side for every product
    Eigen::Index rows() const { return n; }
    Eigen::Index cols() const { return n; }
    void perform_op(const double *xIn, double *yOut) const
    {
      Eigen::Map<const Eigen::VectorXd> x(xIn, n);
      Eigen::Map<Eigen::VectorXd> y(yOut, n);
      b = x.array() - x.mean();
      y = factor.solve(b);
      y.array() -= y.mean();
    }
  };

} // namespace

fiedlerResult fiedlerVector(int n, const std::vector<std::array<int, 2> > &edges,
                            const std::vector<double> &weights)
{
  fiedlerResult result;
  if(n < 2) {
    result.error = reparamFailure(reparamStatus::emptyPatch, "fewer than 2 nodes");
    return result;
  }
  if(n == 2) { // no Krylov space to speak of
    result.x = Eigen::VectorXd(2);
    result.x << -M_SQRT1_2, M_SQRT1_2;
    return result;
  }
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(4 * edges.size() + n);
  Eigen::VectorXd degree = Eigen::VectorXd::Zero(n);
  for(std::size_t e = 0; e < edges.size(); e++) {
    int i = edges[e][0], j = edges[e][1];
    entries.emplace_back(i, j, -weights[e]);
    entries.emplace_back(j, i, -weights[e]);
    degree[i] += weights[e];
    degree[j] += weights[e];
  }
  const double delta = 1e-8 * degree.mean();
  for(int i = 0; i < n; i++) entries.emplace_back(i, i, degree[i] + delta);
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > factor(L);
  if(factor.info() != Eigen::Success) {
    result.error = reparamFailure(reparamStatus::solverFailed,
                                  "Laplacian factorization");
    return result;
  }
  deflatedInverse op{factor, n, Eigen::VectorXd(n)};
  // Each vector of the basis is a solve with the factor: on large graphs a
  // small basis (1 / lambda2 stands apart from 1 / lambda3). On small ones
  // the solves cost nothing, and where lambda2 is repeated (a tube) the
  // vector found depends on the basis: kept as it was (bench/README.md,
  // "The Fiedler vector's Lanczos basis")
  const int ncv = std::min(n - 1, n > 5000 ? 8 : 20);
  if(ncv < 2) {
    result.error = reparamFailure(reparamStatus::solverFailed, "graph too small");
    return result;
  }
  Spectra::SymEigsSolver<deflatedInverse> solver(op, 1, ncv);
  // A start orthogonal to the constants, not symmetric about the middle
  Eigen::VectorXd start(n);
  for(int i = 0; i < n; i++) start[i] = std::sin(1. + 2.3 * i);
  start.array() -= start.mean();
  solver.init(start.data());
  solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-8);
  if(solver.info() != Spectra::CompInfo::Successful) {
    result.error = reparamFailure(reparamStatus::solverFailed,
                                  "Lanczos did not converge");
    return result;
  }
  result.x = solver.eigenvectors(1).col(0);
  result.lambda = 1. / solver.eigenvalues()[0] - delta;
  return result;
}
} // namespace reparam

