// Reparam - the Fiedler vector against the path's and the grid's closed forms

#include <cmath>
#include <gtest/gtest.h>
#include "fiedlerVector.h"

using namespace reparam;

namespace {

  // A grid of nx x ny nodes (ny = 1: a path), unit weights; node i + nx j
  void grid(int nx, int ny, std::vector<std::array<int, 2> > &edges,
            std::vector<double> &weights)
  {
    for(int j = 0; j < ny; j++)
      for(int i = 0; i < nx; i++) {
        if(i + 1 < nx) edges.push_back({{i + nx * j, i + 1 + nx * j}});
        if(j + 1 < ny) edges.push_back({{i + nx * j, i + nx * (j + 1)}});
      }
    weights.assign(edges.size(), 1.);
  }

  // |cosine| between the vector found and cos(pi (i + 1/2) / nx) along the
  // grid's long side, the closed form of its Fiedler vector
  double agreement(const fiedlerResult &f, int nx, int ny)
  {
    double dot = 0., norm = 0.;
    for(int j = 0; j < ny; j++)
      for(int i = 0; i < nx; i++) {
        const double c = std::cos(M_PI * (i + 0.5) / nx);
        dot += c * f.x[i + nx * j];
        norm += c * c;
      }
    return std::fabs(dot) / (std::sqrt(norm) * f.x.norm());
  }

} // namespace

TEST(fiedlerVector, aPathGetsItsCosine)
{
  // 50 nodes (a basis of 20 vectors) and 6000 (8)
  for(int n : {50, 6000}) {
    std::vector<std::array<int, 2> > edges;
    std::vector<double> weights;
    grid(n, 1, edges, weights);
    const fiedlerResult f = fiedlerVector(n, edges, weights);
    ASSERT_TRUE(f.error.ok());
    const double lambda = 2. - 2. * std::cos(M_PI / n);
    EXPECT_NEAR(f.lambda / lambda, 1., 1e-6) << n;
    EXPECT_GT(agreement(f, n, 1), 1. - 1e-6) << n;
    EXPECT_NEAR(f.x.norm(), 1., 1e-9);
    EXPECT_NEAR(f.x.sum(), 0., 1e-9);
  }
}

TEST(fiedlerVector, aLongGridVariesAlongItsLength)
{
  // 120 x 60 nodes: lambda2 along the length stands apart from lambda3
  // (across and along: both 2 - 2 cos(pi / 60))
  std::vector<std::array<int, 2> > edges;
  std::vector<double> weights;
  grid(120, 60, edges, weights);
  const fiedlerResult f = fiedlerVector(120 * 60, edges, weights);
  ASSERT_TRUE(f.error.ok());
  EXPECT_NEAR(f.lambda, 2. - 2. * std::cos(M_PI / 120), 1e-7);
  EXPECT_GT(agreement(f, 120, 60), 1. - 1e-6);
}

TEST(fiedlerVector, twoNodesAndFewer)
{
  const fiedlerResult two = fiedlerVector(2, {{{0, 1}}}, {1.});
  ASSERT_TRUE(two.error.ok());
  EXPECT_NEAR(two.x[0], -two.x[1], 1e-15);
  EXPECT_FALSE(fiedlerVector(1, {}, {}).error.ok());
}
