// Reparam - closest-triangle search and the fidelity of a new mesh to its
// input: distances and orientation

#include <cmath>
#include <gtest/gtest.h>
#include "SVector3.h"
#include "closestTriangle.h"
#include "meshFidelity.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  double bruteForceDistance(const testTriangulation &t, const SPoint3 &p)
  {
    double best = 1e300;
    for(const auto &tri : t.triangles)
      best = std::min(
        best, p.distance(closestPointOnTriangle(
                p, t.points[tri[0]], t.points[tri[1]], t.points[tri[2]])));
    return best;
  }

  // a fixed linear congruential sequence in [0, 1)
  struct sequence {
    unsigned state;
    double next()
    {
      state = state * 1664525u + 1013904223u;
      return (state >> 8) / 16777216.;
    }
  };

} // namespace

TEST(closestTriangle, pointOnTriangleByRegion)
{
  SPoint3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  // above the face: its projection
  SPoint3 q = closestPointOnTriangle(SPoint3(0.5, 0.5, 3), a, b, c);
  EXPECT_NEAR(q.distance(SPoint3(0.5, 0.5, 0)), 0., 1e-15);
  // beyond a vertex, beyond an edge, beyond the hypotenuse
  q = closestPointOnTriangle(SPoint3(-1, -1, 1), a, b, c);
  EXPECT_NEAR(q.distance(a), 0., 1e-15);
  q = closestPointOnTriangle(SPoint3(1, -3, -1), a, b, c);
  EXPECT_NEAR(q.distance(SPoint3(1, 0, 0)), 0., 1e-15);
  q = closestPointOnTriangle(SPoint3(2, 2, 0), a, b, c);
  EXPECT_NEAR(q.distance(SPoint3(1, 1, 0)), 0., 1e-15);
  // a degenerate (collinear) triangle is its longest edge
  q = closestPointOnTriangle(SPoint3(3, 1, 0), a, SPoint3(1, 0, 0),
                             SPoint3(4, 0, 0));
  EXPECT_NEAR(q.distance(SPoint3(3, 0, 0)), 0., 1e-15);
  q = closestPointOnTriangle(SPoint3(5, 0, 1), a, a, SPoint3(4, 0, 0));
  EXPECT_NEAR(q.distance(SPoint3(4, 0, 0)), 0., 1e-15);
  // a segment: its inner point, an end, and a point segment
  q = closestPointOnSegment(SPoint3(1, 3, 0), a, b);
  EXPECT_NEAR(q.distance(SPoint3(1, 0, 0)), 0., 1e-15);
  q = closestPointOnSegment(SPoint3(-2, 1, 0), a, b);
  EXPECT_NEAR(q.distance(a), 0., 1e-15);
  q = closestPointOnSegment(SPoint3(3, 3, 3), b, b);
  EXPECT_NEAR(q.distance(b), 0., 1e-15);
}

TEST(closestTriangle, searchEqualsBruteForce)
{
  // a hemisphere plus one huge triangle and a sliver: the search must stay
  // exact everywhere, also far off the surface
  testTriangulation t = hemisphere(12, 40);
  int n = (int)t.points.size();
  t.points.push_back(SPoint3(-30, -30, -2));
  t.points.push_back(SPoint3(30, -30, -2));
  t.points.push_back(SPoint3(0, 30, -2));
  t.points.push_back(SPoint3(3, 0, 0));
  t.triangles.push_back({{n, n + 1, n + 2}});
  t.triangles.push_back({{n + 3, 0, n + 3}});
  closestTriangleSearch search(t.points, t.triangles);
  // a binary tree of leaves of up to four triangles
  EXPECT_GE(search.numBoxes(), 2 * (t.triangles.size() / 4) - 1);
  EXPECT_LT(search.numBoxes(), t.triangles.size());
  sequence s{7};
  for(int i = 0; i < 3000; i++) {
    SPoint3 p(8 * s.next() - 4, 8 * s.next() - 4, 6 * s.next() - 3);
    closestTriangleHit hit = search.closest(p);
    ASSERT_GE(hit.triangle, 0);
    EXPECT_NEAR(hit.distance, bruteForceDistance(t, p), 1e-13) << i;
    EXPECT_NEAR(hit.point.distance(p), hit.distance, 1e-13);
    // started from any triangle (a guess, near or far): the same distance
    const int near = (int)(s.next() * t.triangles.size());
    closestTriangleHit guessed = search.closest(p, near);
    EXPECT_NEAR(guessed.distance, hit.distance, 1e-13) << i;
    EXPECT_NEAR(guessed.point.distance(p), guessed.distance, 1e-13);
    EXPECT_EQ(search.closest(p, -1).triangle, hit.triangle);
  }
}

TEST(meshFidelity, againstTheInputGivenTheCentroidsClosestPoint)
{
  // the test with the input's closest point to the centroid given (a
  // caller measuring distances has it) answers as the one that searches it
  const surfaceMesh input = asSurfaceMesh(hemisphere(8, 24));
  const closestTriangleSearch onInput(input.points, input.triangles);
  sequence s{3};
  std::size_t against = 0;
  for(int i = 0; i < 400; i++) {
    SPoint3 c[3];
    for(SPoint3 &p : c)
      p = onInput
            .closest(
              SPoint3(2 * s.next() - 1, 2 * s.next() - 1, 2 * s.next() - 1))
            .point;
    const bool searched =
      triangleAgainstInput(c[0], c[1], c[2], input, onInput);
    const closestTriangleHit hit =
      onInput.closest((c[0] + c[1] + c[2]) * (1. / 3.));
    EXPECT_EQ(triangleAgainstInput(c[0], c[1], c[2], input, onInput, hit),
              searched)
      << i;
    against += searched;
  }
  EXPECT_GT(against, 50u); // both answers met
  EXPECT_LT(against, 350u);
}

TEST(meshFidelity, againstTheInputAsWithEverySample)
{
  // the test stops searching once its samples so far decide it: the same
  // answers as the sum of all four samples' unit normals, for triangles
  // across the input's ridges, reversed, tiny and far from it
  testTriangulation t = hemisphere(6, 18);
  const surfaceMesh input = asSurfaceMesh(t);
  const closestTriangleSearch onInput(input.points, input.triangles);
  auto unitNormal = [&](int i) {
    const auto &tri = input.triangles[i];
    SVector3 n =
      crossprod(SVector3(input.points[tri[0]], input.points[tri[1]]),
                SVector3(input.points[tri[0]], input.points[tri[2]]));
    return n.norm() > 0. ? n * (1. / n.norm()) : n;
  };
  auto everySample = [&](const SPoint3 &a, const SPoint3 &b, const SPoint3 &c) {
    const SPoint3 g = (a + b + c) * (1. / 3.);
    const int at = onInput.closest(g).triangle;
    SVector3 sum = unitNormal(at);
    for(const SPoint3 &p : {a, b, c})
      sum += unitNormal(onInput.closest((g + p) * 0.5, at).triangle);
    return dot(crossprod(SVector3(a, b), SVector3(a, c)), sum) < 0.;
  };
  sequence s{19};
  std::size_t against = 0, along = 0;
  for(int i = 0; i < 2000; i++) {
    const double size = i % 3 == 0 ? 1e-6 : i % 3 == 1 ? 0.2 : 1.5;
    SPoint3 c[3];
    const SPoint3 o = onInput
                        .closest(SPoint3(2 * s.next() - 1, 2 * s.next() - 1,
                                         s.next() + (i % 7 == 0 ? 3. : 0.)))
                        .point;
    for(SPoint3 &p : c)
      p = o + SPoint3(size * (s.next() - 0.5), size * (s.next() - 0.5),
                      size * (s.next() - 0.5));
    const bool full = everySample(c[0], c[1], c[2]);
    ASSERT_EQ(triangleAgainstInput(c[0], c[1], c[2], input, onInput), full)
      << i;
    EXPECT_EQ(triangleAgainstInput(c[2], c[1], c[0], input, onInput),
              everySample(c[2], c[1], c[0]))
      << i;
    (full ? against : along)++;
  }
  EXPECT_GT(against, 300u); // both answers met
  EXPECT_GT(along, 300u);
}

TEST(meshFidelity, sameMeshIsFaithfulAndReversedIsInverted)
{
  surfaceMesh input = asSurfaceMesh(hemisphere(8, 24));
  meshFidelity f = compareToInput(input, input);
  EXPECT_EQ(f.elements, input.triangles.size());
  EXPECT_EQ(f.inverted, 0u);
  EXPECT_NEAR(f.hausdorff, 0., 1e-14);
  EXPECT_NEAR(f.diagonal, std::sqrt(2. * 2. * 2. + 1.), 1e-12);

  surfaceMesh reversed = input;
  for(auto &t : reversed.triangles) std::swap(t[1], t[2]);
  EXPECT_EQ(compareToInput(input, reversed).inverted, input.triangles.size());
}

TEST(meshFidelity, distancesOfAnOffsetPlaneAndOfQuadrangles)
{
  surfaceMesh input = asSurfaceMesh(rectangleGrid(10, 10, 1, 1));
  // a 4 x 4 quadrangle mesh of the same square, 0.01 above it
  surfaceMesh quads;
  for(int j = 0; j <= 4; j++)
    for(int i = 0; i <= 4; i++)
      quads.points.push_back(SPoint3(i / 4., j / 4., 0.01));
  for(int j = 0; j < 4; j++)
    for(int i = 0; i < 4; i++) {
      int a = 5 * j + i;
      quads.quadrangles.push_back({{a, a + 1, a + 6, a + 5}});
    }
  meshFidelity f = compareToInput(input, quads);
  EXPECT_EQ(f.elements, 16u);
  EXPECT_EQ(f.inverted, 0u);
  EXPECT_NEAR(f.hausdorff, 0.01, 1e-14);
  EXPECT_NEAR(f.meanDistance, 0.01, 1e-14);
  // one quadrangle numbered clockwise
  std::swap(quads.quadrangles[5][1], quads.quadrangles[5][3]);
  EXPECT_EQ(compareToInput(input, quads).inverted, 1u);

  // an output covering only the lower half: the input's upper half is up to
  // 0.5 away (sampled at its nodes), the output everywhere on the input
  surfaceMesh half = asSurfaceMesh(rectangleGrid(10, 5, 1, 0.5));
  f = compareToInput(input, half);
  EXPECT_NEAR(f.hausdorff, 0.5, 1e-14);
  EXPECT_EQ(f.inverted, 0u);
}

TEST(meshFidelity, wholeModelDistancesIgnoreWhereFacesMeet)
{
  // The input split between two faces along a zig-zag of amplitude 0.1,
  // the output along the straight line between: face by face the zig-zag's
  // teeth are 0.1 from the face's own mesh, the whole output covers them
  testTriangulation grid = rectangleGrid(10, 10, 1., 1.);
  testTriangulation input[2], output[2];
  for(const auto &t : grid.triangles) {
    SPoint3 c =
      (grid.points[t[0]] + grid.points[t[1]] + grid.points[t[2]]) * (1. / 3.);
    // zig-zag: the column of cells right of x = 0.5 goes left on odd rows
    const int row = (int)(c.y() * 10.);
    const double cut = row % 2 ? 0.6 : 0.5;
    input[c.x() < cut ? 0 : 1].triangles.push_back(t);
    output[c.x() < 0.5 ? 0 : 1].triangles.push_back(t);
  }
  surfaceMesh in[2], out[2];
  for(int f = 0; f < 2; f++) {
    // each face with its own nodes only, as Gmsh's faces have
    input[f].points = output[f].points = grid.points;
    in[f] = asSurfaceMesh(weld(input[f], 1e-9));
    out[f] = asSurfaceMesh(weld(output[f], 1e-9));
  }
  double faceByFace = 0.;
  for(int f = 0; f < 2; f++)
    faceByFace = std::max(faceByFace, compareToInput(in[f], out[f]).hausdorff);
  EXPECT_NEAR(faceByFace, 0.1, 1e-12);
  meshFidelity whole =
    compareDistancesToInput({in[0], in[1]}, {out[0], out[1]});
  EXPECT_NEAR(whole.hausdorff, 0., 1e-14);
  EXPECT_NEAR(whole.diagonal, std::sqrt(2.), 1e-14);
  EXPECT_EQ(whole.elements, grid.triangles.size());
}

TEST(meshFidelity, farthestPointIsWhereTheHausdorffDistanceIs)
{
  // the unit square as input; the output cuts its corner (1, 1) off: the
  // input's corner is the farthest sample, sqrt(2) / 4 from the mesh
  surfaceMesh input, output;
  input.points = {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(1, 1, 0),
                  SPoint3(0, 1, 0)};
  input.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  output.points = {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(1, 0.5, 0),
                   SPoint3(0.5, 1, 0), SPoint3(0, 1, 0)};
  output.triangles = {{{0, 1, 2}}, {{0, 2, 3}}, {{0, 3, 4}}};
  meshFidelity f = compareToInput(input, output);
  EXPECT_NEAR(f.hausdorff, std::sqrt(2.) / 4., 1e-12);
  EXPECT_TRUE(f.farthestOnInput);
  EXPECT_NEAR(f.farthest.distance(SPoint3(1, 1, 0)), 0., 1e-12);

  // the other way round, a mesh node lifted off the input plane by 0.3
  output = input;
  output.points[2] = SPoint3(1, 1, 0.3);
  f = compareDistancesToInput({input}, {output});
  EXPECT_NEAR(f.hausdorff, 0.3, 1e-12);
  EXPECT_FALSE(f.farthestOnInput);
  EXPECT_NEAR(f.farthest.distance(SPoint3(1, 1, 0.3)), 0., 1e-12);
}

TEST(meshFidelity, unionKeepsEachPartsNodesAndElements)
{
  // a triangle and a unit square of one quadrangle: the union has their 7
  // nodes (the shared ones repeated), the triangle and the quadrangle's two
  // halves, each element and node tagged with its part, areas kept
  surfaceMesh triangle, square;
  triangle.points = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                     SPoint3(0., 1., 0.)};
  triangle.triangles = {{{0, 1, 2}}};
  square.points = {SPoint3(1., 0., 0.), SPoint3(2., 0., 0.),
                   SPoint3(2., 1., 0.), SPoint3(1., 1., 0.)};
  square.quadrangles = {{{0, 1, 2, 3}}};
  std::vector<int> pointPart, elementPart;
  const surfaceMesh u =
    unionAsTriangles({triangle, square}, &pointPart, &elementPart);
  ASSERT_EQ(u.points.size(), 7u);
  ASSERT_EQ(u.triangles.size(), 3u);
  EXPECT_EQ(pointPart, std::vector<int>({0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(elementPart, std::vector<int>({0, 1, 1}));
  double area = 0.;
  for(const auto &t : u.triangles)
    area += 0.5 * crossprod(SVector3(u.points[t[0]], u.points[t[1]]),
                            SVector3(u.points[t[0]], u.points[t[2]]))
                    .z();
  EXPECT_NEAR(area, 1.5, 1e-15); // all turned the same way
  EXPECT_TRUE(u.quadrangles.empty());
}

TEST(meshFidelity, distanceToPolylineIsToItsClosestSegment)
{
  const std::vector<SPoint3> line = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                                     SPoint3(1., 1., 0.)};
  EXPECT_NEAR(distanceToPolyline(SPoint3(0.5, -0.2, 0.), line), 0.2, 1e-15);
  EXPECT_NEAR(distanceToPolyline(SPoint3(1.3, 0.5, 0.), line), 0.3, 1e-15);
  // beyond an end: to the end point
  EXPECT_NEAR(distanceToPolyline(SPoint3(-0.3, 0.4, 0.), line), 0.5, 1e-15);
  EXPECT_NEAR(distanceToPolyline(SPoint3(2., 3., 0.), {SPoint3(2., 3., 4.)}),
              4., 1e-15);
}
