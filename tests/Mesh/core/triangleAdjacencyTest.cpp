// Reparam - the edges of a triangulation and the triangles around them

#include <gtest/gtest.h>
#include "testPatches.h"
#include "triangleAdjacency.h"

using namespace reparam;

TEST(triangleAdjacency, acrossAManifoldEdgeOnly)
{
  // triangles 0 and 1 share edge 0-2; triangles 2, 3, 4 share edge 5-6
  const std::vector<std::array<int, 3> > t = {
    {{0, 1, 2}}, {{0, 2, 3}}, {{5, 6, 7}}, {{6, 5, 8}}, {{5, 6, 9}}};
  const triangleAdjacency a = makeTriangleAdjacency(t);
  const int shared = a.find(2, 0);
  ASSERT_GE(shared, 0);
  EXPECT_EQ(a.numTriangles(shared), 2);
  EXPECT_EQ(a.across(shared, 0), 1);
  EXPECT_EQ(a.across(shared, 1), 0);
  const int fin = a.find(5, 6);
  EXPECT_EQ(a.numTriangles(fin), 3);
  EXPECT_EQ(a.across(fin, 2), -1);
  EXPECT_EQ(a.find(1, 3), -1);
  EXPECT_EQ(a.triangleEdges[1][0], shared); // nodes 0 and 2 of triangle 1
}

TEST(triangleAdjacency, partNeighboursAreIndicesInThePart)
{
  // a 3 x 2 grid, two triangles a cell; the part: cells (0, 0) and (1, 0)
  // given in a shuffled order
  const testTriangulation g = rectangleGrid(3, 2, 3., 2.);
  const triangleAdjacency a = makeTriangleAdjacency(g.triangles);
  const std::vector<int> part = {3, 0, 2, 1};
  const auto n = partNeighbours(a, part, g.triangles.size());
  ASSERT_EQ(n.size(), part.size());
  for(std::size_t i = 0; i < part.size(); i++)
    for(int k = 0; k < 3; k++) {
      const int o = a.across(a.triangleEdges[part[i]][k], part[i]);
      int expected = -1;
      for(std::size_t j = 0; j < part.size(); j++)
        if(part[j] == o) expected = (int)j;
      EXPECT_EQ(n[i][k], expected) << "triangle " << part[i] << " edge " << k;
    }
  // each triangle of the part has one neighbour in it at least, and the
  // neighbours are symmetric
  for(std::size_t i = 0; i < part.size(); i++) {
    int inside = 0;
    for(int k = 0; k < 3; k++)
      if(n[i][k] >= 0) {
        inside++;
        const auto &back = n[n[i][k]];
        EXPECT_TRUE(back[0] == (int)i || back[1] == (int)i ||
                    back[2] == (int)i);
      }
    EXPECT_GE(inside, 1);
  }
  // a second part on the same thread: nothing of the first is left over
  const std::vector<int> other = {part[0]};
  const auto alone = partNeighbours(a, other, g.triangles.size());
  EXPECT_EQ(alone[0], (std::array<int, 3>{{-1, -1, -1}}));
  // every triangle: as many inner edges, counted from both sides, as the
  // grid has (3 * 2 cells: 6 diagonals, 2 * 2 + 3 * 1 between cells)
  std::vector<int> all(g.triangles.size());
  for(std::size_t t = 0; t < all.size(); t++) all[t] = (int)t;
  int twice = 0;
  for(const auto &e : partNeighbours(a, all, all.size()))
    for(int k = 0; k < 3; k++) twice += e[k] >= 0;
  EXPECT_EQ(twice, 2 * (6 + 7));
}
