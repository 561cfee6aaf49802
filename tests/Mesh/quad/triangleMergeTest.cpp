// Reparam - pairs of triangles merged into quadrangles: two halves of a
// square make it, locked edges and poor quadrangles are left, each triangle
// goes into one quadrangle at most, best first

#include <algorithm>
#include <gtest/gtest.h>
#include "quadQuality.h"
#include "surfaceMesh.h"
#include "testPatches.h"
#include "triangleMerge.h"

using namespace reparam;

namespace {

  // the unit square's corners (0, 1, 2, 3 counterclockwise) and a fifth
  // point right of it at (2, y)
  surfaceMesh squareAndPoint(double y)
  {
    surfaceMesh m;
    m.points = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.), SPoint3(1., 1., 0.),
                SPoint3(0., 1., 0.), SPoint3(2., y, 0.)};
    m.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    return m;
  }

} // namespace

TEST(triangleMerge, twoHalvesOfASquareMakeIt)
{
  const surfaceMesh m = squareAndPoint(0.5);
  const std::vector<triangleMerge> merges = triangleMerges(m, {}, 0.3);
  ASSERT_EQ(merges.size(), 1u);
  EXPECT_NEAR(merges[0].eta, 1., 1e-12);
  // the four corners once each, counterclockwise like the triangles
  std::array<int, 4> sorted = merges[0].quadrangle;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::array<int, 4>{{0, 1, 2, 3}}));
  EXPECT_NEAR(quadAreaXY(m, merges[0].quadrangle), 1., 1e-12);
}

TEST(triangleMerge, lockedEdgesAndPoorQuadranglesAreLeft)
{
  const surfaceMesh m = squareAndPoint(0.5);
  EXPECT_TRUE(triangleMerges(m, {{0, 2}}, 0.3).empty());
  // a thin pair: (0, 1, 4) and (1, 0, 5) with 4 and 5 close to the edge
  surfaceMesh thin;
  thin.points = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                 SPoint3(0.5, 0.1, 0.), SPoint3(0.5, -0.1, 0.)};
  thin.triangles = {{{0, 1, 2}}, {{1, 0, 3}}};
  const std::vector<triangleMerge> loose = triangleMerges(thin, {}, 0.);
  ASSERT_EQ(loose.size(), 1u);
  EXPECT_LT(loose[0].eta, 0.3);
  EXPECT_TRUE(triangleMerges(thin, {}, 0.3).empty());
}

TEST(triangleMerge, eachTriangleOnceBestFirst)
{
  // three triangles in a row: (0, 1, 2), (0, 2, 3) the square's halves and
  // (1, 4, 2) right of it; the square's pair (eta 1) beats the other
  surfaceMesh m = squareAndPoint(0.5);
  m.triangles.push_back({{1, 4, 2}});
  const std::vector<triangleMerge> merges = triangleMerges(m, {}, 0.);
  ASSERT_EQ(merges.size(), 1u);
  EXPECT_EQ(std::min(merges[0].first, merges[0].second), 0);
  EXPECT_EQ(std::max(merges[0].first, merges[0].second), 1);
  // inconsistently oriented neighbours are no pair
  surfaceMesh flipped = squareAndPoint(0.5);
  flipped.triangles[1] = {{0, 3, 2}};
  EXPECT_TRUE(triangleMerges(flipped, {}, 0.).empty());
}
