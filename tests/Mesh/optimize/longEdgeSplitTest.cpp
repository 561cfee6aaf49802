// Reparam - inner edges longer than the size split at the input, and an
// edge whose chord cuts a ridge off split whatever its halves

#include <cmath>
#include <gtest/gtest.h>
#include "closestTriangle.h"
#include "longEdgeSplit.h"
#include "optimizerTestMeshes.h"
#include "testPatches.h"

using namespace optimizeTest;

TEST(longEdgeSplit, longEdgesAreSplitOnTheInput)
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

TEST(longEdgeSplit, anEdgeThatCutsARidgeOffIsSplitWhateverItsHalves)
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
