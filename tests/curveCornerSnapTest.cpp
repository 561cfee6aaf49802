// Reparam - 1D nodes of a discrete curve moved onto the input's corners

#include <cmath>
#include <gtest/gtest.h>
#include "curveCornerSnap.h"

namespace {

  // an L: 10 unit steps along x, then 10 along y; its corner is node 10
  std::vector<SPoint3> lShape()
  {
    std::vector<SPoint3> p;
    for(int i = 0; i <= 10; i++) p.push_back(SPoint3(i, 0, 0));
    for(int i = 1; i <= 10; i++) p.push_back(SPoint3(10, i, 0));
    return p;
  }

} // namespace

TEST(curveCornerSnap, cornerBecomesANodeAndPiecesKeepTheirSize)
{
  // segments of 4.5 (the last 2) across the corner at 10: the piece before
  // it had 2.2 segments, the one after 2.8, now 2 and 3 even ones
  std::vector<double> snapped =
    snapCurveNodesToCorners(lShape(), {0., 4.5, 9., 13.5, 18., 20.});
  std::vector<double> expected = {0., 5., 10., 40. / 3., 50. / 3., 20.};
  ASSERT_EQ(snapped.size(), expected.size());
  for(std::size_t k = 0; k < expected.size(); k++)
    EXPECT_NEAR(snapped[k], expected[k], 1e-12) << k;

  // 1.9 and 2.1 segments: 2 and 2
  snapped = snapCurveNodesToCorners(lShape(), {0., 5., 10.8, 16., 20.});
  expected = {0., 5., 10., 15., 20.};
  ASSERT_EQ(snapped.size(), expected.size());
  for(std::size_t k = 0; k < expected.size(); k++)
    EXPECT_NEAR(snapped[k], expected[k], 1e-12) << k;
}

TEST(curveCornerSnap, cornerNearAnEndIsLeftOut)
{
  // a corner at node 1, less than half a segment (5.25) from the curve's
  // end node: a node already sits about there
  std::vector<SPoint3> p = {SPoint3(0, 0, 0)};
  for(int i = 0; i <= 20; i++) p.push_back(SPoint3(1, i, 0));
  std::vector<double> params = {0., 5., 10., 15., 21.};
  EXPECT_EQ(snapCurveNodesToCorners(p, params), params);
}

TEST(curveCornerSnap, zigZagAtTheInputScaleIsNoCorner)
{
  // a straight line of input edges zig-zagging by +-0.3 across it (turning
  // by 62 degrees at every node), meshed with segments of 10 edges: seen at
  // half a segment it does not turn
  std::vector<SPoint3> p;
  for(int i = 0; i <= 40; i++) p.push_back(SPoint3(i, i % 2 ? 0.3 : -0.3, 0));
  const std::vector<double> params = {0., 10.5, 20.5, 30.5, 40.};
  EXPECT_EQ(snapCurveNodesToCorners(p, params), params);
}

TEST(curveCornerSnap, smoothCurveIsLeftAlone)
{
  // a half circle of 200 input nodes, meshed with 9 even segments: moving a
  // node onto an input node never halves a segment's sagitta
  std::vector<SPoint3> p;
  for(int i = 0; i < 200; i++) {
    const double a = M_PI * i / 199.;
    p.push_back(SPoint3(std::cos(a), std::sin(a), 0.));
  }
  std::vector<double> params;
  for(int k = 0; k <= 9; k++) params.push_back(199. * k / 9.);
  EXPECT_EQ(snapCurveNodesToCorners(p, params), params);
}

TEST(curveCornerSnap, onlyCornersOf40DegreesOrMoreAttract)
{
  // a polyline turning by 30 degrees at node 10, then by 45 at node 30
  std::vector<SPoint3> p;
  SPoint3 x(0, 0, 0);
  double heading = 0.;
  for(int i = 0; i <= 50; i++) {
    p.push_back(x);
    if(i == 10) heading += 30. * M_PI / 180.;
    if(i == 30) heading += 45. * M_PI / 180.;
    x = SPoint3(x.x() + std::cos(heading), x.y() + std::sin(heading), 0.);
  }
  const std::vector<double> params = {0., 8.5, 17., 25.5, 34., 42.5, 50.};
  std::vector<double> snapped = snapCurveNodesToCorners(p, params);
  // the 45 degree corner at 30 a node, 3.5 and 2.5 segments before and
  // after it: 4 and 2 (rounded half away from zero); the 30 degree turn at
  // 10 is no corner
  const std::vector<double> expected = {0., 7.5, 15., 22.5, 30., 40., 50.};
  ASSERT_EQ(snapped.size(), expected.size());
  for(std::size_t k = 0; k < expected.size(); k++)
    EXPECT_NEAR(snapped[k], expected[k], 1e-9) << k;
}
