// Reparam - measures of a node's ring with the node moved: kappas (worst,
// mean, sum, count below the target), centroid, longest edge, distance of a
// point to the ring

#include <cmath>
#include <gtest/gtest.h>
#include "hexagonFan.h"
#include "localOptimizer.h"
#include "triangleQuality.h"

using namespace optimizeTest;
using namespace reparam::optimizeInternal;

TEST(optimizeRingMeasures, kappasOfTheRingWithTheNodeMoved)
{
  fanOptimizer fan;
  optimizableMesh &m = fan.m;
  const localOptimizer &opt = fan.opt;
  // at the center: six equilateral triangles
  const std::pair<double, double> here = opt.ringKappa(6, m.points[6]);
  EXPECT_NEAR(here.first, 1., 1e-12);
  EXPECT_NEAR(here.second, 1., 1e-12);
  // at (0.5, 0): two 30-60-90 triangles, 2 sqrt(3) / (3 + sqrt(3)), worst
  const SPoint3 at(0.5, 0., 0.);
  double sum = 0.;
  for(const auto &t : m.triangles)
    sum += triangleKappa(at, m.points[t[1]], m.points[t[2]]);
  EXPECT_NEAR(sum, 4.886077, 1e-6);
  const std::pair<double, double> moved = opt.ringKappa(6, at);
  EXPECT_NEAR(moved.first, 2. * std::sqrt(3.) / (3. + std::sqrt(3.)), 1e-12);
  EXPECT_NEAR(moved.second, sum / 6., 1e-12);
  const localOptimizer::ringQuality q = opt.ringAt(6, at);
  EXPECT_NEAR(q.worst, moved.first, 0.);
  EXPECT_NEAR(q.sum, sum, 1e-12);
  EXPECT_EQ(q.below, 0);
  // at (0.9, 0): four below the target 0.6 (0.153 twice, 0.531 twice)
  EXPECT_EQ(opt.ringAt(6, SPoint3(0.9, 0., 0.)).below, 4);
  EXPECT_EQ(fan.searches, 0u); // no search of the input for these
}

TEST(optimizeRingMeasures, centroidLongestEdgeAndDistance)
{
  fanOptimizer fan(SPoint3(0.3, -0.2, 0.));
  optimizableMesh &m = fan.m;
  const localOptimizer &opt = fan.opt;
  // the neighbours' centroid: the hexagon's center, wherever node 6 is
  const SPoint3 c = opt.ringCentroid(6);
  EXPECT_NEAR(c.distance(SPoint3(0., 0., 0.)), 0., 1e-15);
  // the longest edge: from (0.3, -0.2) to the corner (-1/2, sqrt(3)/2)
  EXPECT_NEAR(opt.ringLongestEdge(6), std::hypot(0.8, std::sqrt(3.) / 2. + 0.2),
              1e-12);
  // a point above the flat ring: its height; beside it: to its border
  EXPECT_NEAR(opt.distanceToRing(6, m.points[6], SPoint3(0.2, 0.1, 0.5)), 0.5,
              1e-12);
  EXPECT_NEAR(opt.distanceToRing(6, m.points[6], SPoint3(3., 0., 0.)), 2.,
              1e-12);
}
