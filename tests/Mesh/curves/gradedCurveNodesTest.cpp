// Reparam - the nodes of a curve's 1D mesh spread by a varying size

#include <cmath>
#include <gtest/gtest.h>
#include "gradedCurveNodes.h"

using namespace reparam;

namespace {

  // a straight polyline from 0 to 1 along x, with n uneven pieces
  std::vector<SPoint3> line(int n)
  {
    std::vector<SPoint3> p;
    for(int i = 0; i <= n; i++)
      p.push_back(SPoint3(std::pow(i / (double)n, 1.5), 0., 0.));
    return p;
  }

  // x at parameter t of the polyline
  double xAt(const std::vector<SPoint3> &p, double t)
  {
    const int i = std::min((int)t, (int)p.size() - 2);
    return p[i].x() + (t - i) * (p[i + 1].x() - p[i].x());
  }

} // namespace

TEST(gradedCurveNodes, evenSizeGivesEvenSegments)
{
  const std::vector<SPoint3> p = line(7);
  const std::vector<double> t = gradedCurveParameters(
    p, [](const SPoint3 &, double) { return 0.1; }, 1);
  ASSERT_EQ(t.size(), 11u); // 10 segments
  EXPECT_EQ(t.front(), 0.);
  EXPECT_EQ(t.back(), 7.);
  for(std::size_t i = 0; i + 1 < t.size(); i++)
    EXPECT_NEAR(xAt(p, t[i + 1]) - xAt(p, t[i]), 0.1, 1e-9) << i;
}

TEST(gradedCurveNodes, segmentsFollowAGrowingSize)
{
  // 0.01 at x = 0, growing by half the distance, up to 0.1
  const std::vector<SPoint3> p = line(5);
  auto size = [](const SPoint3 &x, double) {
    return std::min(0.1, 0.01 + 0.5 * x.x());
  };
  const std::vector<double> t = gradedCurveParameters(p, size, 1);
  ASSERT_GT(t.size(), 12u);
  for(std::size_t i = 0; i + 1 < t.size(); i++) {
    const double a = xAt(p, t[i]), b = xAt(p, t[i + 1]);
    // each segment about the size at its middle
    EXPECT_NEAR((b - a) / size(SPoint3(0.5 * (a + b), 0., 0.), 0.), 1., 0.25)
      << i;
  }
}

TEST(gradedCurveNodes, atLeastTheFewestSegments)
{
  const std::vector<SPoint3> p = line(1);
  const std::vector<double> t = gradedCurveParameters(
    p, [](const SPoint3 &, double) { return 10.; }, 2);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_NEAR(t[1], 0.5, 1e-9);
}

TEST(gradedCurveNodes, evenForBlossom)
{
  // 9 segments of 1/9; a curve of a face Blossom recombines gets 10 (Gmsh's
  // rule: its boundary must have an even number of segments)
  const std::vector<SPoint3> p = line(7);
  auto ninth = [](const SPoint3 &, double) { return 1. / 9.; };
  EXPECT_EQ(gradedCurveParameters(p, ninth, 1).size(), 10u);
  const std::vector<double> t = gradedCurveParameters(p, ninth, 1, true);
  ASSERT_EQ(t.size(), 11u);
  for(std::size_t i = 0; i + 1 < t.size(); i++)
    EXPECT_NEAR(xAt(p, t[i + 1]) - xAt(p, t[i]), 0.1, 1e-9) << i;
  // and at least 3 becomes 4
  EXPECT_EQ(gradedCurveParameters(
              line(1), [](const SPoint3 &, double) { return 10.; }, 3, true)
              .size(),
            5u);
}
