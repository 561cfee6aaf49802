// Reparam - a curve's node slid along its input polyline

#include <array>
#include <cmath>
#include <vector>
#include <gtest/gtest.h>
#include "curveNodeSlide.h"
#include "triangleQuality.h"

namespace {

  // the x axis from 0 to 4, a node every unit (parameter = x)
  std::vector<SPoint3> axis()
  {
    std::vector<SPoint3> p;
    for(int i = 0; i <= 4; i++) p.push_back(SPoint3(i, 0., 0.));
    return p;
  }

  // a node at t on the axis between neighbours at 0 and 4, with the
  // triangles (node, a, b) of `opposite`
  curveNodeRing ringOnAxis(double t,
                           const std::vector<std::array<SPoint3, 2> > &opposite)
  {
    curveNodeRing ring;
    ring.polyline = axis();
    ring.t = t;
    ring.before = 0.;
    ring.after = 4.;
    ring.opposite = opposite;
    return ring;
  }

  double signedArea(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c)
  {
    return (b.x() - a.x()) * (c.y() - a.y()) -
           (b.y() - a.y()) * (c.x() - a.x());
  }

} // namespace

TEST(curveNodeSlide, pointOnPolylineIsLinearBetweenItsNodes)
{
  const std::vector<SPoint3> p = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                                  SPoint3(1., 2., 0.)};
  EXPECT_NEAR(pointOnPolyline(p, 0.25).x(), 0.25, 1e-15);
  EXPECT_NEAR(pointOnPolyline(p, 1.5).y(), 1., 1e-15);
  EXPECT_NEAR(pointOnPolyline(p, 1.5).x(), 1., 1e-15);
  EXPECT_NEAR(pointOnPolyline(p, 7.).y(), 2., 1e-15); // clamped
  EXPECT_NEAR(pointOnPolyline(p, -1.).x(), 0., 1e-15);
}

TEST(curveNodeSlide, nodeGoesWhereItsTrianglesAreBest)
{
  // neighbours at 0 and 4, an apex above 2: with the node at 1 one
  // triangle is thin; at 2 both are right triangles of kappa 0.82
  const SPoint3 apex(2., 1.7, 0.);
  const curveNodeRing ring = ringOnAxis(
    1., {{{SPoint3(4., 0., 0.), apex}}, {{apex, SPoint3(0., 0., 0.)}}});
  const curveNodeSlide s = slideCurveNode(ring);
  EXPECT_NEAR(s.t, 2., 1e-12);
  EXPECT_LT(s.worstBefore, 0.75);
  EXPECT_GT(s.worstAfter, 0.8);
  EXPECT_NEAR(s.worstAfter,
              triangleKappa(SPoint3(2., 0., 0.), SPoint3(4., 0., 0.), apex),
              1e-12);
}

TEST(curveNodeSlide, nodeOnACornerOfTheCurveStays)
{
  // the curve turns by 90 degrees at the node (parameter 1): anywhere else
  // a chord to a neighbour cuts the corner off, however much better the
  // triangles would be
  curveNodeRing ring;
  ring.polyline = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                   SPoint3(1., 1., 0.)};
  ring.t = 1.;
  ring.before = 0.;
  ring.after = 2.;
  ring.opposite = {{{SPoint3(1., 1., 0.), SPoint3(0.2, 0.9, 0.)}},
                   {{SPoint3(0.2, 0.9, 0.), SPoint3(0., 0., 0.)}}};
  const curveNodeSlide s = slideCurveNode(ring);
  EXPECT_EQ(s.t, 1.);
  EXPECT_EQ(s.worstAfter, s.worstBefore);
}

TEST(curveNodeSlide, noTriangleTurnsOver)
{
  // one triangle, thin with the node at 1; past x = 3 it turns over (and
  // its kappa would be higher): the node goes no farther than where it
  // still faces the same way
  const SPoint3 a(3., 1., 0.), b(2.2, 0.2, 0.);
  const curveNodeRing ring = ringOnAxis(1., {{{a, b}}});
  const double before = signedArea(SPoint3(1., 0., 0.), a, b);
  const curveNodeSlide s = slideCurveNode(ring);
  EXPECT_GT(s.worstAfter, s.worstBefore);
  EXPECT_GT(signedArea(pointOnPolyline(ring.polyline, s.t), a, b) * before, 0.);
}

TEST(curveNodeSlide, aNodeAHairFromItsNeighbourMovesAway)
{
  // the node 0.1 from its neighbour at 4: a sliver towards the apex; half
  // way it is gone
  const SPoint3 apex(2., 1.7, 0.);
  const curveNodeRing ring = ringOnAxis(
    3.9, {{{SPoint3(4., 0., 0.), apex}}, {{apex, SPoint3(0., 0., 0.)}}});
  const curveNodeSlide s = slideCurveNode(ring);
  EXPECT_LT(s.worstBefore, 0.1);
  EXPECT_GT(s.worstAfter, 0.8);
  EXPECT_GT(s.t, 1.);
  EXPECT_LT(s.t, 3.);
}

TEST(curveNodeSlide, chordsFollowTheirPolyline)
{
  // an L: 10 unit steps along x, then 10 along y; a node at the corner (10)
  // between neighbours at 5 and 15
  std::vector<SPoint3> p;
  for(int i = 0; i <= 10; i++) p.push_back(SPoint3(i, 0, 0));
  for(int i = 1; i <= 10; i++) p.push_back(SPoint3(10, i, 0));
  EXPECT_TRUE(chordsFollowPolyline(p, 10., 10., 5., 15., 0.05));
  // off the corner, a chord cuts it
  EXPECT_FALSE(chordsFollowPolyline(p, 10., 11., 5., 15., 0.05));
  // along the straight part, anywhere
  EXPECT_TRUE(chordsFollowPolyline(p, 3., 4., 1., 8., 0.05));
  // no worse than where it was: allowed
  EXPECT_TRUE(chordsFollowPolyline(p, 11., 11., 5., 15., 0.05));
}
