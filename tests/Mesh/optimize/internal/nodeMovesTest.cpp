// Reparam - the node moves of the optimization on the input: the places a
// node is tried at (the worst triangle's apex, the max-min place of its
// ring), and a move kept where the ring gets better

#include <cmath>
#include <gtest/gtest.h>
#include "hexagonFan.h"
#include "localOptimizer.h"

using namespace optimizeTest;
using namespace reparam::optimizeInternal;

TEST(optimizeNodeMoves, theApexAndTheMaxMinPlaceOfAFanAreItsCenter)
{
  // the apex that makes any of the hexagon's triangles equilateral is the
  // center, and there all six are: both places find it from off-center
  fanOptimizer fan(SPoint3(0.5, 0.1, 0.));
  const localOptimizer &opt = fan.opt;
  EXPECT_NEAR(opt.worstTriangleApex(6).distance(SPoint3(0., 0., 0.)), 0.,
              1e-12);
  // compass steps from a quarter of the mean edge (1.07 here), halved down
  // to 1/32 of that: within a last step of the center
  const SPoint3 best = opt.maxMinPoint(6);
  EXPECT_LT(best.distance(SPoint3(0., 0., 0.)), 0.25 * 1.07 / 32.);
  EXPECT_GT(opt.ringKappa(6, best).first, 0.98);
  EXPECT_NEAR(best.z(), 0., 1e-15); // in the ring's plane
}

TEST(optimizeNodeMoves, aMoveLandsOnTheInputWhereTheRingIsBetter)
{
  fanOptimizer fan(SPoint3(0.9, 0., 0.));
  optimizableMesh &m = fan.m;
  localOptimizer &opt = fan.opt;
  // a fixed node does not move
  EXPECT_FALSE(opt.tryMove(0));
  EXPECT_TRUE(opt.tryMove(6));
  // the neighbours' centroid: the center, six equilateral triangles
  EXPECT_NEAR(m.points[6].distance(SPoint3(0., 0., 0.)), 0., 1e-12);
  EXPECT_GE(m.landing[6], 0);
  EXPECT_GT(fan.searches, 0u);
  // nothing changed around it since: not tried again
  EXPECT_FALSE(opt.tryMove(6));
}
