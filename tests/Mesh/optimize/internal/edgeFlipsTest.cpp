// Reparam - the edge flips of the optimization on the input: locked edges
// stay, a sliver's flip may cut a ridge off by its own tolerance, the
// valence flips undo a flip that broke a regular grid

#include <array>
#include <cmath>
#include <set>
#include <gtest/gtest.h>
#include "closestTriangle.h"
#include "hexagonFan.h"
#include "localOptimizer.h"
#include "optimizeOnInput.h"
#include "../optimizerTestMeshes.h"
#include "testPatches.h"
#include "triangleQuality.h"

using namespace optimizeTest;
using namespace reparam::optimizeInternal;

namespace {

  // n x n unit squares of [0, n]^2 cut by the same diagonal: every inner
  // node of valence 6
  optimizableMesh diagonalGrid(int n)
  {
    testTriangulation t;
    for(int j = 0; j <= n; j++)
      for(int i = 0; i <= n; i++) t.points.push_back(SPoint3(i, j, 0.));
    for(int j = 0; j < n; j++)
      for(int i = 0; i < n; i++) {
        const int a = i + (n + 1) * j, b = a + 1, c = a + n + 1, d = c + 1;
        t.triangles.push_back({{a, b, d}});
        t.triangles.push_back({{a, d, c}});
      }
    return optimizable(t);
  }

  std::size_t innerNodesNotOfValence6(const optimizableMesh &m)
  {
    std::vector<std::set<int> > neighbours(m.points.size());
    for(const auto &t : m.triangles)
      for(int k = 0; k < 3; k++) {
        neighbours[t[k]].insert(t[(k + 1) % 3]);
        neighbours[t[(k + 1) % 3]].insert(t[k]);
      }
    std::size_t n = 0;
    for(std::size_t v = 0; v < m.points.size(); v++)
      n += m.movable[v] && neighbours[v].size() != 6;
    return n;
  }

} // namespace

TEST(optimizeEdgeFlips, lockedEdgesAreNotFlipped)
{
  // Two triangles over a quad whose diagonal makes a sliver: flipped when
  // free, kept when locked
  optimizableMesh m;
  m.points = {SPoint3(0., 0., 0.), SPoint3(1., 0.45, 0.), SPoint3(0., 1., 0.),
              SPoint3(-0.02, 0.5, 0.)};
  // diagonal 0-2 with node 3 almost on it: (0, 1, 2) and (2, 3, 0)
  m.triangles = {{{0, 1, 2}}, {{2, 3, 0}}};
  m.movable.assign(4, false);
  optimizableMesh locked = m;
  locked.lockedEdges.insert(std::make_pair(0, 2));
  meshOptimizationOptions o;
  o.insertAbove = 0.;
  // node 3 lies outside the unit square's input: put the input under it
  const testTriangulation wide = rectangleGrid(10, 10, 2., 2.);
  testTriangulation shifted = wide;
  for(SPoint3 &p : shifted.points) p = SPoint3(p.x() - 1., p.y() - 0.5, 0.);
  const surfaceMesh under = asSurfaceMesh(shifted);
  const closestTriangleSearch onUnder(under.points, under.triangles);
  const meshOptimizationResult free = optimizeOnInput(m, under, onUnder, o);
  EXPECT_EQ(free.flips, 1u);
  EXPECT_GT(free.minAfter, free.minBefore);
  const meshOptimizationResult kept =
    optimizeOnInput(locked, under, onUnder, o);
  EXPECT_EQ(kept.flips, 0u);
  EXPECT_EQ(locked.triangles[0], (std::array<int, 3>{{0, 1, 2}}));
}

TEST(optimizeEdgeFlips, aSliverIsFlippedAcrossARidgeWithinItsOwnTolerance)
{
  // a roof z = -|y| (a 90 degree ridge along x), a sliver (a, b, p) along
  // the ridge and a triangle (b, a, q) down one side: the flip to (p, q)
  // cuts the ridge off by 2.5 % of the new edge's length, more than the
  // 2 % a flip may; for a sliver it may by 20 %
  surfaceMesh input;
  const testTriangulation roof = rectangleGrid(8, 8, 4., 4.);
  for(const SPoint3 &x : roof.points) {
    const double y = x.y() - 2.;
    input.points.push_back(SPoint3(x.x() - 2., y, -std::fabs(y)));
  }
  input.triangles = roof.triangles;
  const closestTriangleSearch onInput(input.points, input.triangles);
  auto twoTriangles = []() {
    optimizableMesh m;
    m.points = {SPoint3(-1., 0., 0.), SPoint3(1., 0., 0.),
                SPoint3(0., 0.05, -0.05), SPoint3(0., -1., -1.)};
    m.triangles = {{{0, 1, 2}}, {{1, 0, 3}}};
    m.movable.assign(4, false);
    return m;
  };
  meshOptimizationOptions o;
  o.insertAbove = 0.;
  o.smoothPasses = 0;
  o.sliverTolerance = o.tolerance;
  optimizableMesh kept = twoTriangles();
  EXPECT_EQ(optimizeOnInput(kept, input, onInput, o).flips, 0u);
  EXPECT_LT(worstKappa(kept), 0.1);

  o.sliverTolerance = meshOptimizationOptions().sliverTolerance;
  optimizableMesh flipped = twoTriangles();
  const meshOptimizationResult r = optimizeOnInput(flipped, input, onInput, o);
  EXPECT_EQ(r.flips, 1u);
  EXPECT_GT(worstKappa(flipped), 0.5);
  EXPECT_EQ(r.againstAfter, 0u);
}

TEST(optimizeEdgeFlips, valenceFlipsUndoAFlipThatBrokeARegularGrid)
{
  // one diagonal of a regular grid flipped: its triangles are as good as
  // the others (right isosceles), so only the valences (5, 5, 7, 7) tell;
  // the valence flips put it back, without them it stays
  const int n = 6;
  optimizableMesh grid = diagonalGrid(n);
  const surfaceMesh in = asSurfaceMesh({grid.points, grid.triangles});
  const closestTriangleSearch onInput(in.points, in.triangles);
  // cell (2, 2): (a, b, d), (a, d, c) -> (a, b, c), (b, d, c)
  const int a = 2 + (n + 1) * 2, b = a + 1, c = a + n + 1, d = c + 1;
  for(auto &t : grid.triangles) {
    if(t == std::array<int, 3>{{a, b, d}})
      t = {{a, b, c}};
    else if(t == std::array<int, 3>{{a, d, c}})
      t = {{b, d, c}};
  }
  ASSERT_EQ(innerNodesNotOfValence6(grid), 4u);
  meshOptimizationOptions o;
  o.insertAbove = 0.;
  optimizableMesh without = grid;
  const meshOptimizationResult r = optimizeOnInput(grid, in, onInput, o);
  EXPECT_EQ(innerNodesNotOfValence6(grid), 0u);
  EXPECT_GE(r.flips, 1u);
  EXPECT_GE(r.minAfter, r.minBefore);
  EXPECT_LT(largestDistance(grid, onInput), 1e-12);
  o.valenceFlips = false;
  optimizeOnInput(without, in, onInput, o);
  EXPECT_EQ(innerNodesNotOfValence6(without), 4u);
}

TEST(optimizeEdgeFlips, theShortDiagonalOfAThinRhombus)
{
  // (a, b, c) and (a, c, d) across the long diagonal (a, c) of a rhombus
  // 2 x 0.4 are slivers; flipped to the short one, (d, b, c) and (a, b, d)
  const testTriangulation grid = rectangleGrid(4, 4, 2., 2.);
  testTriangulation shifted = grid;
  for(SPoint3 &p : shifted.points) p = SPoint3(p.x() - 1., p.y() - 1., 0.);
  const surfaceMesh input = asSurfaceMesh(shifted);
  const closestTriangleSearch onInput(input.points, input.triangles);
  optimizableMesh m;
  m.points = {SPoint3(-1., 0., 0.), SPoint3(0., -0.2, 0.), SPoint3(1., 0., 0.),
              SPoint3(0., 0.2, 0.)};
  m.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  m.movable.assign(4, false);
  m.against.assign(2, false);
  const double before = triangleKappa(m.points[0], m.points[1], m.points[2]);
  std::size_t searches = 0;
  localOptimizer opt(m, input, onInput, meshOptimizationOptions(), searches,
                     1000);
  EXPECT_TRUE(opt.tryFlips(0));
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{{3, 1, 2}}));
  EXPECT_EQ(m.triangles[1], (std::array<int, 3>{{0, 1, 3}}));
  // the isosceles halves: 4 sin(A) sin(B)^2 / (sin(A) + 2 sin(B)), apex
  // angle A = 2 atan(0.2), base angles B
  const double A = 2. * std::atan(0.2), B = 0.5 * (M_PI - A);
  const double after = 4. * std::sin(A) * std::sin(B) * std::sin(B) /
                       (std::sin(A) + 2. * std::sin(B));
  EXPECT_NEAR(opt.kappa(0), after, 1e-12);
  EXPECT_NEAR(opt.kappa(1), after, 1e-12);
  EXPECT_GT(after, before + minimalGain);
  // 2 x 4 searches for the new triangles' orientation, 6 distances
  EXPECT_EQ(searches, 14u);
  // flipped back would lower them: kept
  EXPECT_FALSE(opt.tryFlips(0));
  EXPECT_FALSE(opt.tryFlips(1));
}

TEST(optimizeEdgeFlips, valencesAndTheirIdeals)
{
  // inside a closed ring the ideal is 6; on the border one more than the
  // angle over 60 degrees: 120 degrees at a hexagon's corner, 3
  fanOptimizer fan;
  const localOptimizer &opt = fan.opt;
  EXPECT_EQ(opt.valenceOf(6), 6);
  EXPECT_EQ(opt.idealValenceOf(6), 6);
  EXPECT_EQ(opt.valenceOf(0), 3);
  EXPECT_EQ(opt.idealValenceOf(0), 3);
  // a regular grid: the border's inner nodes have 180 degrees, ideal 4
  optimizableMesh grid = diagonalGrid(3);
  const localOptimizer onGrid(grid, fan.input.mesh, fan.input.search,
                              meshOptimizationOptions(), fan.searches, 1000);
  EXPECT_EQ(onGrid.idealValenceOf(1), 4);
  EXPECT_EQ(onGrid.idealValenceOf(5), 6);
  EXPECT_EQ(onGrid.valenceOf(5), 6);
}
