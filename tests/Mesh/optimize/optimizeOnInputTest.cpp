// Reparam - optimization of a new mesh on its input triangulation, end to
// end: flips and node moves raise the worst kappa and keep nodes on the
// input, a fold is repaired where it is, input nodes the mesh cuts off are
// inserted, triangles the caller knows along the input are not tested

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include "closestTriangle.h"
#include "optimizeOnInput.h"
#include "optimizerTestMeshes.h"
#include "testPatches.h"

using namespace optimizeTest;

TEST(optimizeOnInput, slivers)
{
  // An 8 x 8 grid lifted on a bump, three of its inner nodes pushed to 2 %
  // of a cell from a neighbour (slivers and needles around each); the input
  // is a fine triangulation of the same bump. The optimizer must get rid of
  // them and leave every node on the input, every triangle along it
  const testTriangulation input = bump(rectangleGrid(60, 60, 1., 1.));
  const surfaceMesh in = asSurfaceMesh(input);
  const closestTriangleSearch onInput(in.points, in.triangles);
  testTriangulation grid = rectangleGrid(8, 8, 1., 1.);
  const double h = 1. / 8.;
  for(int node : {2 * 9 + 2, 3 * 9 + 5, 6 * 9 + 3}) {
    SPoint3 &p = grid.points[node];
    p = SPoint3(p.x() - 0.98 * h, p.y(), 0.);
  }
  optimizableMesh m = optimizable(bump(grid));
  // on the input's triangles, not only on the bump
  for(SPoint3 &p : m.points) p = onInput.closest(p).point;
  const std::vector<SPoint3> before = m.points;
  const double worstBefore = worstKappa(m);
  ASSERT_LT(worstBefore, 0.05);
  meshOptimizationOptions o;
  o.insertAbove = 0.; // the mesh's nodes are on the input already
  const meshOptimizationResult r = optimizeOnInput(m, in, onInput, o);
  EXPECT_NEAR(r.minBefore, worstBefore, 1e-12);
  EXPECT_GT(r.minAfter, 0.5);
  EXPECT_NEAR(worstKappa(m), r.minAfter, 1e-12);
  EXPECT_GT(r.moves, 0u);
  EXPECT_EQ(r.belowAfter, 0u);
  EXPECT_GE(r.belowBefore, 6u);
  EXPECT_LT(largestDistance(m, onInput), 1e-9);
  EXPECT_EQ(againstCount(m, in, onInput), 0u);
  for(std::size_t i = 0; i < m.points.size(); i++) {
    if(!m.movable[i]) EXPECT_EQ(m.points[i].distance(before[i]), 0.);
    if(m.landing[i] >= 0) {
      // the landing triangle holds the node
      const auto &t = in.triangles[m.landing[i]];
      const SPoint3 c = closestPointOnTriangle(
        m.points[i], in.points[t[0]], in.points[t[1]], in.points[t[2]]);
      EXPECT_LT(c.distance(m.points[i]), 1e-9);
    }
  }
}

TEST(optimizeOnInput, neverLowersTheWorstKappaNorLeavesTheInput)
{
  // Jittered grids of several seeds on the bump: whatever the start, the
  // worst kappa does not drop, nodes stay on the input, no triangle turns
  for(unsigned seed = 1; seed <= 6; seed++) {
    const testTriangulation input = bump(rectangleGrid(50, 50, 1., 1.));
    const surfaceMesh in = asSurfaceMesh(input);
    const closestTriangleSearch onInput(in.points, in.triangles);
    optimizableMesh m = optimizable(bump(jitteredGrid(10, 0.95, seed)));
    // the jittered nodes are on the bump, not on its triangulation: project
    for(SPoint3 &p : m.points) p = onInput.closest(p).point;
    const double before = worstKappa(m);
    meshOptimizationOptions o;
    o.insertAbove = 0.;
    const meshOptimizationResult r = optimizeOnInput(m, in, onInput, o);
    EXPECT_GE(r.minAfter, before) << "seed " << seed;
    EXPECT_LT(largestDistance(m, onInput), 1e-9) << "seed " << seed;
    EXPECT_EQ(againstCount(m, in, onInput), 0u) << "seed " << seed;
    EXPECT_EQ(m.triangles.size(), 200u); // no node added
  }
}

TEST(optimizeOnInput, aFoldIsRepairedLocallyTheRestUnchanged)
{
  // A 12 x 12 grid on the bump with two neighbouring inner nodes crossed
  // over each other (a fold no flip nor single move undoes): the
  // optimization leaves nothing against the input and changes nothing far
  // from the fold (the grid's triangles are above the target kappa)
  const testTriangulation input = bump(rectangleGrid(60, 60, 1., 1.));
  const surfaceMesh in = asSurfaceMesh(input);
  const closestTriangleSearch onInput(in.points, in.triangles);
  optimizableMesh m = bumpGridOnInput(12, onInput);
  const int a = 6 * 13 + 6, b = 6 * 13 + 7;
  std::swap(m.points[a], m.points[b]);
  const std::vector<SPoint3> before = m.points;
  m.size.assign(m.points.size(), 1. / 12.);
  meshOptimizationOptions o;
  o.insertAbove = 0.;
  // the grid's inner nodes have valence 4 and 8: the valence flips of the
  // smoothing sweeps would even them out everywhere
  o.valenceFlips = false;
  const meshOptimizationResult r = optimizeOnInput(m, in, onInput, o);
  EXPECT_GT(r.againstBefore, 0u);
  EXPECT_EQ(r.againstAfter, 0u);
  EXPECT_EQ(againstCount(m, in, onInput), 0u);
  EXPECT_GT(r.minAfter, 0.1);
  EXPECT_LT(largestDistance(m, onInput), 1e-9);
  // every node kept more than 3 cells from the fold stays where it was
  const SPoint3 fold = (before[a] + before[b]) * 0.5;
  std::size_t far = 0, moved = 0;
  for(std::size_t i = 0; i < m.points.size(); i++) {
    const int origin = m.origin[i];
    if(origin < 0 || before[origin].distance(fold) < 3. / 12.) continue;
    far++;
    moved += m.points[i].distance(before[origin]) > 1e-12;
  }
  EXPECT_GT(far, 120u);
  EXPECT_EQ(moved, 0u);
}

TEST(optimizeOnInput, inputNodesTheMeshCutsOffAreInserted)
{
  // The input: a roof, two planes meeting at a ridge along x = 0.5 (77
  // degrees between their normals: a sharp crease the layout merged into a
  // patch); the mesh: a coarse grid whose nodes miss the ridge (7 cells),
  // so its triangles cut across it
  const testTriangulation input = roof(rectangleGrid(40, 40, 1., 1.), 0.8);
  const surfaceMesh in = asSurfaceMesh(input);
  const closestTriangleSearch onInput(in.points, in.triangles);
  optimizableMesh m = optimizable(roof(rectangleGrid(7, 7, 1., 1.), 0.8));
  const std::size_t nodes = m.points.size();
  // the largest and mean distance of the ridge's input nodes to the mesh
  auto cutOff = [&](const optimizableMesh &mesh, double &mean) {
    return ridgeDistance(mesh, in, 0.1, 0.9, &mean);
  };
  double meanBefore, meanAfter;
  const double before = cutOff(m, meanBefore);
  ASSERT_GT(before, 0.05); // 0.057: the ridge is 0.4 high, the chord 0.343
  const meshOptimizationResult r = optimizeOnInput(m, in, onInput);
  const double after = cutOff(m, meanAfter);
  // at most one node per triangle and its neighbours per round, 3 rounds
  EXPECT_GE(r.inserted, 6u);
  // (smoothing may leave the input it held by 2 % of the triangles' size:
  // 0.057 -> 0.0577 here)
  EXPECT_LE(after, before + 0.02 * std::sqrt(2.) / 7.);
  EXPECT_LT(meanAfter, 0.5 * meanBefore); // 0.057 -> 0.019
  EXPECT_EQ(m.points.size(), nodes + r.inserted - r.snapped + r.splits);
  for(std::size_t i = 0; i < m.points.size(); i++)
    if(m.inputNode[i] >= 0) {
      EXPECT_FALSE(m.movable[i]); // it marks the ridge
      EXPECT_EQ(m.points[i].distance(in.points[m.inputNode[i]]), 0.);
    }
  EXPECT_EQ(againstCount(m, in, onInput), 0u);
  EXPECT_GE(r.minAfter, 0.5); // the flips around the new nodes
}

TEST(optimizeOnInput, trianglesKnownAlongTheInputAreNotTested)
{
  // A grid with one triangle turned over: counted against the input, unless
  // the caller says it lies along
  const testTriangulation input = bump(rectangleGrid(30, 30, 1., 1.));
  const surfaceMesh in = asSurfaceMesh(input);
  const closestTriangleSearch onInput(in.points, in.triangles);
  optimizableMesh m = bumpGridOnInput(6, onInput);
  std::swap(m.triangles[10][1], m.triangles[10][2]);
  meshOptimizationOptions o;
  o.insertAbove = 0.;
  o.smoothPasses = 0;
  optimizableMesh trusted = m;
  EXPECT_EQ(optimizeOnInput(m, in, onInput, o).againstBefore, 1u);
  o.knownAlong.assign(trusted.triangles.size(), false);
  o.knownAlong[10] = true;
  EXPECT_EQ(optimizeOnInput(trusted, in, onInput, o).againstBefore, 0u);
}
