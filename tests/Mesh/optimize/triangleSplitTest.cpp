// Reparam - the nodes added to a mesh being optimized: a node moves only
// where it may and its triangles stay good, its neighbours wait a round

#include <gtest/gtest.h>
#include "closestTriangle.h"
#include "optimizerTestMeshes.h"
#include "testPatches.h"
#include "triangleSplit.h"

using namespace optimizeTest;

TEST(triangleSplitter, aNodeMovesOnlyWhereItsTrianglesStayGood)
{
  const surfaceMesh in = asSurfaceMesh(rectangleGrid(8, 8, 1., 1.));
  const closestTriangleSearch onInput(in.points, in.triangles);
  optimizableMesh m = optimizable(rectangleGrid(4, 4, 1., 1.));
  const int center = 2 * 5 + 2, corner = 0;
  {
    triangleSplitter split(m, in, onInput, false);
    // a node that may not move does not
    EXPECT_FALSE(split.moveNode(corner, SPoint3(0.1, 0.1, 0.), -1, 0.));
    // across a neighbour: its triangles would turn over
    EXPECT_FALSE(split.moveNode(center, SPoint3(0.8, 0.5, 0.), -1, 0.));
    // near a neighbour: a triangle below the floor
    EXPECT_FALSE(split.moveNode(center, SPoint3(0.7, 0.5, 0.), -1, 0.2));
    EXPECT_TRUE(split.moveNode(center, SPoint3(0.55, 0.5, 0.), 7, 0.2));
    EXPECT_EQ(m.points[center].distance(SPoint3(0.55, 0.5, 0.)), 0.);
    EXPECT_FALSE(m.movable[center]);
    EXPECT_EQ(m.inputNode[center], 7);
    EXPECT_GE(m.landing[center], 0);
    // its neighbours wait for the next round
    EXPECT_FALSE(split.moveNode(center + 1, SPoint3(0.75, 0.55, 0.), -1, 0.));
  }
  triangleSplitter next(m, in, onInput, false);
  EXPECT_TRUE(next.moveNode(center + 1, SPoint3(0.75, 0.55, 0.), -1, 0.));
}
