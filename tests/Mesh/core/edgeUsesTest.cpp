// Reparam - the count of uses per undirected edge

#include <gtest/gtest.h>
#include "edgeUses.h"
#include "testPatches.h"

using namespace reparam;

TEST(edgeUses, twoTrianglesShareTheirDiagonal)
{
  const edgeUses uses =
    edgeUsesOf(std::vector<std::array<int, 3> >{{{0, 1, 2}}, {{0, 2, 3}}});
  EXPECT_EQ(uses.size(), 5u);
  EXPECT_EQ(uses.of(0, 2), 2);
  EXPECT_EQ(uses.of(2, 0), 2);
  EXPECT_EQ(uses.of(1, 2), 1);
  EXPECT_EQ(uses.of(1, 3), 0);
}

TEST(edgeUses, visitedBySmallerThenLargerNode)
{
  edgeUses uses;
  uses.addTriangle(5, 3, 1);
  uses.add(4, 0);
  const std::vector<std::pair<int, int> > expected = {
    {0, 4}, {1, 3}, {1, 5}, {3, 5}};
  std::vector<std::pair<int, int> > visited;
  for(const auto &e : uses) visited.push_back(e.first);
  EXPECT_EQ(visited, expected);
  EXPECT_EQ(undirectedEdge(7, 2), std::make_pair(2, 7));
}

TEST(edgeUses, flatListCountsAsArrays)
{
  // a fan of three triangles around node 0, one edge used by a fourth
  const std::vector<int> flat = {0, 1, 2, 0, 2, 3, 0, 3, 4, 2, 0, 5};
  const edgeUses uses = edgeUsesOf(flat);
  EXPECT_EQ(uses.of(0, 2), 3);
  EXPECT_EQ(uses.of(0, 3), 2);
  EXPECT_EQ(uses.of(0, 1), 1);
  EXPECT_EQ(uses.size(), 9u);
  // a trailing partial triangle is ignored
  std::vector<int> partial = flat;
  partial.push_back(7);
  partial.push_back(8);
  EXPECT_EQ(edgeUsesOf(partial).size(), 9u);
}

TEST(edgeUses, gridHasItsBorderUsedOnce)
{
  // 4 x 3 cells: 2 (4 + 3) border edges, every other edge used twice
  const testTriangulation t = rectangleGrid(4, 3, 4., 3.);
  std::size_t once = 0, twice = 0;
  for(const auto &e : edgeUsesOf(t.triangles)) {
    once += e.second == 1;
    twice += e.second == 2;
  }
  EXPECT_EQ(once, 14u);
  // edges: 4 * 4 horizontal, 5 * 3 vertical, 12 diagonals
  EXPECT_EQ(once + twice, 43u);
}

TEST(edgeUses, edgesUsedOnceAreTheTreesOnesInItsOrder)
{
  // the fan with an edge of three triangles, a repeated triangle (its edges
  // used twice) and a grid: the same edges, in the same order, as the
  // count's edges of one use
  std::vector<int> fan = {0, 1, 2, 0, 2, 3, 0, 3, 4, 2, 0, 5, 7, 8, 9, 9, 8, 7};
  const testTriangulation grid = rectangleGrid(5, 4, 5., 4.);
  std::vector<int> flat;
  for(const auto &t : grid.triangles)
    flat.insert(flat.end(), t.begin(), t.end());
  for(const std::vector<int> &nodes : {fan, flat}) {
    std::vector<std::pair<int, int> > expected;
    for(const auto &e : edgeUsesOf(nodes))
      if(e.second == 1) expected.push_back(e.first);
    EXPECT_EQ(edgesUsedOnce(nodes), expected);
  }
  // 0-1, 1-2, 2-3, 3-4, 0-4, 0-5, 2-5
  EXPECT_EQ(edgesUsedOnce(fan).size(), 7u);
  EXPECT_EQ(edgesUsedOnce(flat).size(), 18u);
  EXPECT_TRUE(edgesUsedOnce({}).empty());
}
