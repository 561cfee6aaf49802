// Reparam - the smoothing sweeps of the optimization on the input: the mean
// kappa rises, not the worst, and a ridge the mesh holds stays held

#include <cmath>
#include <gtest/gtest.h>
#include "closestTriangle.h"
#include "hexagonFan.h"
#include "localOptimizer.h"
#include "optimizeOnInput.h"
#include "../optimizerTestMeshes.h"
#include "optimizationPasses.h"
#include "testPatches.h"

using namespace optimizeTest;
using namespace reparam::optimizeInternal;

TEST(optimizeSmoothingSweeps, smoothingRaisesTheMeanKappaNotTheWorst)
{
  // Jittered grids on the bump, optimized with and without the smoothing
  // sweeps: the same worst kappa or better, a higher mean, nodes on the
  // input, no triangle against it
  const testTriangulation input = bump(rectangleGrid(50, 50, 1., 1.));
  const surfaceMesh in = asSurfaceMesh(input);
  const closestTriangleSearch onInput(in.points, in.triangles);
  for(unsigned seed = 1; seed <= 4; seed++) {
    optimizableMesh m = optimizable(bump(jitteredGrid(12, 0.6, seed)));
    for(SPoint3 &p : m.points) p = onInput.closest(p).point;
    optimizableMesh unsmoothed = m;
    meshOptimizationOptions o;
    o.insertAbove = 0.;
    const meshOptimizationResult r = optimizeOnInput(m, in, onInput, o);
    o.smoothPasses = 0;
    const meshOptimizationResult r0 =
      optimizeOnInput(unsmoothed, in, onInput, o);
    EXPECT_GE(r.minAfter, r0.minAfter) << "seed " << seed;
    EXPECT_GT(meanKappa(m), meanKappa(unsmoothed) + 0.02) << "seed " << seed;
    EXPECT_GT(r.moves, r0.moves) << "seed " << seed;
    EXPECT_LT(largestDistance(m, onInput), 1e-9) << "seed " << seed;
    EXPECT_EQ(againstCount(m, in, onInput), 0u) << "seed " << seed;
  }
}

TEST(optimizeSmoothingSweeps, smoothingKeepsARidgeTheMeshHolds)
{
  // A roof whose ridge (x = 0.5, 33 degrees between the normals: under the
  // feature angle, so no curve holds it) runs along a column of the mesh's
  // nodes; the column left of it is pushed towards it and held, so that the
  // ridge nodes' neighbours have their centroid off the ridge. Smoothing may
  // move them there only as far as the ridge stays within 2 % of the
  // triangles' size from the mesh
  const testTriangulation input = roof(rectangleGrid(40, 40, 1., 1.), 0.3);
  const surfaceMesh in = asSurfaceMesh(input);
  const closestTriangleSearch onInput(in.points, in.triangles);
  testTriangulation grid = rectangleGrid(10, 10, 1., 1.);
  std::vector<int> held;
  for(std::size_t i = 0; i < grid.points.size(); i++) {
    SPoint3 &p = grid.points[i];
    if(std::fabs(p.x() - 0.4) < 1e-9) {
      p = SPoint3(0.46, p.y(), 0.);
      held.push_back((int)i);
    }
  }
  optimizableMesh start = optimizable(roof(grid, 0.3));
  for(int i : held) start.movable[i] = false;
  auto ridgeCut = [&](const optimizableMesh &mesh) {
    return ridgeDistance(mesh, in, 0.15, 0.85);
  };
  ASSERT_LT(ridgeCut(start), 1e-12);
  meshOptimizationOptions o;
  o.insertAbove = 0.;
  o.target = 0.; // smoothing only
  optimizableMesh kept = start, cut = start;
  optimizeOnInput(kept, in, onInput, o);
  o.smoothTolerance = 1e9; // nothing held
  const meshOptimizationResult r = optimizeOnInput(cut, in, onInput, o);
  const double h = 0.1;
  // without the hold, the ridge nodes go: better triangles, the ridge cut
  EXPECT_GT(r.moves, 0u);
  EXPECT_GT(meanKappa(cut), meanKappa(start));
  EXPECT_GT(ridgeCut(cut), 0.05 * h);
  // the ring's longest edge: a diagonal, sqrt(2) h at most
  EXPECT_LT(ridgeCut(kept), 0.02 * std::sqrt(2.) * h) << ridgeCut(cut);
}

TEST(optimizeSmoothingSweeps, aNodeOffItsFanIsSmoothedToTheCenter)
{
  // the points that make each triangle of a hexagon fan equilateral are all
  // its center, wherever the node is; the neighbours' centroid too
  fanOptimizer fan(SPoint3(0.1, 0.05, 0.));
  EXPECT_NEAR(meanKappa(fan.m), 0.990612, 1e-6);
  EXPECT_NEAR(fan.opt.ringApexMean(6).distance(SPoint3(0., 0., 0.)), 0., 1e-12);
  EXPECT_FALSE(fan.opt.trySmooth(0, 1e-3)); // fixed
  // a gain the center cannot give: the ring's kappa sum rises by 0.056
  EXPECT_FALSE(fan.opt.trySmooth(6, 0.1));
  fanOptimizer fresh(SPoint3(0.1, 0.05, 0.));
  optimizableMesh &again = fresh.m;
  EXPECT_TRUE(fresh.opt.trySmooth(6, 1e-3));
  EXPECT_NEAR(again.points[6].distance(SPoint3(0., 0., 0.)), 0., 1e-12);
  EXPECT_NEAR(meanKappa(again), 1., 1e-12);
  EXPECT_GE(again.landing[6], 0);
}

TEST(optimizeSmoothingSweeps, sweepsStopWhenOneMovesNothing)
{
  // one move in the first sweep, none in the second; no valence flip (every
  // node has its ideal valence)
  const hexagonInput input;
  optimizableMesh m = hexagonFan(SPoint3(0.1, 0.05, 0.));
  m.landing.assign(7, -1);
  m.inputNode.assign(7, -1);
  meshOptimizationResult r;
  smoothMesh(m, input.mesh, input.search, meshOptimizationOptions(), r);
  EXPECT_EQ(r.moves, 1u);
  EXPECT_EQ(r.flips, 0u);
  EXPECT_GT(r.searches, 0u);
  EXPECT_NEAR(m.points[6].distance(SPoint3(0., 0., 0.)), 0., 1e-12);
  // no sweep asked: nothing moves
  optimizableMesh still = hexagonFan(SPoint3(0.1, 0.05, 0.));
  meshOptimizationOptions none;
  none.smoothPasses = 0;
  meshOptimizationResult r0;
  smoothMesh(still, input.mesh, input.search, none, r0);
  EXPECT_EQ(r0.moves, 0u);
  EXPECT_EQ(still.points[6].x(), 0.1);
}
