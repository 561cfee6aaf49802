// Reparam - the generalized eigensolver of the spectral map

#include <vector>
#include <Eigen/Dense>
#include <gtest/gtest.h>
#include "generalizedEigenSolve.h"

TEST(generalizedEigenSolve, matchesADenseSolveWithSingularB)
{
  // A path graph's Laplacian (kernel: the constants), B on 4 of 7 unknowns
  const int n = 7;
  std::vector<Eigen::Triplet<double> > entries;
  for(int i = 0; i + 1 < n; i++) {
    double w = 1. + 0.3 * i;
    entries.emplace_back(i, i, w);
    entries.emplace_back(i + 1, i + 1, w);
    entries.emplace_back(i, i + 1, -w);
    entries.emplace_back(i + 1, i, -w);
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd B = Eigen::VectorXd::Zero(n);
  const int onB[4] = {0, 2, 5, 6};
  for(int i : onB) B[i] = 1.;
  Eigen::MatrixXd kernel = Eigen::MatrixXd::Ones(n, 1);

  eigenpairResult r = smallestGeneralizedEigenpair(L, B, kernel, -0.05);
  ASSERT_TRUE(r.error.ok()) << r.error.what();

  // Independently: the finite eigenvalues are those of the Schur complement
  // of L on the unknowns where B = 1 (B is the identity there)
  Eigen::MatrixXd D = Eigen::MatrixXd(L);
  const int offB[3] = {1, 3, 4};
  Eigen::MatrixXd Lbb(4, 4), Lbi(4, 3), Lii(3, 3);
  for(int a = 0; a < 4; a++) {
    for(int b = 0; b < 4; b++) Lbb(a, b) = D(onB[a], onB[b]);
    for(int b = 0; b < 3; b++) Lbi(a, b) = D(onB[a], offB[b]);
  }
  for(int a = 0; a < 3; a++)
    for(int b = 0; b < 3; b++) Lii(a, b) = D(offB[a], offB[b]);
  Eigen::MatrixXd S = Lbb - Lbi * Lii.inverse() * Lbi.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense(S);
  // eigenvalue 0 is the constants, excluded: the next one is ours
  EXPECT_NEAR(dense.eigenvalues()[0], 0., 1e-12);
  EXPECT_NEAR(r.lambda, dense.eigenvalues()[1], 1e-10);
  // an eigenvector, B-normalized and B-orthogonal to the constants
  Eigen::VectorXd residual = L * r.x - r.lambda * B.cwiseProduct(r.x);
  EXPECT_LT(residual.norm(), 1e-9);
  EXPECT_NEAR(r.x.dot(B.cwiseProduct(r.x)), 1., 1e-12);
  EXPECT_NEAR(B.dot(r.x), 0., 1e-10);
}

TEST(generalizedEigenSolve, rejectsProblemsTooSmall)
{
  Eigen::SparseMatrix<double> L(2, 2);
  L.setIdentity();
  eigenpairResult r = smallestGeneralizedEigenpair(
    L, Eigen::VectorXd::Ones(2), Eigen::MatrixXd::Ones(2, 1), -1.);
  EXPECT_FALSE(r.error.ok());
}
