// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <string>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include "dirichletSolve.h"

namespace {

  template <class Solver>
  reparamError factorAndSolve(const Eigen::SparseMatrix<double> &Lff,
                              const Eigen::MatrixXd &rhs, Eigen::MatrixXd &x)
  {
    Solver solver;
    solver.compute(Lff);
    if(solver.info() != Eigen::Success)
      return reparamFailure(reparamStatus::solverFailed,
                            "factorization of " + std::to_string(Lff.rows()) +
                              " unknowns");
    x = solver.solve(rhs);
    if(solver.info() != Eigen::Success || !x.allFinite())
      return reparamFailure(reparamStatus::solverFailed, "back substitution");
    return reparamError();
  }

} // namespace

reparamError dirichletSolve(const Eigen::SparseMatrix<double> &L,
                            const std::vector<char> &isFixed,
                            std::vector<double> &uv,
                            sparseFactorization factorization)
{
  const int n = (int)L.rows();
  std::vector<int> freeIndex(n, -1);
  int nFree = 0;
  for(int i = 0; i < n; i++)
    if(!isFixed[i]) freeIndex[i] = nFree++;
  if(nFree == 0) return reparamError();

  // Eliminate the fixed nodes: L_ff x_f = -L_fb x_b
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(L.nonZeros());
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nFree, 2);
  for(int col = 0; col < L.outerSize(); col++) {
    for(Eigen::SparseMatrix<double>::InnerIterator it(L, col); it; ++it) {
      int row = freeIndex[it.row()];
      if(row < 0) continue;
      int c = freeIndex[it.col()];
      if(c >= 0)
        entries.emplace_back(row, c, it.value());
      else {
        rhs(row, 0) -= it.value() * uv[2 * it.col()];
        rhs(row, 1) -= it.value() * uv[2 * it.col() + 1];
      }
    }
  }
  Eigen::SparseMatrix<double> Lff(nFree, nFree);
  Lff.setFromTriplets(entries.begin(), entries.end());
  Lff.makeCompressed();

  Eigen::MatrixXd x;
  reparamError err =
    (factorization == sparseFactorization::cholesky) ?
      factorAndSolve<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > >(
        Lff, rhs, x) :
      factorAndSolve<Eigen::SparseLU<Eigen::SparseMatrix<double>,
                                     Eigen::COLAMDOrdering<int> > >(Lff, rhs,
                                                                    x);
  if(!err.ok()) return err;
  for(int i = 0; i < n; i++) {
    if(freeIndex[i] < 0) continue;
    uv[2 * i] = x(freeIndex[i], 0);
    uv[2 * i + 1] = x(freeIndex[i], 1);
  }
  return reparamError();
}
