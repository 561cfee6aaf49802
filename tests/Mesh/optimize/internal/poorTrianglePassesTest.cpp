// Reparam - the targeted passes of the optimization on the input: poor
// triangles counted, and flips and moves around them until none is left

#include <gtest/gtest.h>
#include "hexagonFan.h"
#include "optimizationPasses.h"
#include "../optimizerTestMeshes.h"

using namespace optimizeTest;
using namespace reparam::optimizeInternal;

TEST(optimizePoorTrianglePasses, countsTheTrianglesBelowAndAgainst)
{
  // center at (0.9, 0): four triangles below 0.6 (0.153 and 0.531, twice)
  optimizableMesh m = hexagonFan(SPoint3(0.9, 0., 0.));
  m.against[2] = m.against[3] = true;
  std::size_t below = 7, against = 7;
  countPoorTriangles(m, meshOptimizationOptions(), below, against);
  EXPECT_EQ(below, 4u);
  EXPECT_EQ(against, 2u);
  meshOptimizationOptions lower;
  lower.target = 0.2;
  countPoorTriangles(m, lower, below, against);
  EXPECT_EQ(below, 2u);
}

TEST(optimizePoorTrianglePasses, aNodeNearItsRingsBorderGoesBackInside)
{
  const hexagonInput input;
  optimizableMesh m = hexagonFan(SPoint3(0.9, 0., 0.));
  m.landing.assign(7, -1);
  m.inputNode.assign(7, -1);
  const double before = worstKappa(m);
  meshOptimizationResult r;
  improvePoorTriangles(m, input.mesh, input.search, meshOptimizationOptions(),
                       r, {});
  EXPECT_NEAR(before, 0.153113, 1e-6);
  // one pass: no flip kept, the center moved to its neighbours' centroid
  // (six equilateral triangles), nothing left below the target
  EXPECT_EQ(r.passes, 1u);
  EXPECT_EQ(r.flips, 0u);
  EXPECT_EQ(r.moves, 1u);
  EXPECT_GT(r.searches, 0u);
  EXPECT_NEAR(m.points[6].distance(SPoint3(0., 0., 0.)), 0., 1e-12);
  std::size_t below, against;
  countPoorTriangles(m, meshOptimizationOptions(), below, against);
  EXPECT_EQ(below, 0u);
  EXPECT_NEAR(worstKappa(m), 1., 1e-12);
}
