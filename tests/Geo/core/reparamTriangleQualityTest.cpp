// Reparam - the shape quality of Gmsh's triangles

#include <cmath>
#include <gtest/gtest.h>
#include "gmshTestEnvironment.h"
#include "reparamTriangleQuality.h"

using namespace reparam;

TEST(reparamTriangleQuality, minMeanAndShareBelowPointThree)
{
  // equilateral (kappa 1), right isosceles (2 (sqrt 2 - 1)), and a sliver
  testTriangulation t;
  t.points = {SPoint3(0., 0., 0.),
              SPoint3(1., 0., 0.),
              SPoint3(0.5, std::sqrt(3.) / 2., 0.),
              SPoint3(0., 1., 1.),
              SPoint3(1., 1., 1.),
              SPoint3(0., 2., 1.),
              SPoint3(3., 0., 0.),
              SPoint3(5., 0., 0.),
              SPoint3(4., 0.05, 0.)};
  t.triangles = {{{0, 1, 2}}, {{3, 4, 5}}, {{6, 7, 8}}};
  gmshTriangulation g(t);
  const kappaStatistics k = computeKappaStatistics(g.triangles);
  const double right = 2. * (std::sqrt(2.) - 1.);
  const double sliver = triangleKappa(t.points[6], t.points[7], t.points[8]);
  EXPECT_LT(sliver, 0.3);
  EXPECT_EQ(k.triangles, 3u);
  EXPECT_DOUBLE_EQ(k.min, sliver);
  EXPECT_NEAR(k.mean, (1. + right + sliver) / 3., 1e-12);
  EXPECT_DOUBLE_EQ(k.shareBelow03, 1. / 3.);
}

TEST(reparamTriangleQuality, noTriangleGivesZeros)
{
  const kappaStatistics k = computeKappaStatistics({});
  EXPECT_EQ(k.triangles, 0u);
  EXPECT_EQ(k.min, 0.);
  EXPECT_EQ(k.mean, 0.);
  EXPECT_EQ(k.shareBelow03, 0.);
}
