// Reparam - nodes pinched between two elements that share both their edges
// at it: a triangle of three nodes in a row folded onto the quadrangle
// across them, two triangles on each other; a grid's nodes, a node between
// two elements of different edges or one that may not go stay

#include <gtest/gtest.h>
#include "pinchedNodes.h"
#include "surfaceMesh.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  // a (0), m (1), b (2) in a row bent at m by 0.1; the quadrangle
  // (b, x, a, m) above them with x (3) at (1, 1), the triangle (a, b, m)
  // folded onto it and the triangle (a, c, b) below with c (4) at (1, -1)
  surfaceMesh foldedEar()
  {
    surfaceMesh m;
    m.points = {SPoint3(0., 0., 0.), SPoint3(1., 0.1, 0.), SPoint3(2., 0., 0.),
                SPoint3(1., 1., 0.), SPoint3(1., -1., 0.)};
    m.triangles = {{{0, 2, 1}}, {{0, 4, 2}}};
    m.quadrangles = {{{2, 3, 0, 1}}};
    return m;
  }

} // namespace

TEST(pinchedNodes, aTriangleFoldedOntoAQuadrangleLeavesItsTriangle)
{
  const surfaceMesh m = foldedEar();
  const std::vector<pinchedNode> p =
    pinchedNodes(m, std::vector<bool>(m.points.size(), true));
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].node, 1);
  // the triangle (0) and the quadrangle (element 2 + 0)
  EXPECT_EQ(p[0].elements[0], 0);
  EXPECT_EQ(p[0].elements[1], 2);
  ASSERT_EQ(p[0].triangles.size(), 1u);
  // the quadrangle's corners after m, in its order: (b, x, a)
  EXPECT_EQ(p[0].triangles[0], (std::array<int, 3>{{2, 3, 0}}));
  EXPECT_EQ(p[0].from[0], 1);
}

TEST(pinchedNodes, twoTrianglesOnEachOtherGo)
{
  surfaceMesh m = foldedEar();
  // an inner node (5) with the triangles (a, c, n) and (c, a, n) only
  m.points.push_back(SPoint3(0.5, -0.4, 0.));
  m.triangles.push_back({{0, 4, 5}});
  m.triangles.push_back({{4, 0, 5}});
  std::vector<bool> removable(m.points.size(), false);
  removable[5] = true;
  const std::vector<pinchedNode> p = pinchedNodes(m, removable);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].node, 5);
  EXPECT_EQ(p[0].elements[0], 2);
  EXPECT_EQ(p[0].elements[1], 3);
  EXPECT_TRUE(p[0].triangles.empty());
}

TEST(pinchedNodes, aGridAndNodesThatMayNotGoStay)
{
  // the grid's border nodes have two quadrangles of different edges there
  const surfaceMesh g = quadGrid(3);
  EXPECT_TRUE(
    pinchedNodes(g, std::vector<bool>(g.points.size(), true)).empty());
  const surfaceMesh m = foldedEar();
  std::vector<bool> removable(m.points.size(), true);
  removable[1] = false;
  EXPECT_TRUE(pinchedNodes(m, removable).empty());
}

TEST(pinchedNodes, noElementInTwoPinches)
{
  // the same square twice, the second reversed: each corner is pinched,
  // but all four share the two elements
  surfaceMesh m;
  m.points = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.), SPoint3(1., 1., 0.),
              SPoint3(0., 1., 0.)};
  m.quadrangles = {{{0, 1, 2, 3}}, {{2, 1, 0, 3}}};
  const std::vector<pinchedNode> p =
    pinchedNodes(m, std::vector<bool>(m.points.size(), true));
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].node, 0);
  EXPECT_EQ(p[0].triangles.size(), 2u);
}
