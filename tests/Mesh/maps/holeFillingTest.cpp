// Reparam - holes filled on their mean plane before mapping

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include "gmsh.h"
#include "gmshTestEnvironment.h"
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
  discretePatch p = makePatchOrDie(liftPlanar(polarDiskWithHoles(10, 40, threeHoles), 0.3));
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
          double cx = P(opposite).x() - P(d).x(), cy = P(opposite).y() - P(d).y();
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
  discretePatch p = makePatchOrDie(liftPlanar(polarDiskWithHoles(10, 40, threeHoles), 0.3));
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
      std::fprintf(f, "vertex %.17g %.17g 0\n", t.points[v].x(), t.points[v].y());
    std::fprintf(f, "endloop\nendfacet\n");
  }
  std::fprintf(f, "endsolid holes\n");
  std::fclose(f);
  for(int map : {3, 4, 5}) {
    gmsh::clear();
    gmsh::option::setNumber("Mesh.CompoundParametrization", map);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.04);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.04);
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
  gmsh::option::setNumber("Mesh.CompoundParametrization", 3);
}
