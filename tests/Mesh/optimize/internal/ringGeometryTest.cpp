// Reparam - the small geometry of a ring the optimizer's steps share: the
// ring's normal as its triangles turn, centroids, longest edges, corners
// with a node moved

#include <cmath>
#include <gtest/gtest.h>
#include "ringGeometry.h"

using namespace reparam;
using namespace reparam::optimizeInternal;

namespace {

  // A regular hexagon of radius 1 in z = 0 around node 6 at the origin,
  // its six triangles (6, k, k + 1) counterclockwise seen from +z
  void hexagonFan(std::vector<SPoint3> &points,
                  std::vector<std::array<int, 3> > &triangles)
  {
    points.clear();
    triangles.clear();
    for(int k = 0; k < 6; k++)
      points.push_back(
        SPoint3(std::cos(k * M_PI / 3.), std::sin(k * M_PI / 3.), 0.));
    points.push_back(SPoint3(0., 0., 0.));
    for(int k = 0; k < 6; k++) triangles.push_back({{6, k, (k + 1) % 6}});
  }

} // namespace

TEST(optimizeRingGeometry, ringNormalIsTwiceTheAreaAlongTheTurn)
{
  std::vector<SPoint3> x;
  std::vector<std::array<int, 3> > t;
  hexagonFan(x, t);
  // six equilateral triangles of side 1: twice their area is 3 sqrt(3)
  const SVector3 n = ringNormal(x, t, {0, 1, 2, 3, 4, 5});
  EXPECT_NEAR(n.x(), 0., 1e-15);
  EXPECT_NEAR(n.y(), 0., 1e-15);
  EXPECT_NEAR(n.z(), 3. * std::sqrt(3.), 1e-12);
  // only the triangles asked, and as they turn
  EXPECT_NEAR(ringNormal(x, t, {0, 3}).z(), std::sqrt(3.), 1e-12);
  for(auto &c : t) std::swap(c[1], c[2]);
  EXPECT_NEAR(ringNormal(x, t, {0, 1, 2, 3, 4, 5}).z(), -3. * std::sqrt(3.),
              1e-12);
  // an empty ring has none
  EXPECT_EQ(norm(ringNormal(x, t, {})), 0.);
}

TEST(optimizeRingGeometry, ringNormalOfATentIsItsAxis)
{
  // the hexagon's center lifted to z = 1: the slopes cancel across, what is
  // left is twice the area seen from above, 3 sqrt(3), along z
  std::vector<SPoint3> x;
  std::vector<std::array<int, 3> > t;
  hexagonFan(x, t);
  x[6] = SPoint3(0., 0., 1.);
  const SVector3 n = ringNormal(x, t, {0, 1, 2, 3, 4, 5});
  EXPECT_NEAR(n.x(), 0., 1e-12);
  EXPECT_NEAR(n.y(), 0., 1e-12);
  EXPECT_NEAR(n.z(), 3. * std::sqrt(3.), 1e-12);
}

TEST(optimizeRingGeometry, centroidLongestEdgeAndCornersWith)
{
  const SPoint3 a(0., 0., 0.), b(3., 0., 0.), c(0., 3., 3.);
  const SPoint3 g = centroidOf(a, b, c);
  EXPECT_EQ(g.x(), 1.);
  EXPECT_EQ(g.y(), 1.);
  EXPECT_EQ(g.z(), 1.);
  // a 3-4-5 right triangle
  EXPECT_EQ(
    longestEdge(SPoint3(0., 0., 0.), SPoint3(3., 0., 0.), SPoint3(0., 4., 0.)),
    5.);
  const std::vector<SPoint3> points = {a, b, c, SPoint3(7., 7., 7.)};
  SPoint3 corners[3];
  cornersWith({{3, 1, 0}}, 1, SPoint3(-1., -2., -3.), points, corners);
  EXPECT_EQ(corners[0].x(), 7.);
  EXPECT_EQ(corners[1].y(), -2.); // node 1 moved
  EXPECT_EQ(corners[2].distance(a), 0.);
}
