// Reparam - the generalized eigensolver of the spectral map

#include <vector>
#include <Eigen/Dense>
#include <gtest/gtest.h>
#include "generalizedEigenSolve.h"

using namespace reparam;

TEST(generalizedEigenSolve, matchesADenseSolveWithSingularB)
{
  // A path graph's Laplacian plus i S, S antisymmetric along a cycle through
  // the 4 unknowns where B = 1 (like the conformal energy's boundary term,
  // it keeps the constants in the kernel)
  typedef std::complex<double> complexd;
  const int n = 7;
  std::vector<Eigen::Triplet<complexd> > entries;
  for(int i = 0; i + 1 < n; i++) {
    double w = 1. + 0.3 * i;
    entries.emplace_back(i, i, w);
    entries.emplace_back(i + 1, i + 1, w);
    entries.emplace_back(i, i + 1, -w);
    entries.emplace_back(i + 1, i, -w);
  }
  const int onB[4] = {0, 2, 5, 6};
  for(int k = 0; k < 4; k++) {
    int a = onB[k], b = onB[(k + 1) % 4];
    entries.emplace_back(a, b, complexd(0., 0.4));
    entries.emplace_back(b, a, complexd(0., -0.4));
  }
  Eigen::SparseMatrix<complexd> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd B = Eigen::VectorXd::Zero(n);
  for(int i : onB) B[i] = 1.;
  Eigen::MatrixXcd kernel = Eigen::MatrixXcd::Ones(n, 1);
  EXPECT_LT((L * kernel).norm(), 1e-14);

  eigenpairResult r = smallestGeneralizedEigenpair(L, B, kernel, -0.05);
  ASSERT_TRUE(r.error.ok()) << r.error.what();

  // Independently: the finite eigenvalues are those of the Schur complement
  // of L on the unknowns where B = 1 (B is the identity there)
  Eigen::MatrixXcd D = Eigen::MatrixXcd(L);
  const int offB[3] = {1, 3, 4};
  Eigen::MatrixXcd Lbb(4, 4), Lbi(4, 3), Lii(3, 3);
  for(int a = 0; a < 4; a++) {
    for(int b = 0; b < 4; b++) Lbb(a, b) = D(onB[a], onB[b]);
    for(int b = 0; b < 3; b++) Lbi(a, b) = D(onB[a], offB[b]);
  }
  for(int a = 0; a < 3; a++)
    for(int b = 0; b < 3; b++) Lii(a, b) = D(offB[a], offB[b]);
  Eigen::MatrixXcd S = Lbb - Lbi * Lii.inverse() * Lbi.adjoint();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> dense(S);
  // eigenvalue 0 is the constants, excluded: the next one is ours
  EXPECT_NEAR(dense.eigenvalues()[0], 0., 1e-12);
  EXPECT_GT(dense.eigenvalues()[2] - dense.eigenvalues()[1], 0.1);
  EXPECT_NEAR(r.lambda, dense.eigenvalues()[1], 1e-10);
  // an eigenvector, B-normalized and B-orthogonal to the constants
  Eigen::VectorXcd residual =
    L * r.x - r.lambda * (B.cast<complexd>().cwiseProduct(r.x));
  EXPECT_LT(residual.norm(), 1e-9);
  EXPECT_NEAR(r.x.dot(B.cast<complexd>().cwiseProduct(r.x)).real(), 1., 1e-12);
  EXPECT_NEAR(std::abs(B.cast<complexd>().dot(r.x)), 0., 1e-10);
}

TEST(generalizedEigenSolve, rejectsProblemsTooSmall)
{
  Eigen::SparseMatrix<std::complex<double> > L(2, 2);
  L.setIdentity();
  eigenpairResult r = smallestGeneralizedEigenpair(
    L, Eigen::VectorXd::Ones(2), Eigen::MatrixXcd::Ones(2, 1), -1.);
  EXPECT_FALSE(r.error.ok());
}
