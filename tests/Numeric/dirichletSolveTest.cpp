// Reparam - the shared Dirichlet solve against a dense solution

#include <complex>
#include <Eigen/Dense>
#include <gtest/gtest.h>
#include "dirichletSolve.h"

using namespace reparam;

namespace {

  // A 1D chain Laplacian (SPD after elimination) and an unsymmetric variant
  Eigen::SparseMatrix<double> chain(int n, double skew)
  {
    std::vector<Eigen::Triplet<double> > e;
    for(int i = 0; i < n; i++) {
      double left = (i > 0) ? 1. + skew * i : 0., right = (i < n - 1) ? 1. : 0.;
      if(i > 0) e.emplace_back(i, i - 1, -left);
      if(i < n - 1) e.emplace_back(i, i + 1, -right);
      e.emplace_back(i, i, left + right);
    }
    Eigen::SparseMatrix<double> L(n, n);
    L.setFromTriplets(e.begin(), e.end());
    return L;
  }

  void expectMatchesDense(const Eigen::SparseMatrix<double> &L,
                          sparseFactorization f)
  {
    const int n = L.rows();
    std::vector<char> fixed(n, 0);
    fixed[0] = fixed[n - 1] = 1;
    std::vector<double> uv(2 * n, 0.);
    uv[0] = 1.;
    uv[1] = -2.;
    uv[2 * (n - 1)] = 3.;
    uv[2 * (n - 1) + 1] = 5.;
    ASSERT_TRUE(dirichletSolve(L, fixed, uv, f).ok());
    // dense reference: the full system with identity rows for fixed nodes
    Eigen::MatrixXd M = Eigen::MatrixXd(L);
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, 2);
    for(int i : {0, n - 1}) {
      M.row(i).setZero();
      M(i, i) = 1.;
      b(i, 0) = uv[2 * i];
      b(i, 1) = uv[2 * i + 1];
    }
    Eigen::MatrixXd x = M.fullPivLu().solve(b);
    for(int i = 0; i < n; i++) {
      EXPECT_NEAR(uv[2 * i], x(i, 0), 1e-12);
      EXPECT_NEAR(uv[2 * i + 1], x(i, 1), 1e-12);
    }
  }

} // namespace

TEST(dirichletSolve, choleskyMatchesDense)
{
  expectMatchesDense(chain(20, 0.), sparseFactorization::cholesky);
  // the harmonic solution of a uniform chain is linear
  std::vector<char> fixed(11, 0);
  fixed[0] = fixed[10] = 1;
  std::vector<double> uv(22, 0.);
  uv[20] = 10.;
  ASSERT_TRUE(
    dirichletSolve(chain(11, 0.), fixed, uv, sparseFactorization::cholesky)
      .ok());
  for(int i = 0; i < 11; i++) EXPECT_NEAR(uv[2 * i], i, 1e-12);
}

TEST(dirichletSolve, luMatchesDenseOnUnsymmetric)
{
  expectMatchesDense(chain(30, 0.3), sparseFactorization::lu);
}

TEST(dirichletSolve, singularSystemFails)
{
  // two disconnected nodes, one fixed: the free one has an empty row
  Eigen::SparseMatrix<double> L(3, 3);
  L.insert(0, 0) = 1.;
  L.insert(0, 1) = -1.;
  L.insert(1, 0) = -1.;
  L.insert(1, 1) = 1.;
  std::vector<char> fixed = {1, 0, 0};
  std::vector<double> uv(6, 1.);
  reparamError err = dirichletSolve(L, fixed, uv, sparseFactorization::lu);
  EXPECT_EQ(err.status, reparamStatus::solverFailed);
}

TEST(dirichletSolve, hermitianMatchesDense)
{
  // The chain plus i S, S antisymmetric (the conformal energy's shape), two
  // ends fixed at complex values
  typedef std::complex<double> complexd;
  const int n = 12;
  Eigen::SparseMatrix<complexd> L = chain(n, 0.).cast<complexd>();
  for(int i = 0; i + 1 < n; i++) {
    L.coeffRef(i, i + 1) += complexd(0., 0.3 + 0.01 * i);
    L.coeffRef(i + 1, i) -= complexd(0., 0.3 + 0.01 * i);
  }
  std::vector<char> fixed(n, 0);
  fixed[0] = fixed[n - 1] = 1;
  Eigen::MatrixXcd z = Eigen::MatrixXcd::Zero(n, 1);
  z(0, 0) = complexd(-1., 0.5);
  z(n - 1, 0) = complexd(2., -1.);
  Eigen::MatrixXcd zFixed = z;
  ASSERT_TRUE(dirichletSolve(L, fixed, z).ok());
  EXPECT_EQ(z(0, 0), zFixed(0, 0));
  EXPECT_EQ(z(n - 1, 0), zFixed(n - 1, 0));
  // the free rows of L z vanish
  Eigen::MatrixXcd r = Eigen::MatrixXcd(L) * z;
  for(int i = 1; i + 1 < n; i++) EXPECT_LT(std::abs(r(i, 0)), 1e-12);
  // and i S couples u and v: not the linear solution of the real chain
  complexd linear =
    zFixed(0, 0) + (zFixed(n - 1, 0) - zFixed(0, 0)) * (n / 2 / double(n - 1));
  EXPECT_GT(std::abs(z(n / 2, 0) - linear), 1e-3);
}

TEST(dirichletSolve, luAboveTenThousandUnknowns)
{
  // The size where the LU changes (UMFPACK): the free rows of L x vanish
  const int n = 12000;
  Eigen::SparseMatrix<double> L = chain(n, 1e-4);
  std::vector<char> fixed(n, 0);
  fixed[0] = fixed[n - 1] = 1;
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n, 2);
  x(0, 0) = 1.;
  x(n - 1, 1) = 3.;
  ASSERT_TRUE(dirichletSolve(L, fixed, x, sparseFactorization::lu).ok());
  Eigen::MatrixXd r = L * x;
  EXPECT_LT(r.block(1, 0, n - 2, 2).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(x(0, 0), 1.);
  EXPECT_EQ(x(n - 1, 1), 3.);
  EXPECT_GT(x(n / 2, 0), 0.);
  EXPECT_LE(x(n / 2, 0), 1. + 1e-12); // the maximum principle
}
