// Reparam - input nodes a new mesh cuts off: a node of the mesh next to one
// moves onto it, next to a fixed node it is left out, else it is inserted

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include "closestTriangle.h"
#include "farInputNodes.h"
#include "optimizerTestMeshes.h"
#include "testPatches.h"
#include "triangleQuality.h"

using namespace optimizeTest;

namespace {

  // The flat unit square (40 x 40 cells) with one inner node lifted by 0.08
  // at (x, y): a spike the flat 4 x 4 grid of the square cuts off
  testTriangulation spikeAt(double x, double y)
  {
    testTriangulation t = rectangleGrid(40, 40, 1., 1.);
    for(SPoint3 &p : t.points)
      if(std::fabs(p.x() - x) < 1e-9 && std::fabs(p.y() - y) < 1e-9)
        p = SPoint3(x, y, 0.08);
    return t;
  }

} // namespace

TEST(farInputNodes, aSpikeNextToAnInnerNodeTakesThatNode)
{
  // the spike 0.084 from the grid's inner node (0.5, 0.5), less than 0.4 of
  // the mean edge (0.285) of the triangles there; 0.08 from the grid, more
  // than 0.25 of it: a new node would make an edge of 0.084
  const surfaceMesh in = asSurfaceMesh(spikeAt(0.525, 0.5));
  const closestTriangleSearch onInput(in.points, in.triangles);
  optimizableMesh m = optimizable(rectangleGrid(4, 4, 1., 1.));
  const std::size_t nodes = m.points.size(), triangles = m.triangles.size();
  std::size_t moved = 0;
  EXPECT_EQ(insertFarInputNodes(m, in, onInput, false, 0.25, &moved), 1u);
  EXPECT_EQ(moved, 1u);
  EXPECT_EQ(m.points.size(), nodes);
  EXPECT_EQ(m.triangles.size(), triangles);
  const int center = 2 * 5 + 2; // the grid's node (0.5, 0.5)
  EXPECT_EQ(m.points[center].distance(SPoint3(0.525, 0.5, 0.08)), 0.);
  EXPECT_FALSE(m.movable[center]); // it marks the spike now
  EXPECT_GE(m.inputNode[center], 0);
  EXPECT_EQ(againstCount(m, in, onInput), 0u);
  double worst = 1.;
  for(const auto &t : m.triangles)
    worst = std::min(
      worst, triangleKappa(m.points[t[0]], m.points[t[1]], m.points[t[2]]));
  EXPECT_GT(worst, 0.8); // 0.83; a new node on the edge there: 0.42
}

TEST(farInputNodes, aSpikeNextToABorderNodeIsLeftOut)
{
  // the same spike next to the border node (0.5, 0), which may not move: the
  // mesh passes 0.088 from it already, a new node would make that edge
  const surfaceMesh in = asSurfaceMesh(spikeAt(0.525, 0.025));
  const closestTriangleSearch onInput(in.points, in.triangles);
  optimizableMesh m = optimizable(rectangleGrid(4, 4, 1., 1.));
  const optimizableMesh before = m;
  std::size_t moved = 0;
  EXPECT_EQ(insertFarInputNodes(m, in, onInput, false, 0.25, &moved), 0u);
  EXPECT_EQ(moved, 0u);
  ASSERT_EQ(m.points.size(), before.points.size());
  for(std::size_t i = 0; i < m.points.size(); i++)
    EXPECT_EQ(m.points[i].distance(before.points[i]), 0.);
  EXPECT_EQ(m.triangles, before.triangles);
  // farther from any node it is inserted, as a new node
  const surfaceMesh far = asSurfaceMesh(spikeAt(0.625, 0.375));
  const closestTriangleSearch onFar(far.points, far.triangles);
  EXPECT_EQ(insertFarInputNodes(m, far, onFar, false, 0.25, &moved), 1u);
  EXPECT_EQ(moved, 0u);
  EXPECT_EQ(m.points.size(), before.points.size() + 1);
}
