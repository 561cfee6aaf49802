// Reparam - flips, folds, their repair and the automatic chain

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include "bijectivityCheck.h"
#include "conformalMap.h"
#include "flipRepair.h"
#include "harmonicMap.h"
#include "mapChain.h"
#include "meanValueMap.h"
#include "reparamOptions.h"
#include "spectralConformalMap.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  bool intersect(double ax, double ay, double bx, double by, double cx,
                 double cy, double dx, double dy)
  {
    const double a[2] = {ax, ay}, b[2] = {bx, by}, c[2] = {cx, cy},
                 d[2] = {dx, dy};
    bool r = segmentsIntersect(a, b, c, d);
    // symmetric in the two segments and in their ends
    EXPECT_EQ(r, segmentsIntersect(c, d, a, b));
    EXPECT_EQ(r, segmentsIntersect(b, a, d, c));
    return r;
  }

  // A loop's uv: the nodes of a closed polyline, as a patch's boundary
  discretePatch loopPatch(const std::vector<std::array<double, 2> > &xy,
                          std::vector<double> &uv)
  {
    discretePatch p;
    std::vector<int> loop;
    for(std::size_t i = 0; i < xy.size(); i++) {
      loop.push_back((int)i);
      uv.push_back(xy[i][0]);
      uv.push_back(xy[i][1]);
    }
    p.boundaryLoops.push_back(loop);
    return p;
  }

} // namespace

TEST(bijectivity, segmentIntersectionCases)
{
  EXPECT_TRUE(intersect(0, 0, 2, 2, 0, 2, 2, 0)); // crossing
  EXPECT_FALSE(intersect(0, 0, 1, 0, 0, 1, 1, 1)); // parallel
  EXPECT_FALSE(intersect(0, 0, 1, 1, 2, 0, 3, -5)); // apart
  EXPECT_TRUE(intersect(0, 0, 2, 0, 1, 0, 1, 5)); // T: end on the other
  EXPECT_TRUE(intersect(0, 0, 1, 0, 1, 0, 2, 3)); // common end point
  EXPECT_TRUE(intersect(0, 0, 2, 0, 1, 0, 3, 0)); // collinear overlap
  EXPECT_TRUE(intersect(0, 0, 2, 0, 0.5, 0, 1, 0)); // collinear, inside
  EXPECT_FALSE(intersect(0, 0, 1, 0, 2, 0, 3, 0)); // collinear, apart
  EXPECT_FALSE(intersect(0, 0, 1, 0, 1.5, 1e-300, 3, 1)); // near miss
  // exact arithmetic: a crossing at 1e-17 from an end is still one
  EXPECT_TRUE(intersect(0, 0, 1, 1, 1 - 1e-17, 1, 1, 1 - 1e-16));
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1};
  EXPECT_GT(orientation2d(a, b, c), 0.);
  EXPECT_LT(orientation2d(a, c, b), 0.);
}

TEST(bijectivity, foldsOfBoundaryLoops)
{
  std::vector<double> uv;
  discretePatch square =
    loopPatch({{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}}, uv);
  EXPECT_EQ(countBoundaryFolds(square, uv), 0u);
  // a bow tie: edges 1-2 and 3-0 cross
  uv.clear();
  discretePatch bowTie =
    loopPatch({{{0, 0}}, {{1, 0}}, {{0, 1}}, {{1, 1}}}, uv);
  EXPECT_EQ(countBoundaryFolds(bowTie, uv), 1u);
  // the crossing pair named by the first node of each edge (1-2, 3-0)
  std::vector<std::array<int, 2> > pairs;
  EXPECT_EQ(countBoundaryFolds(bowTie, uv, 0., &pairs), 1u);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(std::min(pairs[0][0], pairs[0][1]), 1);
  EXPECT_EQ(std::max(pairs[0][0], pairs[0][1]), 3);
  // a long loop (a circle of 4000 nodes) wound twice crosses itself: the
  // quadtree finds every crossing of the second turn with the first
  uv.clear();
  std::vector<std::array<double, 2> > spiral;
  for(int i = 0; i < 4000; i++) {
    double t = 4. * M_PI * i / 4000., r = 1. + 0.2 * t;
    spiral.push_back({{r * std::cos(t), r * std::sin(t)}});
  }
  discretePatch wound = loopPatch(spiral, uv);
  // the closing edge from the outer end back to the start crosses the first
  // turn once
  EXPECT_EQ(countBoundaryFolds(wound, uv), 1u);
}

TEST(bijectivity, foldsWithinADistanceAreNotCounted)
{
  // a square whose bottom side doubles back by `back` at its middle: edges
  // 1-2 and 3-4 cross, node 3 at `back` from edge 1-2
  for(double back : {1e-9, 1e-3}) {
    std::vector<double> uv;
    const discretePatch p =
      loopPatch({{{0, 0}},
                 {{0.5 + back, 0}},
                 {{0.5 + back, 2 * back}},
                 {{0.5, 2 * back}},
                 {{0.5 - back, -back}},
                 {{1, 0}},
                 {{1, 1}},
                 {{0, 1}}},
                uv);
    SCOPED_TRACE(back);
    EXPECT_GE(countBoundaryFolds(p, uv), 1u);
    EXPECT_EQ(countBoundaryFolds(p, uv, 1e-6), back < 1e-6 ? 0u : 1u);
  }
}

TEST(bijectivity, foldsOfALoopMostlyCrushedToAPoint)
{
  // 19990 nodes on an arc of radius 1e-9, closed by 10 nodes at radius 1:
  // no crossing; the quadtree splits the crushed part down to its scale
  // (binning by the whole extent would test its 2e8 pairs)
  std::vector<std::array<double, 2> > xy;
  for(int i = 0; i < 19990; i++) {
    double t = 1.9 * M_PI * i / 19989.;
    xy.push_back({{1e-9 * std::cos(t), 1e-9 * std::sin(t)}});
  }
  for(int i = 0; i < 10; i++) {
    double t = 1.9 * M_PI + 0.09 * M_PI * i / 9.;
    xy.push_back({{std::cos(t), std::sin(t)}});
  }
  std::vector<double> uv;
  discretePatch crushed = loopPatch(xy, uv);
  EXPECT_EQ(countBoundaryFolds(crushed, uv), 0u);
  // moving one crushed node across the arc's chord makes it cross
  uv[2 * 5000] = -uv[2 * 5000];
  uv[2 * 5000 + 1] = -uv[2 * 5000 + 1];
  EXPECT_GE(countBoundaryFolds(crushed, uv), 1u);
}

TEST(bijectivity, identityAndMirrorOfAPlanarPatch)
{
  testTriangulation t = polarDisk(5, 20);
  discretePatch p = makePatchOrDie(t);
  std::vector<double> uv;
  for(const SPoint3 &x : t.points) {
    uv.push_back(x.x());
    uv.push_back(x.y());
  }
  bijectivityReport r = checkBijectivity(p, uv);
  EXPECT_TRUE(r.bijective());
  EXPECT_EQ(r.orientation, 1);
  EXPECT_TRUE(r.degenerateTriangles.empty());
  for(std::size_t i = 1; i < uv.size(); i += 2) uv[i] = -uv[i];
  r = checkBijectivity(p, uv);
  EXPECT_TRUE(r.bijective());
  EXPECT_EQ(r.orientation, -1);
  // one node crushed onto its neighbour: degenerate, not flipped
  const auto &tri = p.triangles[7];
  uv[2 * tri[0]] = uv[2 * tri[1]] + 1e-14 * (uv[2 * tri[0]] - uv[2 * tri[1]]);
  uv[2 * tri[0] + 1] =
    uv[2 * tri[1] + 1] + 1e-14 * (uv[2 * tri[0] + 1] - uv[2 * tri[1] + 1]);
  r = checkBijectivity(p, uv);
  EXPECT_TRUE(r.flippedTriangles.empty());
  EXPECT_GE(r.degenerateTriangles.size(), 1u);
}

TEST(bijectivity, kernelOfAStar)
{
  // a regular hexagon's star: its kernel is the hexagon
  std::vector<std::array<double, 4> > edges;
  for(int k = 0; k < 6; k++) {
    double a = M_PI / 3 * k, b = M_PI / 3 * (k + 1);
    edges.push_back({{std::cos(a), std::sin(a), std::cos(b), std::sin(b)}});
  }
  auto kernel = starKernel(edges, {{-1, -1, 1, 1}}, 1);
  ASSERT_GE(kernel.size(), 6u); // with points repeated where it touches
  double area2 = 0.;
  for(std::size_t i = 0; i < kernel.size(); i++) {
    const auto &s = kernel[i], &t = kernel[(i + 1) % kernel.size()];
    area2 += s[0] * t[1] - t[0] * s[1];
  }
  EXPECT_NEAR(area2 / 2., 3. * std::sqrt(3.) / 2., 1e-12);
  // seen from the other side: nothing
  EXPECT_TRUE(starKernel(edges, {{-1, -1, 1, 1}}, -1).empty());
}

// The sliver fixture of the maps: the harmonic map flips, the cavity check
// repairs it, without moving the boundary
TEST(bijectivity, cavityCheckRepairsTheHarmonicMapOnSlivers)
{
  discretePatch p = makePatchOrDie(jitteredGrid(10, 0.95, 2));
  patchMap h = harmonicMap(p);
  ASSERT_TRUE(h.error.ok());
  bijectivityReport before = checkBijectivity(p, h.uv);
  ASSERT_GE(before.flippedTriangles.size(), 1u);
  std::vector<double> uv = h.uv;
  flipRepairResult r = repairFlips(p, uv, before.orientation, false);
  EXPECT_EQ(r.flippedBefore, before.flippedTriangles.size());
  EXPECT_EQ(r.flippedAfter, 0u);
  EXPECT_GE(r.movedNodes, 1);
  EXPECT_TRUE(checkBijectivity(p, uv).bijective());
  for(int i : p.boundaryLoops[p.outerLoop]) {
    EXPECT_EQ(uv[2 * i], h.uv[2 * i]);
    EXPECT_EQ(uv[2 * i + 1], h.uv[2 * i + 1]);
  }
}

// LSCM with the farthest pins on a strongly curved saddle (the fixture of
// the maps) flips an interior triangle and also folds at an end: the repair
// removes the flip, the fold stays (the automatic chain changes map)
TEST(bijectivity, repairRemovesLscmFlipsButNotItsFold)
{
  discretePatch p = makePatchOrDie(saddleStrip(60, 10, 6., 3.));
  patchMap m = conformalMap(p);
  ASSERT_TRUE(m.error.ok());
  bijectivityReport before = checkBijectivity(p, m.uv);
  ASSERT_GE(before.flippedTriangles.size(), 1u);
  ASSERT_GE(before.numFolds, 1u);
  flipRepairResult r = repairFlips(p, m.uv, before.orientation, true);
  EXPECT_EQ(r.flippedAfter, 0u);
  bijectivityReport after = checkBijectivity(p, m.uv);
  EXPECT_TRUE(after.flippedTriangles.empty());
  EXPECT_EQ(after.numFolds, before.numFolds);
}

// Boundary check (Fig. 11): a free boundary node pushed inside, past its
// interior neighbour, comes back along its projection onto the segment of
// its two boundary neighbours
TEST(bijectivity, boundaryCheckMovesAFreeBoundaryNodeBack)
{
  testTriangulation t = rectangleGrid(4, 4, 1., 1.);
  discretePatch p = makePatchOrDie(t);
  std::vector<double> uv;
  int bottomMiddle = -1;
  for(std::size_t i = 0; i < t.points.size(); i++) {
    uv.push_back(t.points[i].x());
    uv.push_back(t.points[i].y());
    if(std::fabs(t.points[i].x() - 0.5) < 1e-12 && t.points[i].y() == 0.)
      bottomMiddle = (int)i;
  }
  ASSERT_GE(bottomMiddle, 0);
  uv[2 * bottomMiddle + 1] = 0.3; // above its neighbour at (0.5, 0.25)
  bijectivityReport before = checkBijectivity(p, uv);
  ASSERT_GE(before.flippedTriangles.size(), 1u);
  // with a fixed boundary, the boundary node may not move: the interior one
  // cannot fix the flip alone
  std::vector<double> fixed = uv;
  flipRepairResult r0 = repairFlips(p, fixed, 1, false);
  EXPECT_EQ(fixed[2 * bottomMiddle + 1], 0.3);
  flipRepairResult r = repairFlips(p, uv, 1, true);
  EXPECT_EQ(r.flippedAfter, 0u);
  EXPECT_LT(r.flippedAfter, r0.flippedBefore);
  EXPECT_TRUE(checkBijectivity(p, uv).bijective());
  // moved along the projection line x = 0.5, below the interior neighbour
  EXPECT_NEAR(uv[2 * bottomMiddle], 0.5, 1e-15);
  EXPECT_LT(uv[2 * bottomMiddle + 1], 0.25);
  EXPECT_GE(uv[2 * bottomMiddle + 1], 0.);
}

// One and a half turns of a ramp: the conformal maps fold (the image of the
// boundary crosses itself), the automatic chain ends on the mean value map,
// one-to-one
TEST(bijectivity, automaticChainEndsOneToOneOnAFoldingRamp)
{
  discretePatch p = makePatchOrDie(helicoidStrip(120, 6, 1.5, 1., 2., 0.05));
  patchMap lscm = conformalMap(p), spectral = spectralConformalMap(p);
  ASSERT_TRUE(lscm.error.ok() && spectral.error.ok());
  EXPECT_GE(checkBijectivity(p, lscm.uv).numFolds, 1u);
  EXPECT_GE(checkBijectivity(p, spectral.uv).numFolds, 1u);

  checkedMap c = runMapChain(p, mapChain(6), true);
  ASSERT_EQ(c.attempts.size(), 3u);
  EXPECT_GE(c.attempts[0].foldsAfter, 1u);
  EXPECT_GE(c.attempts[1].foldsAfter, 1u);
  // where they fold: pairs of boundary nodes (at most maxFoldPairs), for the
  // layout's cut; the mean value map, one-to-one, has none
  for(int a = 0; a < 2; a++) {
    const mapAttempt &m = c.attempts[a];
    EXPECT_EQ(m.foldPairs.size(), std::min(m.foldsAfter, maxFoldPairs)) << a;
    for(const auto &pr : m.foldPairs)
      for(int n : pr) {
        EXPECT_GE(n, 0);
        EXPECT_LT(n, (int)p.points.size());
      }
  }
  EXPECT_TRUE(c.attempts[2].foldPairs.empty());
  EXPECT_TRUE(c.attempts[2].failedNodes.empty());
  EXPECT_TRUE(c.bijective);
  EXPECT_EQ(c.chosen, 2);
  EXPECT_EQ(c.attempts[2].map, (int)compoundParametrization::meanValue);
  EXPECT_TRUE(checkBijectivity(p, c.map.uv).bijective());
}

TEST(bijectivity, aMapLeftFlippedNamesTheNodesOfItsFlippedTriangles)
{
  // a step whose map turns over the triangle at one corner of a 3x3 grid
  // (its corner node moved across the diagonal), with no repair: the
  // attempt names that triangle's nodes
  discretePatch p = makePatchOrDie(rectangleGrid(3, 3, 1., 1.));
  int corner = -1; // the node at (0, 0)
  for(std::size_t i = 0; i < p.points.size(); i++)
    if(p.points[i].x() == 0. && p.points[i].y() == 0.) corner = (int)i;
  ASSERT_GE(corner, 0);
  mapStep turned{(int)compoundParametrization::barycentric,
                 [&](const discretePatch &q) {
                   patchMap m;
                   for(const SPoint3 &x : q.points) {
                     m.uv.push_back(x.x());
                     m.uv.push_back(x.y());
                   }
                   m.uv[2 * corner] = m.uv[2 * corner + 1] = 0.5;
                   return m;
                 },
                 false};
  checkedMap c = runMapChain(p, {turned}, false);
  ASSERT_EQ(c.attempts.size(), 1u);
  const mapAttempt &a = c.attempts[0];
  ASSERT_GE(a.flippedAfter, 1u);
  std::vector<int> expected;
  for(const auto &t : p.triangles)
    if(std::find(t.begin(), t.end(), corner) != t.end())
      expected.insert(expected.end(), t.begin(), t.end());
  std::sort(expected.begin(), expected.end());
  expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
  // the flipped triangles are those at the corner node
  EXPECT_EQ(a.failedNodes, expected);
  EXPECT_TRUE(std::is_sorted(a.failedNodes.begin(), a.failedNodes.end()));
}

TEST(bijectivity, automaticChainStopsAtTheSpectralMapWhenItIsOneToOne)
{
  discretePatch p = makePatchOrDie(sphericalCap(8, 32, 1.));
  checkedMap c = runMapChain(p, mapChain(6), true);
  ASSERT_EQ(c.attempts.size(), 1u);
  EXPECT_EQ(c.chosen, 0);
  EXPECT_EQ(c.attempts[0].map, (int)compoundParametrization::spectral);
  EXPECT_TRUE(c.bijective);
  EXPECT_FALSE(c.attempts[0].repairTried);
}

TEST(bijectivity, chainsOfEveryValue)
{
  for(int v = 1; v <= 5; v++) {
    std::vector<mapStep> s = mapChain(v);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0].map, v);
    EXPECT_EQ(s[0].freeBoundary, v >= 4);
  }
  std::vector<mapStep> automatic = mapChain(6);
  ASSERT_EQ(automatic.size(), 3u);
  EXPECT_EQ(automatic[0].map, 5);
  EXPECT_EQ(automatic[1].map, 4);
  EXPECT_EQ(automatic[2].map, 3);
  EXPECT_TRUE(mapChain(0).empty());
  EXPECT_TRUE(mapChain(7).empty());
}

TEST(bijectivity, principalAxisPinsAreAtTheEndsOfAStrip)
{
  discretePatch p = makePatchOrDie(rectangleGrid(40, 4, 10., 1.));
  std::array<int, 2> pins = principalAxisPins(p);
  double x0 = p.points[pins[0]].x(), x1 = p.points[pins[1]].x();
  EXPECT_NEAR(std::min(x0, x1), 0., 1e-12);
  EXPECT_NEAR(std::max(x0, x1), 10., 1e-12);
}
