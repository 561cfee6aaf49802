// Reparam - optimization of a new mesh on its input triangulation: flips and
// node moves raise the worst kappa and keep nodes on the input, curves and
// locked edges stay, input nodes the mesh cuts off are inserted, long edges
// split

#include <algorithm>
#include <cmath>
#include <set>
#include <gtest/gtest.h>
#include "closestTriangle.h"
#include "farInputNodes.h"
#include "longEdgeSplit.h"
#include "shortEdgeCollapse.h"
#include "meshFidelity.h"
#include "surfaceMeshOptimizer.h"
#include "testPatches.h"
#include "triangleQuality.h"
#include "triangleSplit.h"

using namespace reparam;

namespace {

  // t to optimize: nodes off the border movable
  optimizableMesh optimizable(const testTriangulation &t)
  {
    optimizableMesh m;
    m.points = t.points;
    m.triangles = t.triangles;
    m.movable.assign(t.points.size(), true);
    std::map<std::pair<int, int>, int> uses;
    for(const auto &tri : t.triangles)
      for(int k = 0; k < 3; k++)
        uses[std::make_pair(std::min(tri[k], tri[(k + 1) % 3]),
                            std::max(tri[k], tri[(k + 1) % 3]))]++;
    for(const auto &e : uses)
      if(e.second == 1)
        m.movable[e.first.first] = m.movable[e.first.second] = false;
    return m;
  }

  double largestDistance(const optimizableMesh &m,
                         const closestTriangleSearch &onInput)
  {
    double d = 0.;
    for(const SPoint3 &p : m.points)
      d = std::max(d, onInput.closest(p).distance);
    return d;
  }

  std::size_t againstCount(const optimizableMesh &m, const surfaceMesh &input,
                           const closestTriangleSearch &onInput)
  {
    std::size_t n = 0;
    for(const auto &t : m.triangles)
      n += triangleAgainstInput(m.points[t[0]], m.points[t[1]], m.points[t[2]],
                                input, onInput);
    return n;
  }

  // Each node of t lifted onto z = 0.3 sin(2 x) cos(y) (a smooth bump)
  testTriangulation bump(testTriangulation t)
  {
    for(SPoint3 &p : t.points)
      p = SPoint3(p.x(), p.y(), 0.3 * std::sin(2. * p.x()) * std::cos(p.y()));
    return t;
  }

  // An n x n grid of the unit square lifted on the bump, its nodes on the
  // input triangulation (searched by onInput)
  optimizableMesh bumpGridOnInput(int n, const closestTriangleSearch &onInput)
  {
    optimizableMesh m = optimizable(bump(rectangleGrid(n, n, 1., 1.)));
    for(SPoint3 &p : m.points) p = onInput.closest(p).point;
    return m;
  }

  // A roof over t: two planes of the given slope meeting at a ridge along
  // x = 0.5
  testTriangulation roof(testTriangulation t, double slope)
  {
    for(SPoint3 &p : t.points)
      p = SPoint3(p.x(), p.y(), slope * (0.5 - std::fabs(p.x() - 0.5)));
    return t;
  }

  // The largest and the mean distance to a mesh of the input's nodes on
  // the ridge (x = 0.5) with y in (from, to)
  double ridgeDistance(const optimizableMesh &mesh, const surfaceMesh &input,
                       double from, double to, double *mean = nullptr)
  {
    const closestTriangleSearch onMesh(mesh.points, mesh.triangles);
    double largest = 0., sum = 0.;
    int count = 0;
    for(const SPoint3 &p : input.points)
      if(std::fabs(p.x() - 0.5) < 1e-9 && p.y() > from && p.y() < to) {
        const double d = onMesh.closest(p).distance;
        largest = std::max(largest, d);
        sum += d;
        count++;
      }
    if(mean) *mean = count ? sum / count : 0.;
    return largest;
  }

} // namespace

TEST(surfaceMeshOptimizer, slivers)
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

TEST(surfaceMeshOptimizer, neverLowersTheWorstKappaNorLeavesTheInput)
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

TEST(surfaceMeshOptimizer, aFoldIsRepairedLocallyTheRestUnchanged)
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

TEST(surfaceMeshOptimizer, lockedEdgesAreNotFlipped)
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

TEST(surfaceMeshOptimizer, inputNodesTheMeshCutsOffAreInserted)
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

TEST(surfaceMeshOptimizer, longEdgesAreSplitOnTheInput)
{
  // A 4 x 4 grid of the bump asked at a size of a third of its cells: the
  // inner edges longer than 1.6 times the size are split, at points of the
  // input, in rounds until none is left or nothing can be split
  const testTriangulation input = bump(rectangleGrid(60, 60, 1., 1.));
  const surfaceMesh in = asSurfaceMesh(input);
  const closestTriangleSearch onInput(in.points, in.triangles);
  optimizableMesh m = optimizable(bump(rectangleGrid(4, 4, 1., 1.)));
  m.size.assign(m.points.size(), 0.25 / 3.);
  m.landing.assign(m.points.size(), -1);
  m.inputNode.assign(m.points.size(), -1);
  const std::size_t nodes = m.points.size();
  const std::size_t first = splitLongEdges(m, in, onInput, false, 1.6);
  // inner edges of the 4 x 4 grid: 33 - 16 on the border; one per triangle
  // and neighbours per round
  EXPECT_GT(first, 2u);
  EXPECT_LE(first, 17u);
  EXPECT_EQ(m.points.size(), nodes + first);
  EXPECT_EQ(m.size.size(), m.points.size());
  for(std::size_t i = nodes; i < m.points.size(); i++) {
    EXPECT_TRUE(m.movable[i]);
    EXPECT_LT(onInput.closest(m.points[i]).distance, 1e-9);
    EXPECT_NEAR(m.size[i], 0.25 / 3., 1e-12);
  }
  EXPECT_EQ(m.triangles.size(), 32u + 2 * first);
  EXPECT_EQ(againstCount(m, in, onInput), 0u);
  // no sizes: nothing split
  optimizableMesh unsized = optimizable(bump(rectangleGrid(4, 4, 1., 1.)));
  EXPECT_EQ(splitLongEdges(unsized, in, onInput, false, 1.6), 0u);
}

TEST(surfaceMeshOptimizer, anEdgeThatCutsARidgeOffIsSplitWhateverItsHalves)
{
  // A strip 0.4 x 0.2 meshed by two triangles, their diagonal across
  // the strip's middle line; the input is the strip folded along that line
  // up to a ridge of height `ridge`. The diagonal's halves would be thinner
  // than the triangles there: split only when its chord passes farther
  // from the input than a tenth of its length
  auto splitsWithRidge = [](double ridge, optimizableMesh &m) {
    testTriangulation roof;
    for(double x : {0., 0.2, 0.4})
      for(double y : {-0.1, 0., 0.1})
        roof.points.push_back(SPoint3(x, y, y == 0. ? ridge : 0.));
    for(int i = 0; i < 2; i++)
      for(int j = 0; j < 2; j++) {
        const int a = 3 * i + j, b = a + 3, c = a + 4, d = a + 1;
        roof.triangles.push_back({{a, b, c}});
        roof.triangles.push_back({{a, c, d}});
      }
    const surfaceMesh in = asSurfaceMesh(roof);
    const closestTriangleSearch onInput(in.points, in.triangles);
    testTriangulation strip;
    strip.points = {SPoint3(0., -0.1, 0.), SPoint3(0.4, -0.1, 0.),
                    SPoint3(0.4, 0.1, 0.), SPoint3(0., 0.1, 0.)};
    strip.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    m = optimizable(strip);
    m.size.assign(m.points.size(), 0.2);
    m.landing.assign(m.points.size(), -1);
    m.inputNode.assign(m.points.size(), -1);
    return splitLongEdges(m, in, onInput, false, 1.6);
  };
  optimizableMesh flat, folded;
  // flat: the halves are worse than the two triangles
  EXPECT_EQ(splitsWithRidge(0., flat), 0u);
  // a ridge 0.3 high: the diagonal (0.45 long) passes 0.095 under the roof
  EXPECT_EQ(splitsWithRidge(0.3, folded), 1u);
  ASSERT_EQ(folded.points.size(), 5u);
  // on the roof, at the input point closest to the diagonal's midpoint
  const SPoint3 &p = folded.points[4];
  EXPECT_NEAR(p.z(), 0.3 * (1. - std::fabs(p.y()) / 0.1), 1e-9);
  EXPECT_GT(p.z(), 0.);
  EXPECT_EQ(folded.triangles.size(), 4u);
}

namespace {

  // A hexagon of radius 1/6 around node a on the ridge of a roof of slope 1
  // (ridge along x = 0.5), its corners fixed, and node b 0.05 from a down
  // the slope (x < 0.5): a collapse of the short edge (a, b) takes a off
  // the ridge if a may move
  optimizableMesh ridgeFan(bool aMovable)
  {
    optimizableMesh m;
    auto onRoof = [](double x, double y) {
      return SPoint3(x, y, 0.5 - std::fabs(x - 0.5));
    };
    for(int k = 0; k < 6; k++)
      m.points.push_back(onRoof(0.5 + std::cos(k * M_PI / 3.) / 6.,
                                0.5 + std::sin(k * M_PI / 3.) / 6.));
    const int a = 6, b = 7;
    m.points.push_back(onRoof(0.5, 0.5));
    m.points.push_back(onRoof(0.45, 0.5));
    m.triangles = {{{a, 0, 1}}, {{a, 1, 2}}, {{a, 2, b}}, {{b, 2, 3}},
                   {{a, b, 4}}, {{b, 3, 4}}, {{a, 4, 5}}, {{a, 5, 0}}};
    m.movable.assign(8, false);
    m.movable[a] = aMovable;
    m.movable[b] = true;
    m.size.assign(8, 0.2); // edges up to 1.4 times that: 0.24 across
                           // the fan (the slope makes 0.236)
    m.landing.assign(8, -1);
    m.inputNode.assign(8, -1);
    return m;
  }

} // namespace

TEST(surfaceMeshOptimizer, collapsesKeepTheInputNodesUnderThem)
{
  const surfaceMesh in = asSurfaceMesh(roof(rectangleGrid(60, 60, 1., 1.), 1.));
  const closestTriangleSearch onInput(in.points, in.triangles);
  const double tolerance = 0.08, size = 0.2;
  // both ends movable: they would meet halfway, on the slope, and the
  // triangles from there across the ridge pass 0.035 under its node at a,
  // though the point removed stays on them: not collapsed
  optimizableMesh m = ridgeFan(true);
  EXPECT_EQ(collapseShortEdges(m, in, onInput, false, 0.6, tolerance), 0u);
  EXPECT_EQ(m.points.size(), 8u);
  EXPECT_LE(ridgeDistance(m, in, 0.499, 0.501), tolerance * size);
  // a fixed on the ridge: b goes onto it, the ridge stays
  m = ridgeFan(false);
  EXPECT_EQ(collapseShortEdges(m, in, onInput, false, 0.6, tolerance), 1u);
  EXPECT_EQ(m.points.size(), 7u);
  EXPECT_LT(ridgeDistance(m, in, 0.499, 0.501), 1e-12);
}

TEST(surfaceMeshOptimizer, shortEdgesAreCollapsedKeepingTheMeshValid)
{
  // A 12 x 12 grid of the bump asked at twice its cell size: inner edges
  // shorter than 0.6 times the size (the cells' sides) are collapsed; the
  // border stays, the mesh stays a valid manifold along the input, and the
  // origins say which points and triangles are left
  const testTriangulation input = bump(rectangleGrid(60, 60, 1., 1.));
  const surfaceMesh in = asSurfaceMesh(input);
  const closestTriangleSearch onInput(in.points, in.triangles);
  optimizableMesh m = bumpGridOnInput(12, onInput);
  const std::vector<SPoint3> before = m.points;
  const std::vector<bool> movable = m.movable;
  m.size.assign(m.points.size(), 2. / 12.);
  m.landing.assign(m.points.size(), -1);
  m.inputNode.assign(m.points.size(), -1);
  for(std::size_t i = 0; i < m.points.size(); i++) m.origin.push_back((int)i);
  for(std::size_t t = 0; t < m.triangles.size(); t++)
    m.triangleOrigin.push_back((int)t);
  std::vector<int> kept;
  const std::size_t collapsed =
    collapseShortEdges(m, in, onInput, false, 0.6, 0.08, &kept);
  EXPECT_GT(collapsed, 10u);
  EXPECT_EQ(m.points.size(), 169u - collapsed);
  EXPECT_EQ(m.triangles.size(), 288u - 2 * collapsed);
  EXPECT_EQ(m.origin.size(), m.points.size());
  EXPECT_EQ(m.triangleOrigin.size(), m.triangles.size());
  EXPECT_FALSE(kept.empty());
  // every fixed (border) point is still there, where it was
  std::vector<bool> left(before.size(), false);
  for(std::size_t i = 0; i < m.points.size(); i++) {
    ASSERT_GE(m.origin[i], 0);
    EXPECT_FALSE(left[m.origin[i]]); // each origin once
    left[m.origin[i]] = true;
    if(!movable[m.origin[i]])
      EXPECT_EQ(m.points[i].distance(before[m.origin[i]]), 0.);
    EXPECT_LT(onInput.closest(m.points[i]).distance, 1e-9);
  }
  for(std::size_t i = 0; i < before.size(); i++)
    if(!movable[i]) EXPECT_TRUE(left[i]);
  // a manifold: inner edges on two triangles, the border's 48 on one
  std::map<std::pair<int, int>, int> uses;
  for(const auto &t : m.triangles)
    for(int k = 0; k < 3; k++)
      uses[std::make_pair(std::min(t[k], t[(k + 1) % 3]),
                          std::max(t[k], t[(k + 1) % 3]))]++;
  std::size_t border = 0;
  for(const auto &e : uses) {
    EXPECT_LE(e.second, 2);
    border += e.second == 1;
  }
  EXPECT_EQ(border, 48u);
  EXPECT_EQ(againstCount(m, in, onInput), 0u);
  // no edge longer than 1.4 times the size
  for(const auto &e : uses)
    EXPECT_LE(m.points[e.first.first].distance(m.points[e.first.second]),
              1.4 * 2. / 12. + 1e-12);
}

namespace {

  double meanKappa(const optimizableMesh &m)
  {
    double sum = 0.;
    for(const std::array<int, 3> &t : m.triangles)
      sum += triangleKappa(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
    return sum / m.triangles.size();
  }

} // namespace

TEST(surfaceMeshOptimizer, smoothingRaisesTheMeanKappaNotTheWorst)
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

TEST(surfaceMeshOptimizer, smoothingKeepsARidgeTheMeshHolds)
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

TEST(surfaceMeshOptimizer, trianglesKnownAlongTheInputAreNotTested)
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

TEST(surfaceMeshOptimizer, aSliverIsFlippedAcrossARidgeWithinItsOwnTolerance)
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

TEST(surfaceMeshOptimizer, valenceFlipsUndoAFlipThatBrokeARegularGrid)
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
    if(t == std::array<int, 3>{{a, b, d}}) t = {{a, b, c}};
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
