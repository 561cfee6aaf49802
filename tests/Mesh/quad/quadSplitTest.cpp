// Reparam - quadrangles split into two triangles: a quadrangle with a flat
// corner splits along the diagonal from that corner, a fair one or one whose
// triangles are no better stays, the worst comes first

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include "quadQuality.h"
#include "quadSplit.h"
#include "surfaceMesh.h"
#include "triangleQuality.h"

using namespace reparam;

namespace {

  // (0, 0), (1, 0), (2, h), (1, 1) counterclockwise: a corner of nearly
  // 180 degrees at (1, 0) for a small h
  surfaceMesh flatCorner(double h)
  {
    surfaceMesh m;
    m.points = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.), SPoint3(2., h, 0.),
                SPoint3(1., 1., 0.)};
    m.quadrangles = {{{0, 1, 2, 3}}};
    return m;
  }

  double signedArea(const surfaceMesh &m, const std::array<int, 3> &t)
  {
    const SPoint3 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) -
                  (c.x() - a.x()) * (b.y() - a.y()));
  }

} // namespace

TEST(quadSplit, aFlatCornerSplitsAlongItsDiagonal)
{
  const surfaceMesh m = flatCorner(0.1);
  const std::vector<quadSplit> splits = quadSplits(m, 0.3, 0.3);
  ASSERT_EQ(splits.size(), 1u);
  const quadSplit &s = splits[0];
  EXPECT_EQ(s.quadrangle, 0);
  // a corner of 174 degrees: eta 1 - 84 / 90
  EXPECT_NEAR(
    s.eta, quadEta(m.points[0], m.points[1], m.points[2], m.points[3]), 1e-12);
  EXPECT_LT(s.eta, 0.1);
  // the diagonal from the flat corner (1) to the opposite one (3)
  for(const std::array<int, 3> &t : s.triangles) {
    EXPECT_NE(std::find(t.begin(), t.end(), 1), t.end());
    EXPECT_NE(std::find(t.begin(), t.end(), 3), t.end());
    EXPECT_GT(signedArea(m, t), 0.); // the quadrangle's orientation
  }
  EXPECT_NEAR(signedArea(m, s.triangles[0]) + signedArea(m, s.triangles[1]), 1.,
              1e-12);
  // (0, 1, 3) is the right isosceles one (0.828), (1, 2, 3) is worse
  const double k0 = triangleKappa(m.points[0], m.points[1], m.points[3]);
  const double k1 = triangleKappa(m.points[1], m.points[2], m.points[3]);
  EXPECT_NEAR(k0, 0.8284, 1e-4);
  EXPECT_NEAR(s.kappa, std::min(k0, k1), 1e-12);
  EXPECT_GT(s.kappa, 0.6);
}

TEST(quadSplit, aFairQuadrangleOrNoBetterTrianglesStay)
{
  surfaceMesh square = flatCorner(0.);
  square.points[2] = SPoint3(1., 1., 0.);
  square.points[3] = SPoint3(0., 1., 0.);
  EXPECT_TRUE(quadSplits(square, 0.3, 0.3).empty());
  // a sliver: every triangle of it is thin as well
  surfaceMesh sliver;
  sliver.points = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                   SPoint3(2., 0.05, 0.), SPoint3(1., 0.1, 0.)};
  sliver.quadrangles = {{{0, 1, 2, 3}}};
  EXPECT_LT(quadEta(sliver.points[0], sliver.points[1], sliver.points[2],
                    sliver.points[3]),
            0.3);
  EXPECT_TRUE(quadSplits(sliver, 0.3, 0.3).empty());
  // the bound on the triangles is the caller's
  EXPECT_EQ(quadSplits(sliver, 0.3, 0.).size(), 1u);
}

TEST(quadSplit, theWorstFirst)
{
  surfaceMesh m = flatCorner(0.1);
  // a second quadrangle on the first one's side (2, 3)
  m.points.push_back(SPoint3(3., 0.25, 0.));
  m.points.push_back(SPoint3(2., 1., 0.));
  m.quadrangles.push_back({{2, 4, 5, 3}});
  const double eta0 =
    quadEta(m.points[0], m.points[1], m.points[2], m.points[3]);
  const double eta1 =
    quadEta(m.points[2], m.points[4], m.points[5], m.points[3]);
  const std::vector<quadSplit> splits = quadSplits(m, 0.95, 0.3);
  ASSERT_EQ(splits.size(), 2u);
  EXPECT_EQ(splits[0].quadrangle, eta0 < eta1 ? 0 : 1);
  EXPECT_LE(splits[0].eta, splits[1].eta);
}

TEST(quadSplit, aSharpCornerSplitsIntoTrianglesBetterThanIt)
{
  // a corner of 13 degrees at (0, 0), as where two curves meet at a model
  // point: no quadrangle there is fair, its triangles from the other
  // diagonal are better than it though below 0.3
  const double a = 13. * M_PI / 180.;
  surfaceMesh m;
  m.points = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.), SPoint3(1., 0.2, 0.),
              SPoint3(0.6 * std::cos(a), 0.6 * std::sin(a), 0.)};
  m.quadrangles = {{{0, 1, 2, 3}}};
  const double eta =
    quadEta(m.points[0], m.points[1], m.points[2], m.points[3]);
  EXPECT_NEAR(eta, 0.046, 1e-3);
  EXPECT_TRUE(quadSplits(m, 0.3, 0.3).empty());
  const std::vector<quadSplit> splits = quadSplits(m, 0.3, 0.);
  ASSERT_EQ(splits.size(), 1u);
  // along the diagonal (1, 3): the corner's triangle (0, 1, 3) of kappa
  // 0.137, the other 0.711
  EXPECT_NEAR(splits[0].kappa, 0.137, 1e-3);
  EXPECT_GT(splits[0].kappa, eta);
  for(const std::array<int, 3> &t : splits[0].triangles) {
    EXPECT_NE(std::find(t.begin(), t.end(), 1), t.end());
    EXPECT_NE(std::find(t.begin(), t.end(), 3), t.end());
    EXPECT_GT(signedArea(m, t), 0.);
  }
}
