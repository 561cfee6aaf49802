// Reparam - tests of the widths of strips narrower than the mesh size

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <map>
#include "narrowStrips.h"
#include "surfaceMesh.h"

using namespace reparam;

namespace {

  // The unit cells (i, j), 0 <= i < nx, 0 <= j < ny, that keep(i, j)
  // accepts, two triangles each, their nodes placed by at(u, v); flat: the
  // nodes at (u, v, 0)
  surfaceMesh gridMesh(int nx, int ny,
                       const std::function<bool(int, int)> &keep,
                       const std::function<SPoint3(double, double)> &at,
                       std::vector<SPoint3> &flat)
  {
    surfaceMesh m;
    std::map<std::pair<int, int>, int> index;
    auto node = [&](int i, int j) {
      auto it = index.find({i, j});
      if(it != index.end()) return it->second;
      m.points.push_back(at(i, j));
      flat.push_back(SPoint3(i, j, 0.));
      return index[{i, j}] = (int)m.points.size() - 1;
    };
    for(int i = 0; i < nx; i++)
      for(int j = 0; j < ny; j++) {
        if(!keep(i, j)) continue;
        const int a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1),
                  d = node(i, j + 1);
        m.triangles.push_back({{a, b, c}});
        m.triangles.push_back({{a, c, d}});
      }
    return m;
  }

  SPoint3 planar(double u, double v) { return SPoint3(u, v, 0.); }

  double constantSize(const SPoint3 &) { return 4.; }

} // namespace

TEST(narrowStrips, aFrameIsAsNarrowAsItsBars)
{
  // a 10 x 10 square less its inner 8 x 8: bars 1 wide, the size 4
  std::vector<SPoint3> flat;
  const surfaceMesh m = gridMesh(
    10, 10, [](int i, int j) { return i == 0 || j == 0 || i == 9 || j == 9; },
    planar, flat);
  const std::vector<stripWidth> strips =
    narrowStripWidths(m, flat, constantSize, 0.9);
  // every sample of both loops: 4 per size (1 apart) along 40 + 32
  ASSERT_EQ(strips.size(), 72u);
  double narrowest = 1e9, widest = 0.;
  for(const stripWidth &s : strips) {
    narrowest = std::min(narrowest, s.width);
    widest = std::max(widest, s.width);
  }
  EXPECT_NEAR(narrowest, 1., 1e-12);
  // the outer corners see the inner ones across the diagonal
  EXPECT_NEAR(widest, std::sqrt(2.), 1e-12);
  // a size far below the model's scale: no samples, at once
  const auto tiny = [](const SPoint3 &) { return 1e-6; };
  EXPECT_TRUE(narrowStripWidths(m, flat, tiny, 0.9).empty());
}

TEST(narrowStrips, cornersAndGapsAreNoStrips)
{
  std::vector<SPoint3> flat;
  // a square wider than the size: its sides meet at convex corners
  const surfaceMesh square = gridMesh(
    5, 5, [](int, int) { return true; }, planar, flat);
  EXPECT_TRUE(narrowStripWidths(square, flat, constantSize, 0.9).empty());
  // an L of arms 4 wide: its reflex corner
  flat.clear();
  const surfaceMesh l = gridMesh(
    8, 8, [](int i, int j) { return i < 4 || j < 4; }, planar, flat);
  EXPECT_TRUE(narrowStripWidths(l, flat, constantSize, 0.9).empty());
  // a U of arms 4 wide, 1 apart: the gap lies outside the surface
  flat.clear();
  const surfaceMesh u = gridMesh(
    9, 8, [](int i, int j) { return i < 4 || i > 4 || j < 4; }, planar, flat);
  EXPECT_TRUE(narrowStripWidths(u, flat, constantSize, 0.9).empty());
}

TEST(narrowStrips, aNeckShorterThanTheSizeIsNoStrip)
{
  // two 6 x 6 squares joined by a neck 1 wide and `neck` long, the size 4
  const auto dumbbell = [](int neck, std::vector<SPoint3> &flat) {
    return gridMesh(
      12 + neck, 6,
      [neck](int i, int j) { return i < 6 || i >= 6 + neck || j == 2; }, planar,
      flat);
  };
  std::vector<SPoint3> flat;
  EXPECT_TRUE(
    narrowStripWidths(dumbbell(2, flat), flat, constantSize, 0.9).empty());
  // 8 long: one sample per unit edge along both sides of the neck (along
  // the boundary, the other side is around a whole square away)
  flat.clear();
  const std::vector<stripWidth> strips =
    narrowStripWidths(dumbbell(8, flat), flat, constantSize, 0.9);
  EXPECT_EQ(strips.size(), 2u * 8u);
  for(const stripWidth &s : strips) EXPECT_NEAR(s.width, 1., 1e-12);
}

TEST(narrowStrips, aGrooveIsStraightInItsLayout)
{
  // a strip 6 wide bent into a half cylinder, its sides 2 * 6 / pi apart
  // (3.82; the size 8): their inward normals are parallel in space (no
  // straight line across), opposite in the strip's unrolled layout
  const double radius = 6. / M_PI;
  const auto size = [](const SPoint3 &) { return 8.; };
  std::vector<SPoint3> flat;
  const surfaceMesh groove = gridMesh(
    40, 6, [](int, int) { return true; },
    [&](double u, double v) {
      const double a = M_PI * v / 6.;
      return SPoint3(u, radius * std::cos(a), -radius * std::sin(a));
    },
    flat);
  EXPECT_TRUE(narrowStripWidths(groove, groove.points, size, 0.9).empty());
  const std::vector<stripWidth> strips =
    narrowStripWidths(groove, flat, size, 0.9);
  // one sample per unit edge along both long sides (a quarter of the size
  // is longer), but within 5 of their ends: at u, the other side is 2 u + 6
  // away along the boundary, not 4 times 3.82 yet
  for(const stripWidth &s : strips) {
    EXPECT_NEAR(s.width, 2. * radius, 1e-9);
    EXPECT_NEAR(std::fabs(s.point.y()), radius, 1e-9);
    EXPECT_GE(s.point.x(), 5.);
    EXPECT_LE(s.point.x(), 35.);
  }
  EXPECT_EQ(strips.size(), 2u * 31u);
  // a cut the mesh crosses is no side
  const auto notTheFarSide = [&](int a, int b) {
    return groove.points[a].y() > -radius + 1e-9 ||
           groove.points[b].y() > -radius + 1e-9;
  };
  EXPECT_TRUE(
    narrowStripWidths(groove, flat, size, 0.9, notTheFarSide).empty());
}
