// Reparam - node splits of quadrangles: a grid with a diagonal collapsed
// (a node of valence 6 between two of valence 3) gets its grid back, its
// nodes on the input; a fixed node, a regular grid, or a node on a tip of
// the input stays

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include "closestTriangle.h"
#include "quadEdgeRotation.h"
#include "quadNodeSplit.h"
#include "quadQuality.h"
#include "surfaceMesh.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  const int n = 4;

  int point(int i, int j) { return i + (n + 1) * j; }
  int quadrangle(int i, int j) { return i + n * j; }

  // The 4 x 4 grid with quadrangle (1, 1) collapsed along its diagonal from
  // node (1, 1) to node (2, 2), merged into the first at the diagonal's
  // midpoint (at height z): the merged node of valence 6, nodes (2, 1) and
  // (1, 2) of valence 3
  surfaceMesh gridWithACollapse(double z = 0.)
  {
    surfaceMesh m = quadGrid(n);
    const int kept = point(1, 1), gone = point(2, 2);
    m.points[kept] = SPoint3(1.5, 1.5, z);
    for(auto &q : m.quadrangles) std::replace(q.begin(), q.end(), gone, kept);
    m.quadrangles.erase(m.quadrangles.begin() + quadrangle(1, 1));
    return m;
  }

  // The square [-2, 5]^2 as two triangles, its middle (1.5, 1.5) at height
  // `tip` (four triangles then)
  surfaceMesh inputUnder(double tip)
  {
    surfaceMesh input;
    input.points = {SPoint3(-2., -2., 0.), SPoint3(5., -2., 0.),
                    SPoint3(5., 5., 0.), SPoint3(-2., 5., 0.),
                    SPoint3(1.5, 1.5, tip)};
    input.triangles = {{{0, 1, 4}}, {{1, 2, 4}}, {{2, 3, 4}}, {{3, 0, 4}}};
    return input;
  }

} // namespace

TEST(quadNodeSplit, aCollapsedDiagonalIsSplitBack)
{
  surfaceMesh m = gridWithACollapse();
  const surfaceMesh input = inputUnder(0.);
  const closestTriangleSearch onInput(input.points, input.triangles);
  quadNodeSplitOptions o;
  o.input = &input;
  o.onInput = &onInput;
  std::vector<int> part, owner(m.points.size(), 0), splitFrom;
  const std::size_t points = m.points.size();
  const quadNodeSplitResult r = splitQuadNodes(m, part, owner, splitFrom, o);
  EXPECT_EQ(r.splits, 1u);
  EXPECT_EQ(r.irregularBefore, 3u); // one of valence 6, two of 3
  EXPECT_EQ(r.irregularAfter, 0u);
  // one new point, split from the merged node, and one new quadrangle
  ASSERT_EQ(m.points.size(), points + 1);
  EXPECT_EQ(splitFrom.back(), point(1, 1));
  EXPECT_EQ(owner.back(), 0);
  EXPECT_EQ(m.quadrangles.size(), (std::size_t)n * n);
  const std::array<int, 4> &added = m.quadrangles.back();
  EXPECT_EQ(std::count(added.begin(), added.end(), point(1, 1)), 1);
  EXPECT_EQ(std::count(added.begin(), added.end(), (int)points), 1);
  double worst, mean;
  etaOfQuadrangles(m, worst, mean);
  EXPECT_GE(worst, 0.3);
  for(const auto &q : m.quadrangles) EXPECT_GT(quadAreaXY(m, q), 0.);
  // the halves on the input, on either side of the merged node's place
  for(int v : {point(1, 1), (int)points})
    EXPECT_NEAR(m.points[v].z(), 0., 1e-12);
  EXPECT_GT(m.points[point(1, 1)].distance(m.points[points]), 0.5);
}

TEST(quadNodeSplit, aFixedNodeOrARegularGridStays)
{
  surfaceMesh m = gridWithACollapse();
  std::vector<int> part, owner(m.points.size(), 0), splitFrom;
  owner[point(1, 1)] = -1; // a curve's node
  EXPECT_EQ(splitQuadNodes(m, part, owner, splitFrom).splits, 0u);
  // another face's quadrangle around it
  owner[point(1, 1)] = 0;
  part.assign(m.quadrangles.size(), 0);
  part[0] = 1;
  EXPECT_EQ(splitQuadNodes(m, part, owner, splitFrom).splits, 0u);
  surfaceMesh grid = quadGrid(n);
  std::vector<int> none, all(grid.points.size(), 0);
  const quadNodeSplitResult r = splitQuadNodes(grid, none, all, splitFrom);
  EXPECT_EQ(r.splits, 0u);
  EXPECT_EQ(r.irregularBefore, 0u);
}

TEST(quadNodeSplit, aNodeOnATipStays)
{
  // the merged node on the tip of a pyramid of the input, 2 high: its
  // halves would cut the tip off
  surfaceMesh m = gridWithACollapse(2.);
  const surfaceMesh input = inputUnder(2.);
  const closestTriangleSearch onInput(input.points, input.triangles);
  for(std::size_t i = 0; i < m.points.size(); i++)
    m.points[i] = onInput.closest(m.points[i]).point;
  quadNodeSplitOptions o;
  o.input = &input;
  o.onInput = &onInput;
  o.minEta = 0.;
  std::vector<int> part, owner(m.points.size(), 0), splitFrom;
  EXPECT_EQ(splitQuadNodes(m, part, owner, splitFrom, o).splits, 0u);
  // without the input, the same split is made
  o.input = nullptr;
  o.onInput = nullptr;
  EXPECT_EQ(splitQuadNodes(m, part, owner, splitFrom, o).splits, 1u);
}
