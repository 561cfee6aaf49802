// Reparam - tips of a triangulation kept as mesh nodes

#include <cmath>
#include <set>
#include <gtest/gtest.h>
#include "conePoints.h"
#include "creaseChains.h"
#include "edgeByCoordinates.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"

using namespace reparam;

namespace {

  // A cone of apex (0, 0, height) over the circle of radius 1 in z = 0,
  // open at its base: `rings` rings of `sectors` nodes (node 0 the apex)
  testTriangulation cone(int rings, int sectors, double height)
  {
    testTriangulation t;
    t.points.push_back(SPoint3(0., 0., height));
    for(int r = 1; r <= rings; r++)
      for(int s = 0; s < sectors; s++) {
        const double a = 2. * M_PI * s / sectors;
        const double f = (double)r / rings;
        t.points.push_back(
          SPoint3(f * std::cos(a), f * std::sin(a), height * (1. - f)));
      }
    auto id = [sectors](int r, int s) {
      return r == 0 ? 0 : 1 + (r - 1) * sectors + (s % sectors);
    };
    for(int s = 0; s < sectors; s++) t.triangles.push_back({0, id(1, s), id(1, s + 1)});
    for(int r = 1; r < rings; r++)
      for(int s = 0; s < sectors; s++) {
        const int a = id(r, s), b = id(r, s + 1);
        const int c = id(r + 1, s), d = id(r + 1, s + 1);
        t.triangles.push_back({a, c, d});
        t.triangles.push_back({a, d, b});
      }
    return t;
  }

} // namespace

TEST(conePoints, apexOfASharpConeOnly)
{
  // half-angle atan(1 / 3) = 18.4 degrees: angles at the apex sum to
  // 2 pi sin(18.4) = 1.99 < pi
  testTriangulation sharp = cone(6, 24, 3.);
  EXPECT_EQ(conePoints(sharp.points, sharp.triangles, M_PI),
            std::vector<int>{0});
  // half-angle 63 degrees: 5.6, no tip; nor is any node of a flat grid
  testTriangulation blunt = cone(6, 24, 0.5);
  EXPECT_TRUE(conePoints(blunt.points, blunt.triangles, M_PI).empty());
  testTriangulation grid = rectangleGrid(6, 6, 1., 1.);
  EXPECT_TRUE(conePoints(grid.points, grid.triangles, 2. * M_PI - 1e-9).empty());
  // the closed cube's corners sum to 3 pi / 2: tips below 2 pi, not below pi
  testTriangulation cube;
  for(int i = 0; i < 8; i++)
    cube.points.push_back(SPoint3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  cube.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6},
                    {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},
                    {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  EXPECT_TRUE(conePoints(cube.points, cube.triangles, M_PI).empty());
  EXPECT_EQ(conePoints(cube.points, cube.triangles, 2. * M_PI).size(), 8u);
}

TEST(conePoints, meshHasANodeAtTheTip)
{
  // meshed coarsely, the cone keeps its apex: a point embedded in its face
  remeshWithRecipe(cone(12, 48, 3.), 0.4);
  std::vector<std::size_t> tags;
  std::vector<double> coords, params;
  gmsh::model::mesh::getNodes(tags, coords, params, -1, -1, false);
  double nearest = 1e300;
  for(std::size_t i = 0; i + 2 < coords.size(); i += 3)
    nearest = std::min(nearest, std::hypot(coords[i], coords[i + 1],
                                           coords[i + 2] - 3.));
  EXPECT_LT(nearest, 1e-12);
  // and every surface is meshed
  EXPECT_TRUE(surfacesWithoutElements().empty());
}

TEST(conePoints, creaseCornersAreWhereThreeCreasesMeet)
{
  // a 4 x 4 grid; creases from its middle node 12 to three neighbours, and
  // two from node 6: only node 12 is a corner
  testTriangulation grid = rectangleGrid(4, 4, 1., 1.);
  const std::set<std::pair<int, int> > creases = {
    {7, 12}, {11, 12}, {12, 13}, {1, 6}, {6, 11}};
  auto isCrease = [&creases](int a, int b) {
    return creases.count({std::min(a, b), std::max(a, b)}) > 0;
  };
  EXPECT_EQ(creaseCorners(grid.points, grid.triangles, isCrease),
            std::vector<int>{12});
}

TEST(edgeByCoordinates, sameEdgeWhateverTheOrderOfItsEnds)
{
  const SPoint3 a(1, 2, 3), b(1, 2, 4), c(0, 5, 5);
  EXPECT_EQ(byCoordinates(a, b), byCoordinates(b, a));
  EXPECT_EQ(byCoordinates(a, b), (edgeByCoordinates{{1, 2, 3, 1, 2, 4}}));
  EXPECT_NE(byCoordinates(a, b), byCoordinates(a, c));
}
