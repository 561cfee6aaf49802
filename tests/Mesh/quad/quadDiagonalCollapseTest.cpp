// Reparam - diagonal collapses of quadrangles: a grid with one node split
// in two across a diamond gets its grid back (the diamond collapsed, the
// two nodes merged where the grid had its node, every inner node of valence
// 4, every quadrangle a square); a fixed node, or a diamond of another
// part than its nodes, stays

#include <algorithm>
#include <gtest/gtest.h>
#include "quadDiagonalCollapse.h"
#include "quadEdgeRotation.h"
#include "quadQuality.h"
#include "surfaceMesh.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  const int n = 4;

  int point(int i, int j) { return i + (n + 1) * j; }
  int quadrangle(int i, int j) { return i + n * j; }

  // The 4 x 4 grid with its middle node (2, 2) split into two nodes 0.3 to
  // its west (a new point, last) and east (the old one), joined through a
  // diamond with the nodes north and south: both of valence 3, north and
  // south of valence 5. The diamond is the last quadrangle
  surfaceMesh gridWithASplitNode(int &west, int &east)
  {
    surfaceMesh m = quadGrid(n);
    east = point(2, 2);
    west = (int)m.points.size();
    m.points.push_back(SPoint3(1.7, 2., 0.));
    m.points[east] = SPoint3(2.3, 2., 0.);
    for(int q : {quadrangle(1, 1), quadrangle(1, 2)})
      std::replace(m.quadrangles[q].begin(), m.quadrangles[q].end(), east,
                   west);
    m.quadrangles.push_back({{point(2, 1), east, point(2, 3), west}});
    return m;
  }

  double worstEta(const surfaceMesh &m, const std::vector<bool> &removed)
  {
    double worst = 1.;
    for(std::size_t i = 0; i < m.quadrangles.size(); i++) {
      if(removed[i]) continue;
      const auto &q = m.quadrangles[i];
      worst = std::min(worst, quadEta(m.points[q[0]], m.points[q[1]],
                                      m.points[q[2]], m.points[q[3]]));
    }
    return worst;
  }

} // namespace

TEST(quadDiagonalCollapse, aSplitNodeIsMergedBack)
{
  int west, east;
  surfaceMesh m = gridWithASplitNode(west, east);
  const std::vector<int> owner(m.points.size(), 0);
  std::vector<int> mergedInto;
  std::vector<bool> removed;
  const quadCollapseResult r =
    collapseQuadDiagonals(m, {}, owner, mergedInto, removed);
  EXPECT_EQ(r.collapses, 1u);
  EXPECT_EQ(r.irregularBefore, 4u); // two of valence 3, two of 5
  EXPECT_EQ(r.irregularAfter, 0u);
  EXPECT_TRUE(removed.back());
  EXPECT_EQ(std::count(removed.begin(), removed.end(), true), 1);
  EXPECT_EQ(mergedInto[west], east);
  EXPECT_EQ(std::count_if(mergedInto.begin(), mergedInto.end(),
                          [](int i) { return i >= 0; }),
            1);
  EXPECT_NEAR(m.points[east].x(), 2., 1e-12);
  EXPECT_NEAR(m.points[east].y(), 2., 1e-12);
  EXPECT_NEAR(worstEta(m, removed), 1., 1e-12);
  for(std::size_t i = 0; i + 1 < m.quadrangles.size(); i++)
    EXPECT_EQ(
      std::count(m.quadrangles[i].begin(), m.quadrangles[i].end(), west), 0);
}

TEST(quadDiagonalCollapse, aFixedNodeOrAnotherPartStays)
{
  int west, east;
  surfaceMesh m = gridWithASplitNode(west, east);
  std::vector<int> owner(m.points.size(), 0);
  owner[west] = -1; // a curve's node
  std::vector<int> mergedInto;
  std::vector<bool> removed;
  const quadCollapseResult fixed =
    collapseQuadDiagonals(m, {}, owner, mergedInto, removed);
  EXPECT_EQ(mergedInto[west], -1);
  EXPECT_FALSE(removed.back()); // the diamond has the fixed node
  // elsewhere the look-ahead: a collapse that alone changes nothing, then
  // one next to it that gains
  EXPECT_EQ(fixed.collapses, 2u);
  EXPECT_LT(fixed.irregularAfter, fixed.irregularBefore);

  m = gridWithASplitNode(west, east);
  owner[west] = 0;
  std::vector<int> part(m.quadrangles.size(), 0);
  part.back() = 1; // the diamond is another face's
  collapseQuadDiagonals(m, part, owner, mergedInto, removed);
  EXPECT_FALSE(removed.back());
  EXPECT_EQ(mergedInto[west], -1);
}

TEST(quadDiagonalCollapse, noGainNoCollapse)
{
  // a regular grid: every collapse would make it less regular
  surfaceMesh m = quadGrid(n);
  const std::vector<int> owner(m.points.size(), 0);
  std::vector<int> mergedInto;
  std::vector<bool> removed;
  const quadCollapseResult r =
    collapseQuadDiagonals(m, {}, owner, mergedInto, removed);
  EXPECT_EQ(r.collapses, 0u);
  EXPECT_EQ(r.irregularBefore, 0u);
}
