// Reparam - node moves that square up quadrangles on the input surface:
// a node pushed off a grid goes back, a zig-zag row of movable nodes is
// straightened, fixed nodes stay, no quadrangle turns over nor gets worse
// than the worst around it, every node stays on the input

#include <cmath>
#include <gtest/gtest.h>
#include "SVector3.h"
#include "closestTriangle.h"
#include "quadNodeSmoothing.h"
#include "quadQuality.h"
#include "surfaceMesh.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  std::vector<bool> innerNodes(int n)
  {
    std::vector<bool> movable((n + 1) * (n + 1), false);
    for(int j = 1; j < n; j++)
      for(int i = 1; i < n; i++) movable[i + (n + 1) * j] = true;
    return movable;
  }

  double etaOf(const surfaceMesh &m, const std::array<int, 4> &q)
  {
    return quadEta(m.points[q[0]], m.points[q[1]], m.points[q[2]],
                   m.points[q[3]]);
  }

  SVector3 normalOf(const surfaceMesh &m, const std::array<int, 4> &q)
  {
    return crossprod(SVector3(m.points[q[0]], m.points[q[2]]),
                     SVector3(m.points[q[1]], m.points[q[3]]));
  }

  // A pseudo-random number in [-1, 1]
  double noise(unsigned i, unsigned salt)
  {
    unsigned h = 2654435761u * (i + 104729u * salt);
    h ^= h >> 13;
    h *= 2246822519u;
    h ^= h >> 16;
    return 2. * (h % 10000) / 9999. - 1.;
  }

} // namespace

TEST(quadNodeSmoothing, aNodePushedOffTheGridGoesBack)
{
  const int n = 4;
  surfaceMesh m = quadGrid(n);
  const int centre = 2 + (n + 1) * 2;
  m.points[centre] = SPoint3(2.3, 2.2, 0.);
  // the input: the plane, finer than the quadrangles
  const surfaceMesh input = asSurfaceMesh(rectangleGrid(16, 16, 4., 4.));
  const closestTriangleSearch onInput(input.points, input.triangles);
  std::vector<int> landing;
  const quadSmoothingResult r =
    smoothQuadsOnInput(m, innerNodes(n), onInput, landing);
  EXPECT_LT(r.etaMinBefore, 0.9); // 0.796
  EXPECT_GT(r.etaMinAfter, 0.98);
  EXPECT_GT(r.etaMeanAfter, r.etaMeanBefore);
  EXPECT_GE(landing[centre], 0);
  EXPECT_NEAR(m.points[centre].x(), 2., 0.05);
  EXPECT_NEAR(m.points[centre].y(), 2., 0.05);
  EXPECT_EQ(m.points[centre].z(), 0.);
  // the grid's other nodes were square already: not moved
  for(std::size_t i = 0; i < m.points.size(); i++)
    if((int)i != centre) EXPECT_EQ(landing[i], -1) << i;
}

TEST(quadNodeSmoothing, aZigZagRowOfMovableNodesIsStraightened)
{
  // the middle row zig-zags by a third of a cell, as the nodes of a cut
  // along the input's edges
  const int n = 6;
  surfaceMesh m = quadGrid(n);
  for(int i = 1; i < n; i++)
    m.points[i + (n + 1) * 3] = SPoint3(i, 3. + (i % 2 ? 0.33 : -0.33), 0.);
  const surfaceMesh input = asSurfaceMesh(rectangleGrid(12, 12, 6., 6.));
  const closestTriangleSearch onInput(input.points, input.triangles);
  std::vector<int> landing;

  // the row fixed (a feature curve): nothing to gain around it
  std::vector<bool> fixedRow = innerNodes(n);
  for(int i = 1; i < n; i++) fixedRow[i + (n + 1) * 3] = false;
  surfaceMesh kept = m;
  smoothQuadsOnInput(kept, fixedRow, onInput, landing);
  for(int i = 1; i < n; i++) EXPECT_EQ(landing[i + (n + 1) * 3], -1);

  // the row movable (a cut): straightened
  const quadSmoothingResult r =
    smoothQuadsOnInput(m, innerNodes(n), onInput, landing);
  EXPECT_LT(r.etaMinBefore, 0.7); // 0.59
  EXPECT_GT(r.etaMinAfter, 0.9);
  for(int i = 1; i < n; i++)
    EXPECT_NEAR(m.points[i + (n + 1) * 3].y(), 3., 0.15) << i;
}

TEST(quadNodeSmoothing, neverWorseNorTurnedAndOnACurvedInput)
{
  // a quadrangle grid on the unit cylinder x^2 + z^2 = 1 (angle i / 8 of
  // a radian around, j / 4 along), its inner nodes moved at random along
  // the surface by up to 0.3 cells; the input: the cylinder, finer
  const int n = 8;
  surfaceMesh m = quadGrid(n);
  for(std::size_t i = 0; i < m.points.size(); i++) {
    const int a = (int)i % (n + 1), b = (int)i / (n + 1);
    const bool inner = a > 0 && a < n && b > 0 && b < n;
    const double t = (a + (inner ? 0.3 * noise(i, 0) : 0.)) / 8.;
    const double y = (b + (inner ? 0.3 * noise(i, 1) : 0.)) / 8.;
    m.points[i] = SPoint3(std::sin(t), y, std::cos(t));
  }
  testTriangulation fine = rectangleGrid(64, 64, 1., 1.);
  for(SPoint3 &p : fine.points)
    p = SPoint3(std::sin(p.x()), p.y(), std::cos(p.x()));
  const surfaceMesh input = asSurfaceMesh(fine);
  const closestTriangleSearch onInput(input.points, input.triangles);
  std::vector<SVector3> normals;
  for(const auto &q : m.quadrangles) normals.push_back(normalOf(m, q));
  std::vector<int> landing;
  const quadSmoothingResult r =
    smoothQuadsOnInput(m, innerNodes(n), onInput, landing);
  EXPECT_GT(r.moves, 20u);
  EXPECT_GE(r.etaMinAfter, r.etaMinBefore);
  EXPECT_GT(r.etaMeanAfter, r.etaMeanBefore + 0.02);
  for(std::size_t q = 0; q < m.quadrangles.size(); q++)
    EXPECT_GT(dot(normalOf(m, m.quadrangles[q]), normals[q]), 0.) << q;
  // on the input: the polyhedron's points are within its sag of the
  // cylinder, (1/64)^2 / 8 of a radian cell
  for(std::size_t i = 0; i < m.points.size(); i++) {
    if(landing[i] < 0) continue;
    const double r2 = std::hypot(m.points[i].x(), m.points[i].z());
    EXPECT_NEAR(r2, 1., 5e-5) << i;
    EXPECT_LT(onInput.closest(m.points[i]).distance, 1e-12) << i;
  }
}

TEST(quadNodeSmoothing, aBorderNodeSlidesAlongItsPolyline)
{
  // the bottom border of a 4 x 4 grid, its node 2 pushed to x = 2.6: it
  // slides back between its neighbours, along the border (y = 0); the
  // polyline: the border's input, 8 edges of 0.5
  const int n = 4;
  surfaceMesh m = quadGrid(n);
  m.points[2] = SPoint3(2.6, 0., 0.);
  std::vector<SPoint3> border;
  for(int i = 0; i <= 8; i++) border.push_back(SPoint3(0.5 * i, 0., 0.));
  std::vector<polylineSlide> slides(m.points.size());
  for(int i = 1; i < n; i++) {
    polylineSlide &s = slides[i];
    s.polyline = &border;
    s.t = i == 2 ? 5.2 : 2. * i;
    s.before = 2. * (i - 1);
    s.after = 2. * (i + 1);
    s.previous = i > 1 ? i - 1 : -1;
    s.next = i + 1 < n ? i + 1 : -1;
  }
  const surfaceMesh input = asSurfaceMesh(rectangleGrid(8, 8, 4., 4.));
  const closestTriangleSearch onInput(input.points, input.triangles);
  std::vector<int> landing;
  const quadSmoothingResult r =
    smoothQuadsOnInput(m, std::vector<bool>(m.points.size(), false), onInput,
                       landing, {}, &slides);
  EXPECT_GT(r.slides, 0u);
  EXPECT_GT(r.etaMinAfter, 0.95); // 0.81 before
  EXPECT_NEAR(slides[2].t, 4., 0.2);
  EXPECT_NEAR(m.points[2].x(), 2., 0.1);
  EXPECT_EQ(m.points[2].y(), 0.);
  EXPECT_EQ(landing[2], -1); // not moved on the input: along the polyline
}

TEST(quadNodeSmoothing, aNodeOnAPolylineCornerStays)
{
  // the same border bent at node 2 (x = 2): 40 degrees up after it; the
  // node sits on the corner, and a slide would cut it (its chords 5 % of
  // their length off the polyline)
  const int n = 4;
  surfaceMesh m = quadGrid(n);
  std::vector<SPoint3> border;
  for(int i = 0; i <= 8; i++) {
    const double x = 0.5 * i;
    border.push_back(
      SPoint3(x, x > 2. ? (x - 2.) * std::tan(40. * M_PI / 180.) : 0., 0.));
  }
  for(int i = 0; i <= n; i++) m.points[i] = border[2 * i];
  std::vector<polylineSlide> slides(m.points.size());
  polylineSlide &s = slides[2];
  s.polyline = &border;
  s.t = 4.;
  s.before = 2.;
  s.after = 6.;
  const surfaceMesh input = asSurfaceMesh(rectangleGrid(8, 8, 4., 4.));
  const closestTriangleSearch onInput(input.points, input.triangles);
  std::vector<int> landing;
  smoothQuadsOnInput(m, std::vector<bool>(m.points.size(), false), onInput,
                     landing, {}, &slides);
  EXPECT_EQ(slides[2].t, 4.);
}

TEST(quadNodeSmoothing, withTheSizeAskedTheEdgesComeNearerToIt)
{
  // an 8 x 8 grid of unit cells in the plane, its inner nodes moved at
  // random by up to 0.3 cells, smoothed by the angles alone and with the
  // size 1 asked: the edges nearer to it (their log-ratios summed 13.8 ->
  // 12.7), eta mean 0.014 lower (the angles and the lengths pull apart
  // where the cells are uneven), its worst no lower
  const int n = 8;
  surfaceMesh start = quadGrid(n);
  for(std::size_t i = 0; i < start.points.size(); i++) {
    const int a = (int)i % (n + 1), b = (int)i / (n + 1);
    if(a > 0 && a < n && b > 0 && b < n)
      start.points[i] =
        SPoint3(a + 0.3 * noise(i, 0), b + 0.3 * noise(i, 1), 0.);
  }
  const surfaceMesh input = asSurfaceMesh(rectangleGrid(64, 64, 8., 8.));
  const closestTriangleSearch onInput(input.points, input.triangles);
  auto offSize = [](const surfaceMesh &x) {
    double sum = 0.;
    for(const auto &q : x.quadrangles)
      for(int k = 0; k < 4; k++)
        sum += std::fabs(
          std::log(x.points[q[k]].distance(x.points[q[(k + 1) % 4]])));
    return sum;
  };
  surfaceMesh alone = start, sized = start;
  std::vector<int> landing;
  const quadSmoothingResult a =
    smoothQuadsOnInput(alone, innerNodes(n), onInput, landing);
  quadSmoothingOptions o;
  o.size.assign(start.points.size(), 1.);
  const quadSmoothingResult s =
    smoothQuadsOnInput(sized, innerNodes(n), onInput, landing, o);
  EXPECT_LT(offSize(sized), 0.95 * offSize(alone));
  EXPECT_GT(s.etaMeanAfter, a.etaMeanAfter - 0.02);
  EXPECT_GE(s.etaMinAfter, s.etaMinBefore);
  // sizes not one per point are none: the same moves as the angles alone
  o.size.assign(3, 1.);
  surfaceMesh none = start;
  smoothQuadsOnInput(none, innerNodes(n), onInput, landing, o);
  for(std::size_t i = 0; i < start.points.size(); i++)
    EXPECT_EQ(none.points[i].distance(alone.points[i]), 0.) << i;
}

TEST(quadNodeSmoothing, meanEdgeAtEachPoint)
{
  // a 2 x 2 grid whose columns are 1 and 2 wide: a left corner's edges 1
  // and 1, a right corner's 2 and 1, the centre's 1, 2 and twice 1 (each
  // counted once per quadrangle: 10 / 8); a point of no quadrangle 0
  surfaceMesh m = quadGrid(2);
  for(SPoint3 &p : m.points)
    p = SPoint3(p.x() < 1.5 ? p.x() : 3., p.y(), 0.);
  m.points.push_back(SPoint3(9., 9., 0.));
  const std::vector<double> mean = meanQuadEdgeAtPoints(m);
  ASSERT_EQ(mean.size(), m.points.size());
  EXPECT_NEAR(mean[0], 1., 1e-12);
  EXPECT_NEAR(mean[2], 1.5, 1e-12);
  EXPECT_NEAR(mean[4], 1.25, 1e-12);
  EXPECT_EQ(mean[9], 0.);
}
