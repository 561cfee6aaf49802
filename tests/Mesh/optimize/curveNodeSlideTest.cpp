// Reparam - a curve's node slid along its input polyline

#include <array>
#include <cmath>
#include <vector>
#include <gtest/gtest.h>
#include "curveNodeSlide.h"
#include "triangleQuality.h"

using namespace reparam;

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

TEST(curveNodeSlide, forTheMeanTheRingEvensOut)
{
  // two triangles above the axis, both good, one better than the other:
  // the node goes where their kappa summed is highest (under the apex)
  // without lowering the worst
  const SPoint3 apex(2., 1.7, 0.);
  const curveNodeRing ring = ringOnAxis(
    1.6, {{{SPoint3(4., 0., 0.), apex}}, {{apex, SPoint3(0., 0., 0.)}}});
  double meanBefore = 0.;
  for(const auto &o : ring.opposite)
    meanBefore += triangleKappa(SPoint3(1.6, 0., 0.), o[0], o[1]) / 2.;
  const curveNodeSlide s = slideCurveNodeForMean(ring);
  EXPECT_NEAR(s.t, 2., 1e-12);
  EXPECT_GE(s.worstAfter, s.worstBefore);
  double meanAfter = 0.;
  for(const auto &o : ring.opposite)
    meanAfter += triangleKappa(SPoint3(2., 0., 0.), o[0], o[1]) / 2.;
  EXPECT_GT(meanAfter, meanBefore + 1e-3);
  // already there: it stays
  EXPECT_EQ(slideCurveNodeForMean(ringOnAxis(2., ring.opposite)).t, 2.);
}

TEST(curveNodeSlide, forTheMeanNoPoorTriangleGetsWorse)
{
  // three triangles over the node at 3, kappa 0.02, 0.43 and 0.76: their
  // sum is highest with the node at 1.5, where the second falls to 0.36;
  // with the target at 0.6 that is refused, and the node stops at 2, where
  // every triangle below 0.6 gains
  const SPoint3 far(0.51, 1.43, 0.), near(0.59, 0.58, 0.);
  const curveNodeRing ring = ringOnAxis(3., {{{SPoint3(4., 0., 0.), near}},
                                             {{near, far}},
                                             {{far, SPoint3(0., 0., 0.)}}});
  const curveNodeSlide loose = slideCurveNodeForMean(ring, 0.);
  const curveNodeSlide strict = slideCurveNodeForMean(ring, 0.6);
  EXPECT_NEAR(loose.t, 1.5, 1e-12);
  EXPECT_NEAR(strict.t, 2., 1e-12);
  const SPoint3 from = pointOnPolyline(ring.polyline, 3.);
  const SPoint3 to = pointOnPolyline(ring.polyline, strict.t);
  const SPoint3 looseTo = pointOnPolyline(ring.polyline, loose.t);
  EXPECT_LT(triangleKappa(looseTo, near, far), triangleKappa(from, near, far));
  for(const auto &o : ring.opposite) {
    const double before = triangleKappa(from, o[0], o[1]);
    if(before < 0.6) EXPECT_GE(triangleKappa(to, o[0], o[1]), before);
  }
  EXPECT_GE(strict.worstAfter, strict.worstBefore);
}

namespace {

  // The x axis from 0 to 4 with a tip at x = 2 (y = 1.5): a node at 1.5
  // (half way up) between neighbours at 0 and 4 cuts it off by a third of
  // its chord
  curveNodeRing ringUnderATip(const std::vector<std::array<SPoint3, 2> > &o)
  {
    curveNodeRing ring;
    ring.polyline = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                     SPoint3(2., 1.5, 0.), SPoint3(3., 0., 0.),
                     SPoint3(4., 0., 0.)};
    ring.t = 1.5;
    ring.before = 0.;
    ring.after = 4.;
    ring.opposite = o;
    return ring;
  }

} // namespace

TEST(curveNodeSlide, forFidelityANodeGoesOntoTheTipItsChordsCutOff)
{
  // triangles below the curve, apex at (2, -1.7): on the tip the node's
  // triangles are good, and the chords follow the polyline
  const SPoint3 apex(2., -1.7, 0.);
  const curveNodeRing ring = ringUnderATip(
    {{{apex, SPoint3(4., 0., 0.)}}, {{SPoint3(0., 0., 0.), apex}}});
  const curveNodeSlide s = slideCurveNodeToFarthest(ring);
  EXPECT_EQ(s.t, 2.);
  EXPECT_GE(s.worstAfter, std::min(s.worstBefore, 0.5));
  // on the tip nothing is cut off any more: it stays
  curveNodeRing there = ring;
  there.t = 2.;
  EXPECT_EQ(slideCurveNodeToFarthest(there).t, 2.);
  // a tip a fortieth of the chord off is left (share 0.25)
  curveNodeRing low = ring;
  low.polyline[2] = SPoint3(2., 0.1, 0.);
  EXPECT_EQ(slideCurveNodeToFarthest(low).t, 1.5);
}

TEST(curveNodeSlide, forFidelityNoTriangleBelowTheFloor)
{
  // apex at (0.6, -1.6): the worst triangle 0.76 now, 0.61 on the tip;
  // refused with the floor at 0.7, taken with 0.5
  const SPoint3 apex(0.6, -1.6, 0.);
  const curveNodeRing ring = ringUnderATip(
    {{{apex, SPoint3(4., 0., 0.)}}, {{SPoint3(0., 0., 0.), apex}}});
  const curveNodeSlide strict = slideCurveNodeToFarthest(ring, 0.25, 0.7, 1.5);
  EXPECT_EQ(strict.t, 1.5);
  EXPECT_GT(strict.worstBefore, 0.75);
  const curveNodeSlide loose = slideCurveNodeToFarthest(ring, 0.25, 0.5, 1.5);
  EXPECT_EQ(loose.t, 2.);
  EXPECT_LT(loose.worstAfter, 0.7);
  EXPECT_GE(loose.worstAfter, 0.5);
}
