// Reparam - the state the optimizer's passes share: triangles below the
// target in the order they are tried, rings and their neighbours

#include <cmath>
#include <set>
#include <gtest/gtest.h>
#include "hexagonFan.h"
#include "localOptimizer.h"
#include "triangleQuality.h"

using namespace optimizeTest;
using namespace reparam::optimizeInternal;

TEST(optimizeLocalOptimizer, trianglesBelowTargetAgainstFirstThenWorst)
{
  // center at (0.9, 0): triangles 0 and 5 at kappa 0.153, 1 and 4 at 0.531
  // (below 0.6), 2 and 3 at 0.762
  fanOptimizer fan(SPoint3(0.9, 0., 0.));
  optimizableMesh &m = fan.m;
  const localOptimizer &opt = fan.opt;
  m.against[2] = true;
  EXPECT_NEAR(opt.kappa(0), 0.153113, 1e-6);
  EXPECT_NEAR(opt.kappa(1), 0.530635, 1e-6);
  EXPECT_NEAR(opt.kappa(2), 0.761625, 1e-6);
  const std::vector<int> below = opt.trianglesBelowTarget();
  ASSERT_EQ(below.size(), 5u);
  EXPECT_EQ(below[0], 2); // against the input: worse than any
  EXPECT_EQ(std::set<int>(below.begin() + 1, below.begin() + 3),
            (std::set<int>{0, 5}));
  EXPECT_EQ(std::set<int>(below.begin() + 3, below.end()),
            (std::set<int>{1, 4}));
  EXPECT_FALSE(opt.spent());
  EXPECT_EQ(fan.searches, 0u);
}

TEST(optimizeLocalOptimizer, neighboursAndTheTriangleAcrossAnEdge)
{
  fanOptimizer fan(SPoint3(0., 0., 0.), 0);
  optimizableMesh &m = fan.m;
  const localOptimizer &opt = fan.opt;
  std::set<int> around;
  opt.addNeighbours(0, around);
  EXPECT_EQ(around, (std::set<int>{0, 1, 5, 6}));
  opt.addNeighbours(6, around);
  EXPECT_EQ(around.size(), 7u);
  // (6, 0, 1) across its inner edge (6, 1) is (6, 1, 2); its border edge
  // (0, 1) has none
  EXPECT_EQ(opt.neighbourAcross(0, 6, 1), 1);
  EXPECT_EQ(opt.neighbourAcross(0, 6, 0), 5);
  EXPECT_EQ(opt.neighbourAcross(0, 0, 1), -1);
  EXPECT_TRUE(opt.spent()); // a budget of no search
  // the per-point records the optimizer keeps, made
  EXPECT_EQ(m.landing, std::vector<int>(7, -1));
  EXPECT_EQ(m.inputNode, std::vector<int>(7, -1));
}
