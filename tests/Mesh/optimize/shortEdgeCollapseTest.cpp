// Reparam - inner edges shorter than the size collapsed: the mesh stays a
// valid manifold on the input, and the input nodes under it stay near

#include <algorithm>
#include <cmath>
#include <map>
#include <gtest/gtest.h>
#include "closestTriangle.h"
#include "optimizerTestMeshes.h"
#include "shortEdgeCollapse.h"
#include "testPatches.h"

using namespace optimizeTest;

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

TEST(shortEdgeCollapse, collapsesKeepTheInputNodesUnderThem)
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

TEST(shortEdgeCollapse, shortEdgesAreCollapsedKeepingTheMeshValid)
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
