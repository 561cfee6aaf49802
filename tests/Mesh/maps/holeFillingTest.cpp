// Reparam - holes filled on their mean plane before mapping

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "SVector3.h"
#include "holeFilling.h"
#include "mapDistortion.h"
#include "meanValueMap.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  // Three holes of (ring, sector) cells: (rings from, to, sectors from, to)
  const std::vector<std::array<int, 4> > threeHoles = {
    {{3, 5, 0, 6}}, {{3, 6, 14, 18}}, {{6, 8, 25, 33}}};

  discretePatch filledPatch(const discretePatch &p, const holeFilling &f)
  {
    std::vector<std::array<int, 3> > all = p.triangles;
    all.insert(all.end(), f.triangles.begin(), f.triangles.end());
    discretePatch extended;
    reparamError err = makeDiscretePatch(p.points, all, extended);
    EXPECT_TRUE(err.ok()) << err.what();
    return extended;
  }

  // The patch's triangles with a node on an inner loop
  std::vector<int> trianglesAtHoles(const discretePatch &p)
  {
    std::vector<char> atHole(p.points.size(), 0);
    for(int l = 0; l < (int)p.boundaryLoops.size(); l++)
      if(l != p.outerLoop)
        for(int i : p.boundaryLoops[l]) atHole[i] = 1;
    std::vector<int> which;
    for(std::size_t t = 0; t < p.triangles.size(); t++) {
      const auto &tri = p.triangles[t];
      if(atHole[tri[0]] || atHole[tri[1]] || atHole[tri[2]])
        which.push_back((int)t);
    }
    return which;
  }

} // namespace

TEST(holeFilling, threeHolesGiveADiskWithTheSameNodes)
{
  discretePatch p =
    makePatchOrDie(liftPlanar(polarDiskWithHoles(10, 40, threeHoles), 0.3));
  ASSERT_EQ(p.boundaryLoops.size(), 4u);
  holeFilling f = fillHoles(p);
  EXPECT_EQ(f.filledHoles, 3);
  EXPECT_EQ(f.skippedHoles, 0);
  // a polygon of m nodes: m - 2 triangles
  std::size_t expected = 0;
  for(int l = 0; l < 4; l++)
    if(l != p.outerLoop) expected += p.boundaryLoops[l].size() - 2;
  EXPECT_EQ(f.triangles.size(), expected);
  discretePatch extended = filledPatch(p, f);
  EXPECT_EQ(extended.points.size(), p.points.size());
  EXPECT_EQ(extended.boundaryLoops.size(), 1u);
  EXPECT_EQ(extended.genus(), 0);
  // filled triangles are oriented like the patch: none had to be reversed
  EXPECT_EQ(extended.numReorientedTriangles, 0u);
}

TEST(holeFilling, fillingIsLocallyDelaunayOnTheMeanPlane)
{
  // a planar, non-convex hole of 3 x 8 polar cells: across every filling
  // edge whose quadrilateral is convex, the opposite node is outside the
  // circumcircle
  discretePatch p = makePatchOrDie(polarDiskWithHoles(8, 16, {{{2, 5, 0, 8}}}));
  ASSERT_EQ(p.boundaryLoops.size(), 2u);
  holeFilling f = fillHoles(p);
  ASSERT_EQ(f.filledHoles, 1);
  auto P = [&](int i) { return p.points[i]; };
  int checked = 0;
  for(std::size_t t1 = 0; t1 < f.triangles.size(); t1++) {
    for(std::size_t t2 = 0; t2 < f.triangles.size(); t2++) {
      if(t1 == t2) continue;
      const auto &a = f.triangles[t1], &b = f.triangles[t2];
      for(int k = 0; k < 3; k++) {
        // edge (a[k], a[k+1]) of t1 run backwards by t2
        int i = a[k], j = a[(k + 1) % 3], opposite = a[(k + 2) % 3];
        for(int l = 0; l < 3; l++) {
          if(b[l] != j || b[(l + 1) % 3] != i) continue;
          int d = b[(l + 2) % 3];
          // convex quadrilateral (opposite, i, d, j)
          if(signedArea2(P(opposite).x(), P(opposite).y(), P(i).x(), P(i).y(),
                         P(d).x(), P(d).y()) <= 0. ||
             signedArea2(P(d).x(), P(d).y(), P(j).x(), P(j).y(),
                         P(opposite).x(), P(opposite).y()) <= 0.)
            continue;
          double ax = P(i).x() - P(d).x(), ay = P(i).y() - P(d).y();
          double bx = P(j).x() - P(d).x(), by = P(j).y() - P(d).y();
          double cx = P(opposite).x() - P(d).x(),
                 cy = P(opposite).y() - P(d).y();
          double incircle = (ax * ax + ay * ay) * (bx * cy - cx * by) -
                            (bx * bx + by * by) * (ax * cy - cx * ay) +
                            (cx * cx + cy * cy) * (ax * by - bx * ay);
          EXPECT_LE(incircle, 1e-12);
          checked++;
        }
      }
    }
  }
  EXPECT_GT(checked, 0);
}

TEST(holeFilling, fillingLowersAngleDistortionNearHoles)
{
  discretePatch p =
    makePatchOrDie(liftPlanar(polarDiskWithHoles(10, 40, threeHoles), 0.3));
  discretePatch extended = filledPatch(p, fillHoles(p));
  patchMap free = meanValueMap(p), filled = meanValueMap(extended);
  ASSERT_TRUE(free.error.ok() && filled.error.ok());
  std::vector<int> near = trianglesAtHoles(p);
  mapDistortionStats dFree = angleDistortionStats(p, free.uv, near),
                     dFilled = angleDistortionStats(p, filled.uv, near);
  EXPECT_EQ(dFree.flipped, 0u);
  EXPECT_EQ(dFilled.flipped, 0u);
  std::printf("angle distortion at the holes: %.4f free, %.4f filled\n",
              dFree.mean, dFilled.mean);
  EXPECT_LT(dFilled.mean, dFree.mean - 0.05);
}

TEST(holeFilling, noRemeshNodeInsideAHole)
{
  // the disk with three holes as an STL, remeshed through the hook with the
  // conformal map and filled holes
  testTriangulation t = polarDiskWithHoles(10, 40, threeHoles);
  std::string stl = testing::TempDir() + "reparam_three_holes.stl";
  FILE *f = std::fopen(stl.c_str(), "w");
  ASSERT_TRUE(f);
  std::fprintf(f, "solid holes\n");
  for(const auto &tri : t.triangles) {
    std::fprintf(f, "facet normal 0 0 1\nouter loop\n");
    for(int v : tri)
      std::fprintf(f, "vertex %.17g %.17g 0\n", t.points[v].x(),
                   t.points[v].y());
    std::fprintf(f, "endloop\nendfacet\n");
  }
  std::fprintf(f, "endsolid holes\n");
  std::fclose(f);
  for(int map : {3, 4, 5}) {
    gmsh::clear();
    gmsh::option::setNumber("Mesh.CompoundParametrization", map);
    const uniformMeshSize meshSize(0.04);
    gmsh::merge(stl);
    gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
    gmsh::model::mesh::createGeometry();
    gmsh::model::mesh::generate(2);
    std::vector<std::size_t> tags;
    std::vector<double> xyz, param;
    gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, true, false);
    ASSERT_GT(tags.size(), 500u) << map;
    int inside = 0;
    for(std::size_t i = 0; i < tags.size(); i++) {
      double x = xyz[3 * i], y = xyz[3 * i + 1];
      double r = std::hypot(x, y) * 10.;
      double s = std::atan2(y, x) / (2. * M_PI) * 40.;
      if(s < 0.) s += 40.;
      for(const auto &h : threeHoles)
        // strictly inside the cells, with a margin for the curved sides
        if(r > h[0] + 0.05 && r < h[1] - 0.05 && s > h[2] + 0.05 &&
           s < h[3] - 0.05)
          inside++;
    }
    EXPECT_EQ(inside, 0) << "map " << map;
  }
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
}

namespace {

  // A unit square on an n x n grid without the cells [ia, ib) x [ja, jb):
  // a rectangular hole whose sides carry nodes in a line
  testTriangulation squareWithRectangularHole(int ia, int ib, int ja, int jb,
                                              int n = 10)
  {
    testTriangulation grid = rectangleGrid(n, n, 1., 1.), t;
    std::vector<int> index(grid.points.size(), -1);
    for(std::size_t k = 0; k < grid.triangles.size(); k++) {
      const int cell = (int)k / 2, i = cell % n, j = cell / n;
      if(i >= ia && i < ib && j >= ja && j < jb) continue;
      std::array<int, 3> tri = grid.triangles[k];
      for(int &n : tri) {
        if(index[n] < 0) {
          index[n] = (int)t.points.size();
          t.points.push_back(grid.points[n]);
        }
        n = index[n];
      }
      t.triangles.push_back(tri);
    }
    return t;
  }

  int innerLoop(const discretePatch &p) { return p.outerLoop == 0 ? 1 : 0; }

} // namespace

TEST(holeFilling, aRectangularHoleWithNodesAlongItsSidesIsFilled)
{
  // 4 x 2 cells: 12 nodes, 4 corners. Ear clipping used to cut off the last
  // corner with the others' nodes on the diagonal and be left with the
  // nodes of one side in a line (a CAD panel's window, refused level after
  // level)
  for(const std::array<int, 4> &cells :
      {std::array<int, 4>{{3, 7, 4, 6}}, std::array<int, 4>{{2, 8, 3, 5}},
       std::array<int, 4>{{4, 5, 2, 8}}}) {
    discretePatch p = makePatchOrDie(
      squareWithRectangularHole(cells[0], cells[1], cells[2], cells[3]));
    ASSERT_EQ(p.boundaryLoops.size(), 2u);
    std::vector<std::array<int, 3> > tris;
    ASSERT_TRUE(triangulateHole(p, innerLoop(p), tris));
    const std::size_t m = p.boundaryLoops[innerLoop(p)].size();
    EXPECT_EQ(tris.size(), m - 2);
    // on the square's plane, Delaunay: no angle under that of a cell and a
    // half (26.6 degrees), where a fan from one corner has 9.5 degrees
    double smallest = M_PI;
    for(const auto &t : tris)
      for(int k = 0; k < 3; k++) {
        const SVector3 u(p.points[t[k]], p.points[t[(k + 1) % 3]]),
          v(p.points[t[k]], p.points[t[(k + 2) % 3]]);
        smallest = std::min(smallest, angle(u, v));
      }
    EXPECT_GT(smallest * 180. / M_PI, 26.);
    discretePatch extended = filledPatch(p, {tris, 1, 0});
    EXPECT_EQ(extended.boundaryLoops.size(), 1u);
  }
}

TEST(holeFilling, aHoleWhoseRimFoldsOverIsFilledInSpace)
{
  // the rectangular hole of 4 x 2 cells with one long side's middle node
  // pulled across the hole and up: its rim crosses itself seen from the
  // mean plane, and from the plane the square faces. Filled all the same,
  // with the least area triangulation in space
  testTriangulation t = squareWithRectangularHole(3, 7, 4, 6);
  for(SPoint3 &q : t.points) // (0.5, 0.4), on the bottom side
    if(std::fabs(q.x() - 0.5) < 1e-9 && std::fabs(q.y() - 0.4) < 1e-9)
      q = SPoint3(0.5, 0.65, 0.08);
  discretePatch p = makePatchOrDie(t);
  ASSERT_EQ(p.boundaryLoops.size(), 2u);
  std::vector<std::array<int, 3> > tris;
  ASSERT_TRUE(triangulateHole(p, innerLoop(p), tris));
  EXPECT_EQ(tris.size(), p.boundaryLoops[innerLoop(p)].size() - 2);
  discretePatch extended = filledPatch(p, {tris, 1, 0});
  EXPECT_EQ(extended.boundaryLoops.size(), 1u);
  EXPECT_EQ(extended.genus(), 0);
}

TEST(holeFilling, theEndOfATubeIsNotFilledInSpace)
{
  // a tube whose end's rim doubles back around the axis (its nodes' angle
  // warped by 0.6 sin 3a): the rim crosses itself on its mean plane, and
  // the triangles around face every way. A filling in space would close
  // the tube into a sock, that no conformal map spreads: the layout cuts
  // across the tube instead
  const int around = 36, along = 6;
  testTriangulation t = rectangleGrid(around, along, 2. * M_PI, 2.);
  for(SPoint3 &q : t.points) {
    const bool end = q.y() > 2. - 1e-12;
    const double a = end ? q.x() + 0.6 * std::sin(3. * q.x()) : q.x();
    q = SPoint3(std::cos(a), std::sin(a), q.y());
  }
  const testTriangulation tube = weld(t, 1e-9);
  discretePatch p = makePatchOrDie(tube);
  ASSERT_EQ(p.boundaryLoops.size(), 2u);
  std::vector<std::array<int, 3> > tris;
  for(int loop = 0; loop < 2; loop++) {
    tris.clear();
    const bool endRim = p.points[p.boundaryLoops[loop][0]].z() > 1.;
    if(endRim) EXPECT_FALSE(triangulateHole(p, loop, tris));
    // the other end is a circle: filled on its mean plane, as before
    else
      EXPECT_TRUE(triangulateHole(p, loop, tris));
  }
}

TEST(holeFilling, aHoleThatDwarfsThePatchIsLeftFree)
{
  // a frame one cell wide around a square hole: on a 10 x 10 grid the hole
  // is 1.8 times the frame's area and filled; on a 60 x 60 grid 14.2 times,
  // and left free (filled, the frame's map is a band along the disk's edge)
  discretePatch wide = makePatchOrDie(squareWithRectangularHole(1, 9, 1, 9));
  EXPECT_EQ(fillHoles(wide).filledHoles, 1);
  discretePatch thin =
    makePatchOrDie(squareWithRectangularHole(1, 59, 1, 59, 60));
  const holeFilling f = fillHoles(thin);
  EXPECT_EQ(f.filledHoles, 0);
  EXPECT_EQ(f.skippedHoles, 1);
  EXPECT_TRUE(f.triangles.empty());
  std::vector<std::array<int, 3> > tris;
  EXPECT_TRUE(triangulateHole(thin, innerLoop(thin), tris));
}
