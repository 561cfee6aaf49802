// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <string>
#include <type_traits>
#include <Eigen/SparseCholesky>
#include <Eigen/KLUSupport>
#include <Eigen/UmfPackSupport>
#include "dirichletSolve.h"

namespace reparam {

namespace {

  template <class Solver, class Scalar>
  reparamError factorAndSolve(
    Solver &solver, const Eigen::SparseMatrix<Scalar> &Lff,
    const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> &rhs,
    Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> &x)
  {
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

  template <class Scalar>
  reparamError
  solveFree(const Eigen::SparseMatrix<Scalar> &L,
            const std::vector<char> &isFixed,
            Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> &x,
            sparseFactorization factorization)
  {
    typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> denseMatrix;
    const int n = (int)L.rows();
    const int k = (int)x.cols();
    std::vector<int> freeIndex(n, -1);
    int nFree = 0;
    for(int i = 0; i < n; i++)
      if(!isFixed[i]) freeIndex[i] = nFree++;
    if(nFree == 0) return reparamError();

    // Eliminate the fixed unknowns: L_ff x_f = -L_fb x_b. Built column by
    // column from L's compressed columns, whose rows stay sorted: no triplets.
    denseMatrix rhs = denseMatrix::Zero(nFree, k);
    std::vector<int> outer(1, 0);
    std::vector<int> inner;
    std::vector<Scalar> values;
    inner.reserve(L.nonZeros());
    values.reserve(L.nonZeros());
    for(int col = 0; col < n; col++) {
      const bool fixedColumn = (freeIndex[col] < 0);
      for(typename Eigen::SparseMatrix<Scalar>::InnerIterator it(L, col); it;
          ++it) {
        int row = freeIndex[it.row()];
        if(row < 0) continue;
        if(fixedColumn)
          rhs.row(row) -= it.value() * x.row(col);
        else {
          inner.push_back(row);
          values.push_back(it.value());
        }
      }
      if(!fixedColumn) outer.push_back((int)inner.size());
    }
    Eigen::SparseMatrix<Scalar> Lff =
      Eigen::Map<const Eigen::SparseMatrix<Scalar> >(
        nFree, nFree, (int)inner.size(), outer.data(), inner.data(),
        values.data());

    denseMatrix xFree;
    reparamError err;
    if(factorization == sparseFactorization::cholesky) {
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<Scalar> > solver;
      err = factorAndSolve(solver, Lff, rhs, xFree);
    }
    else if constexpr(std::is_same<Scalar, double>::value) {
      // KLU (SuiteSparse): AMD ordering, left-looking LU. Measured fastest of
      // the sparse LUs on these matrices (symmetric pattern, diagonally
      // dominant rows) up to about 10k unknowns; above, UMFPACK's
      // multifrontal BLAS kernels win (bench/README.md#maps-and-solvers).
      if(nFree <= 10000) {
        Eigen::KLU<Eigen::SparseMatrix<double> > solver;
        err = factorAndSolve(solver, Lff, rhs, xFree);
      }
      else {
        Eigen::UmfPackLU<Eigen::SparseMatrix<double> > solver;
        err = factorAndSolve(solver, Lff, rhs, xFree);
      }
    }
    else
      return reparamFailure(reparamStatus::solverFailed,
                            "no LU factorization of complex matrices");
    if(!err.ok()) return err;
    for(int i = 0; i < n; i++)
      if(freeIndex[i] >= 0) x.row(i) = xFree.row(freeIndex[i]);
    return reparamError();
  }

} // namespace

reparamError dirichletSolve(const Eigen::SparseMatrix<double> &L,
                            const std::vector<char> &isFixed,
                            Eigen::MatrixXd &x,
                            sparseFactorization factorization)
{
  return solveFree(L, isFixed, x, factorization);
}

reparamError dirichletSolve(const Eigen::SparseMatrix<std::complex<double> > &L,
                            const std::vector<char> &isFixed,
                            Eigen::MatrixXcd &x)
{
  return solveFree(L, isFixed, x, sparseFactorization::cholesky);
}

reparamError dirichletSolve(const Eigen::SparseMatrix<double> &L,
                            const std::vector<char> &isFixed,
                            std::vector<double> &uv,
                            sparseFactorization factorization)
{
  // uv is the row-major n x 2 matrix of the two right-hand sides
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> > m(
    uv.data(), (Eigen::Index)(uv.size() / 2), 2);
  Eigen::MatrixXd x = m;
  reparamError err = dirichletSolve(L, isFixed, x, factorization);
  if(err.ok()) m = x;
  return err;
}
} // namespace reparam

