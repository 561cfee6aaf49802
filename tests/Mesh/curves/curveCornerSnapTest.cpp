// Reparam - 1D nodes of a discrete curve moved onto the input's corners

#include <array>
#include <cmath>
#include <map>
#include <gtest/gtest.h>
#include "curveCornerSnap.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"

using namespace reparam;

namespace {

  // an L: 10 unit steps along x, then 10 along y; its corner is node 10
  std::vector<SPoint3> lShape()
  {
    std::vector<SPoint3> p;
    for(int i = 0; i <= 10; i++) p.push_back(SPoint3(i, 0, 0));
    for(int i = 1; i <= 10; i++) p.push_back(SPoint3(10, i, 0));
    return p;
  }

} // namespace

TEST(curveCornerSnap, cornerBecomesANodeAndPiecesKeepTheirSize)
{
  // segments of 4.5 (the last 2) across the corner at 10: the piece before
  // it had 2.2 segments, the one after 2.8, now 2 and 3 even ones
  std::vector<double> snapped =
    snapCurveNodesToCorners(lShape(), {0., 4.5, 9., 13.5, 18., 20.});
  std::vector<double> expected = {0., 5., 10., 40. / 3., 50. / 3., 20.};
  ASSERT_EQ(snapped.size(), expected.size());
  for(std::size_t k = 0; k < expected.size(); k++)
    EXPECT_NEAR(snapped[k], expected[k], 1e-12) << k;

  // 1.9 and 2.1 segments: 2 and 2
  snapped = snapCurveNodesToCorners(lShape(), {0., 5., 10.8, 16., 20.});
  expected = {0., 5., 10., 15., 20.};
  ASSERT_EQ(snapped.size(), expected.size());
  for(std::size_t k = 0; k < expected.size(); k++)
    EXPECT_NEAR(snapped[k], expected[k], 1e-12) << k;
}

TEST(curveCornerSnap, cornerNearAnEndIsLeftOut)
{
  // a corner at node 1, less than half a segment (5.25) from the curve's
  // end node: a node already sits about there
  std::vector<SPoint3> p = {SPoint3(0, 0, 0)};
  for(int i = 0; i <= 20; i++) p.push_back(SPoint3(1, i, 0));
  std::vector<double> params = {0., 5., 10., 15., 21.};
  EXPECT_EQ(snapCurveNodesToCorners(p, params), params);
}

TEST(curveCornerSnap, bothCornersOfASlotsEndWithinOneSegment)
{
  // a slot's end: two right-angled corners 0.8 apart (0.82 segments), both
  // within the segment from arc length 3.9 to 4.9; with everyCorner each
  // becomes a node, the end one segment between them
  const std::vector<SPoint3> p = {SPoint3(0, 0, 0), SPoint3(4, 0, 0),
                                  SPoint3(4, 0.8, 0), SPoint3(0, 0.8, 0)};
  const std::vector<double> params = {0.,    0.25, 0.5, 0.75, 0.975,
                                      2.025, 2.25, 2.5, 2.75, 3.};
  std::vector<int> corners;
  snapCurveNodesToCorners(p, params, nullptr, &corners);
  EXPECT_EQ(corners.size(), 1u); // the sharpest of the segment only
  corners.clear();
  const std::vector<double> snapped =
    snapCurveNodesToCorners(p, params, nullptr, &corners, false, true);
  EXPECT_EQ(corners, std::vector<int>({1, 2}));
  ASSERT_EQ(snapped.size(), params.size());
  int on = 0;
  for(std::size_t i = 0; i + 1 < snapped.size(); i++) {
    on += snapped[i] == 1. || snapped[i] == 2.;
    if(snapped[i] == 1.) EXPECT_EQ(snapped[i + 1], 2.);
  }
  EXPECT_EQ(on, 2);
}

TEST(curveCornerSnap, zigZagAtTheInputScaleIsNoCorner)
{
  // a straight line of input edges zig-zagging by +-0.3 across it (turning
  // by 62 degrees at every node), meshed with segments of 10 edges: seen at
  // half a segment it does not turn
  std::vector<SPoint3> p;
  for(int i = 0; i <= 40; i++) p.push_back(SPoint3(i, i % 2 ? 0.3 : -0.3, 0));
  const std::vector<double> params = {0., 10.5, 20.5, 30.5, 40.};
  EXPECT_EQ(snapCurveNodesToCorners(p, params), params);
}

TEST(curveCornerSnap, smoothCurveIsLeftAlone)
{
  // a half circle of 200 input nodes, meshed with 9 even segments: moving a
  // node onto an input node never halves a segment's sagitta
  std::vector<SPoint3> p;
  for(int i = 0; i < 200; i++) {
    const double a = M_PI * i / 199.;
    p.push_back(SPoint3(std::cos(a), std::sin(a), 0.));
  }
  std::vector<double> params;
  for(int k = 0; k <= 9; k++) params.push_back(199. * k / 9.);
  EXPECT_EQ(snapCurveNodesToCorners(p, params), params);
}

TEST(curveCornerSnap, onlyCornersOf40DegreesOrMoreAttract)
{
  // a polyline turning by 30 degrees at node 10, then by 45 at node 30
  std::vector<SPoint3> p;
  SPoint3 x(0, 0, 0);
  double heading = 0.;
  for(int i = 0; i <= 50; i++) {
    p.push_back(x);
    if(i == 10) heading += 30. * M_PI / 180.;
    if(i == 30) heading += 45. * M_PI / 180.;
    x = SPoint3(x.x() + std::cos(heading), x.y() + std::sin(heading), 0.);
  }
  const std::vector<double> params = {0., 8.5, 17., 25.5, 34., 42.5, 50.};
  std::vector<double> snapped = snapCurveNodesToCorners(p, params);
  // the 45 degree corner at 30 a node, 3.5 and 2.5 segments before and
  // after it: 4 and 2 (rounded half away from zero); the 30 degree turn at
  // 10 is no corner
  const std::vector<double> expected = {0., 7.5, 15., 22.5, 30., 40., 50.};
  ASSERT_EQ(snapped.size(), expected.size());
  for(std::size_t k = 0; k < expected.size(); k++)
    EXPECT_NEAR(snapped[k], expected[k], 1e-9) << k;
}

namespace {

  // The nodes of the current model's mesh at p (to 1e-12)
  int meshNodesAt(const SPoint3 &p)
  {
    std::vector<std::size_t> tags;
    std::vector<double> coords, params;
    gmsh::model::mesh::getNodes(tags, coords, params, -1, -1, false);
    int n = 0;
    for(std::size_t i = 0; i + 2 < coords.size(); i += 3)
      n += std::hypot(coords[i] - p.x(), coords[i + 1] - p.y(),
                      coords[i + 2] - p.z()) < 1e-12;
    return n;
  }

} // namespace

TEST(curveCornerSnap, recipeMeshKeepsTheCornersOfAnLShapedPlate)
{
  // an L of the 20 x 20 grid of the unit square (its top right quarter
  // removed): one closed boundary curve (the recipe does not split curves
  // at corners), six corners, the reflex one at (0.5, 0.5). The size, 0.13,
  // puts Gmsh's even nodes off most of them
  testTriangulation grid = rectangleGrid(20, 20, 1., 1.);
  testTriangulation plate;
  std::map<int, int> index;
  for(const auto &t : grid.triangles) {
    SPoint3 g =
      (grid.points[t[0]] + grid.points[t[1]] + grid.points[t[2]]) * (1. / 3.);
    if(g.x() > 0.5 && g.y() > 0.5) continue;
    std::array<int, 3> kept;
    for(int j = 0; j < 3; j++) {
      auto it = index.insert({t[j], (int)plate.points.size()});
      if(it.second) plate.points.push_back(grid.points[t[j]]);
      kept[j] = it.first->second;
    }
    plate.triangles.push_back(kept);
  }
  const std::vector<SPoint3> corners = {
    SPoint3(0, 0, 0),     SPoint3(1, 0, 0),   SPoint3(1, 0.5, 0),
    SPoint3(0.5, 0.5, 0), SPoint3(0.5, 1, 0), SPoint3(0, 1, 0)};
  remeshWithRecipe(plate, 0.13);
  EXPECT_TRUE(surfacesWithoutElements().empty());
  for(const SPoint3 &c : corners)
    EXPECT_EQ(meshNodesAt(c), 1) << c.x() << " " << c.y();

  // Gmsh's even spacing misses some
  gmsh::option::setNumber("Mesh.CompoundCurveCorners", 0);
  remeshWithRecipe(plate, 0.13);
  gmsh::option::setNumber("Mesh.CompoundCurveCorners", 1);
  int missed = 0;
  for(const SPoint3 &c : corners) missed += meshNodesAt(c) == 0;
  EXPECT_GT(missed, 0);

  // a new model of the same plate (its curves other objects at the same
  // places) keeps them all again: what a curve took in a model gone is no
  // claim on them
  remeshWithRecipe(plate, 0.13);
  remeshWithRecipe(plate, 0.13);
  for(const SPoint3 &c : corners)
    EXPECT_EQ(meshNodesAt(c), 1) << c.x() << " " << c.y();
}

TEST(curveCornerSnap, keepParityKeepsTheCountOfSegments)
{
  // 5 segments of 4, the corner at 10 halfway: 2.5 segments on each side,
  // rounded to 3 and 3 (6 segments, an even count from an odd one); keeping
  // the parity (a curve of a face Blossom recombines), 3 and 2
  const std::vector<double> params = {0., 4., 8., 12., 16., 20.};
  const std::vector<double> rounded = snapCurveNodesToCorners(lShape(), params);
  ASSERT_EQ(rounded.size(), 7u);
  EXPECT_EQ(rounded[3], 10.);
  const std::vector<double> kept =
    snapCurveNodesToCorners(lShape(), params, nullptr, nullptr, true);
  ASSERT_EQ(kept.size(), 6u);
  EXPECT_EQ(kept[3], 10.);
}
