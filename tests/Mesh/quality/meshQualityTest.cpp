// Reparam - quadrangle quality eta (Eq. 4) and efficiency index tau (Eq. 5-6)

#include <cmath>
#include <gtest/gtest.h>
#include "efficiencyIndex.h"
#include "quadQuality.h"
#include "surfaceMesh.h"
#include "testPatches.h"

using namespace reparam;

TEST(quadQuality, squareIsOneAndRhombusIsItsAngle)
{
  EXPECT_NEAR(quadEta(SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(1, 1, 0),
                      SPoint3(0, 1, 0)),
              1., 1e-15);
  // a rectangle anywhere in space
  EXPECT_NEAR(quadEta(SPoint3(1, 1, 1), SPoint3(1, 3, 1), SPoint3(1, 3, 2),
                      SPoint3(1, 1, 2)),
              1., 1e-15);
  // rhombus of angles 60 and 120 degrees: 1 - (2 / pi)(pi / 6) = 2 / 3
  double c = std::cos(M_PI / 3), s = std::sin(M_PI / 3);
  EXPECT_NEAR(quadEta(SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(1 + c, s, 0),
                      SPoint3(c, s, 0)),
              2. / 3., 1e-14);
}

TEST(quadQuality, flatOrReflexCornerIsZero)
{
  // a triangle with a node in the middle of an edge: a 180 degree corner
  EXPECT_EQ(quadEta(SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(2, 0, 0),
                    SPoint3(1, 1, 0)),
            0.);
  // a dart: the corner at (1, 0.3) is reflex
  EXPECT_EQ(quadEta(SPoint3(0, 0, 0), SPoint3(1, 0.3, 0), SPoint3(2, 0, 0),
                    SPoint3(1, 1, 0)),
            0.);
}

TEST(quadQuality, worstAndMeanOfAMesh)
{
  // a 2 x 2 grid of squares, then one corner node pulled so that the
  // quadrangle at it (and only that one) loses its right angles
  surfaceMesh m = quadGrid(2);
  double worst, mean;
  etaOfQuadrangles(m, worst, mean);
  EXPECT_NEAR(worst, 1., 1e-12);
  EXPECT_NEAR(mean, 1., 1e-12);
  m.points[0] = SPoint3(-0.5, 0., 0.);
  const std::array<int, 4> &q = m.quadrangles[0];
  const double pulled =
    quadEta(m.points[q[0]], m.points[q[1]], m.points[q[2]], m.points[q[3]]);
  etaOfQuadrangles(m, worst, mean);
  EXPECT_LT(pulled, 0.8);
  EXPECT_NEAR(worst, pulled, 1e-12);
  EXPECT_NEAR(mean, (3. + pulled) / 4., 1e-12);
  // no quadrangle: 1 and 1
  etaOfQuadrangles(surfaceMesh(), worst, mean);
  EXPECT_EQ(worst, 1.);
  EXPECT_EQ(mean, 1.);
}

TEST(efficiencyIndex, unitEdgesGiveHundredPercent)
{
  testTriangulation t = rectangleGrid(4, 4, 4, 4);
  // the grid's sides have length 1; its diagonals sqrt 2
  std::vector<std::array<int, 2> > sides;
  for(const auto &e : uniqueEdges(t.triangles, {}))
    if(std::fabs(t.points[e[0]].distance(t.points[e[1]]) - 1.) < 1e-12)
      sides.push_back(e);
  EXPECT_EQ(sides.size(), 2u * 4u * 5u);
  auto unit = [](const SPoint3 &) { return 1.; };
  EXPECT_NEAR(efficiencyIndex(t.points, sides, unit), 100., 1e-12);
  // 16 cells, 40 sides and 16 diagonals
  std::vector<std::array<int, 2> > all = uniqueEdges(t.triangles, {});
  EXPECT_EQ(all.size(), 56u);
  // sides d = 0, diagonals d = 1 / sqrt2 - 1
  EXPECT_NEAR(efficiencyIndex(t.points, all, unit),
              100. * std::exp(16. * (1. / std::sqrt(2.) - 1.) / 56.), 1e-12);
}

TEST(efficiencyIndex, paperValuesOfD)
{
  std::vector<SPoint3> p = {SPoint3(0, 0, 0), SPoint3(2, 0, 0),
                            SPoint3(0, 0.5, 0)};
  auto unit = [](const SPoint3 &) { return 1.; };
  // l = 2: d = 1/2 - 1; l = 0.5: d = 0.5 - 1; both -1/2
  EXPECT_NEAR(efficiencyIndex(p, {{{0, 1}}}, unit), 100. * std::exp(-0.5),
              1e-12);
  EXPECT_NEAR(efficiencyIndex(p, {{{0, 2}}}, unit), 100. * std::exp(-0.5),
              1e-12);
  EXPECT_NEAR(efficiencyIndex(p, {{{0, 1}}, {{0, 2}}}, unit),
              100. * std::exp(-0.5), 1e-12);
  EXPECT_EQ(efficiencyIndex(p, {}, unit), 0.);
}

TEST(efficiencyIndex, lengthInAVaryingSizeField)
{
  // size 1 + x along [0, 1]: l = ln 2 (3-point Gauss: 0.693122)
  auto linear = [](const SPoint3 &x) { return 1. + x.x(); };
  EXPECT_NEAR(adimensionalLength(SPoint3(0, 0, 0), SPoint3(1, 0, 0), linear),
              std::log(2.), 3e-5);
  // exact for a size whose inverse is a polynomial of degree <= 5
  auto inverseQuadratic = [](const SPoint3 &x) {
    return 1. / (1. + x.x() * x.x());
  };
  EXPECT_NEAR(adimensionalLength(SPoint3(0, 0, 0),
                                 SPoint3(0, 0, 0) + SPoint3(2, 0, 0),
                                 inverseQuadratic),
              2. + 8. / 3., 1e-12);
}
