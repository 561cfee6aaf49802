// Reparam - sharp creases left inside a face, kept as embedded curves

#include <algorithm>
#include <cmath>
#include <set>
#include <gtest/gtest.h>
#include "creaseChains.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"

using namespace reparam;

namespace {

  // The square z = 1.2 max(0, y - 0.05) |x - 0.5| over a 30 x 30 grid
  // (sharp, > 40 degrees, for y above 0.35: a crease along x = 0.5 from
  // there on, ending inside), rolled into an annulus' sector (radius 0.2 +
  // 0.6 x, angle 1.5 pi y): the crease is an arc of radius 0.5 and 1.53
  // long whose ends are 1 apart
  testTriangulation bentCrease()
  {
    testTriangulation t = rectangleGrid(30, 30, 1., 1.);
    for(auto &p : t.points) {
      const double r = 0.2 + 0.6 * p.x(), a = 1.5 * M_PI * p.y();
      const double z = 1.2 * std::max(0., p.y() - 0.05) * std::fabs(r - 0.5);
      p = SPoint3(r * std::cos(a), r * std::sin(a), z);
    }
    return t;
  }

  // Whether the log says crease curves were not kept for the mesh size
  bool creaseNotKept(const std::vector<std::string> &log)
  {
    for(const auto &l : log)
      if(l.find("too small for the mesh size") != std::string::npos)
        return true;
    return false;
  }

  // The mesh nodes no triangle uses
  std::size_t nodesOutsideTriangles()
  {
    std::vector<std::size_t> tags, used;
    std::vector<double> coords, params;
    gmsh::model::mesh::getNodes(tags, coords, params, -1, -1, false, false);
    std::vector<std::size_t> elements;
    gmsh::model::mesh::getElementsByType(2, elements, used);
    std::set<std::size_t> inTriangles(used.begin(), used.end());
    std::size_t outside = 0;
    for(std::size_t t : tags) outside += !inTriangles.count(t);
    return outside;
  }

} // namespace

TEST(creaseChains, chainsAreCutAtBranchesTrimmedAndKeptWhenLong)
{
  // a 6 x 6 grid (7 nodes a row): creases along the row j = 3 (nodes 21 ..
  // 27) and up from its node 24 (24, 31, 38): three chains from the branch
  // point 24
  testTriangulation grid = rectangleGrid(6, 6, 6., 6.);
  std::set<std::pair<int, int> > creases;
  for(int i = 21; i < 27; i++) creases.insert({i, i + 1});
  creases.insert({24, 31});
  creases.insert({31, 38});
  auto isCrease = [&creases](int a, int b) {
    return creases.count({std::min(a, b), std::max(a, b)}) > 0;
  };
  std::vector<std::vector<int> > chains =
    creaseChains(grid.points, grid.triangles, isCrease, {}, 0., 0.);
  ASSERT_EQ(chains.size(), 3u);
  for(auto &c : chains) {
    if(c.front() != 24) std::reverse(c.begin(), c.end());
    EXPECT_EQ(c.front(), 24);
  }
  std::sort(chains.begin(), chains.end());
  EXPECT_EQ(chains[0], (std::vector<int>{24, 23, 22, 21}));
  EXPECT_EQ(chains[1], (std::vector<int>{24, 25, 26, 27}));
  EXPECT_EQ(chains[2], (std::vector<int>{24, 31, 38}));

  // nodes closer than 1.5 to the point (0, 3) (nodes 21, 22) are trimmed
  // off the first chain; then chains shorter than 2.5 are dropped
  chains = creaseChains(grid.points, grid.triangles, isCrease,
                        {SPoint3(0., 3., 0.)}, 1.5, 2.5);
  ASSERT_EQ(chains.size(), 1u);
  std::vector<int> kept = chains[0];
  if(kept.front() != 24) std::reverse(kept.begin(), kept.end());
  EXPECT_EQ(kept, (std::vector<int>{24, 25, 26, 27}));
}

TEST(creaseChains, creaseEndingInsideAFaceIsMeshedAlong)
{
  // z = max(0, y - 0.3) |x - 0.5| over a 20 x 20 grid of the unit square:
  // a crease along x = 0.5, sharp (> 40 degrees) for y above 0.6, that ends
  // inside the face: it bounds no patch, and the mesh follows it anyway
  // (about 3.5 sizes long; at 0.15 its end by the square's side, closer
  // than half a size, has it left out)
  testTriangulation t = rectangleGrid(20, 20, 1., 1.);
  for(auto &p : t.points)
    p = SPoint3(p.x(), p.y(),
                1.2 * std::max(0., p.y() - 0.3) * std::fabs(p.x() - 0.5));
  EXPECT_TRUE(creaseNotKept(remeshWithRecipe(t, 0.15)));
  std::vector<std::string> log = remeshWithRecipe(t, 0.09);
  EXPECT_FALSE(creaseNotKept(log));
  int embedded = 0;
  for(const auto &l : log) {
    EXPECT_EQ(l.find("Error"), std::string::npos) << l;
    embedded += l.find("kept as embedded curve") != std::string::npos;
  }
  EXPECT_EQ(embedded, 1);
  EXPECT_TRUE(surfacesWithoutElements().empty());
  // the curve inside is no boundary: the free edges are the square's sides
  std::size_t nonManifold = 0;
  for(const auto &e : freeMeshEdges(&nonManifold)) {
    std::vector<double> p1, p2, par;
    gmsh::model::mesh::getNode(e.first, p1, par);
    gmsh::model::mesh::getNode(e.second, p2, par);
    const double x = 0.5 * (p1[0] + p2[0]), y = 0.5 * (p1[1] + p2[1]);
    EXPECT_TRUE(std::fabs(x) < 1e-9 || std::fabs(x - 1.) < 1e-9 ||
                std::fabs(y) < 1e-9 || std::fabs(y - 1.) < 1e-9)
      << x << " " << y;
  }
  EXPECT_EQ(nonManifold, 0u);
  // mesh nodes on the crease, from its end inside (y = 0.65, its first
  // sharp edge) to near the boundary: the curve's ends and its 1D nodes
  std::vector<std::size_t> tags;
  std::vector<double> coords, params;
  gmsh::model::mesh::getNodes(tags, coords, params, -1, -1, false);
  int onCrease = 0;
  for(std::size_t i = 0; i + 2 < coords.size(); i += 3)
    onCrease += std::fabs(coords[i] - 0.5) < 1e-12 && coords[i + 1] > 0.6 &&
                coords[i + 1] < 0.99;
  EXPECT_GE(onCrease, 3);
}

TEST(creaseChains, bentCreaseShorterThanThreeMeshSizesIsNotKept)
{
  // at the size 0.8 the crease (ends 0.65 of its length apart) would get
  // two segments cutting its bend, with corners inside the face at their
  // ends: not kept, and no node
  // of it left outside the triangles; at 0.1 it is kept
  std::vector<std::string> log = remeshWithRecipe(bentCrease(), 0.8);
  for(const auto &l : log) EXPECT_EQ(l.find("Error"), std::string::npos) << l;
  EXPECT_TRUE(creaseNotKept(log));
  EXPECT_TRUE(surfacesWithoutElements().empty());
  std::size_t nonManifold = 0;
  const std::size_t free = freeMeshEdges(&nonManifold).size();
  EXPECT_EQ(nonManifold, 0u);
  EXPECT_GE(free, 4u); // the sector's sides only, at about 0.8
  EXPECT_LT(free, 20u);
  EXPECT_EQ(nodesOutsideTriangles(), 0u);

  log = remeshWithRecipe(bentCrease(), 0.1);
  EXPECT_FALSE(creaseNotKept(log));
  int embedded = 0;
  for(const auto &l : log)
    embedded += l.find("kept as embedded curve") != std::string::npos;
  EXPECT_EQ(embedded, 1);
  EXPECT_EQ(nodesOutsideTriangles(), 0u);
}

TEST(creaseChains, creaseTooSmallWhenShortAndBentOrEndingByAnotherCurve)
{
  const double size = 1.;
  // a hairpin 1.7 sizes long, its ends 0.6 of that apart
  const std::vector<SPoint3> hairpin = {
    SPoint3(0., 0., 0.), SPoint3(0.85, 0.3, 0.), SPoint3(0., 0.6, 0.)};
  EXPECT_TRUE(creaseTooSmallForMesh(hairpin, {}, size));
  // the same bend 3.4 sizes long: enough segments to follow it
  std::vector<SPoint3> large;
  for(SPoint3 p : hairpin) large.push_back(p * 2.);
  EXPECT_FALSE(creaseTooSmallForMesh(large, {}, size));
  // straight and 1.4 sizes long: kept, unless another curve passes within
  // half a size of an end
  const std::vector<SPoint3> straight = {
    SPoint3(0., 0., 0.), SPoint3(0.7, 0., 0.), SPoint3(1.4, 0., 0.)};
  const std::vector<SPoint3> far = {SPoint3(0., 0.6, 0.),
                                    SPoint3(1.4, 0.6, 0.)};
  const std::vector<SPoint3> nearEnd = {SPoint3(1.7, -1., 0.),
                                        SPoint3(1.7, 1., 0.)};
  EXPECT_FALSE(creaseTooSmallForMesh(straight, {}, size));
  EXPECT_FALSE(creaseTooSmallForMesh(straight, {far}, size));
  EXPECT_TRUE(creaseTooSmallForMesh(straight, {far, nearEnd}, size));
  // long and straight: kept whatever passes by
  std::vector<SPoint3> longer;
  for(SPoint3 p : straight) longer.push_back(p * 2.5);
  EXPECT_FALSE(creaseTooSmallForMesh(longer, {nearEnd}, size));
  // a hairpin 6 sizes long, its legs 0.3 of a size apart: too small
  // whatever its length; its legs 1.5 sizes apart: kept
  for(double gap : {0.3, 1.5}) {
    const std::vector<SPoint3> pin = {SPoint3(0., 0., 0.), SPoint3(3., 0., 0.),
                                      SPoint3(3., gap, 0.),
                                      SPoint3(0., gap, 0.)};
    EXPECT_EQ(creaseTooSmallForMesh(pin, {}, size), gap < 0.5) << gap;
  }
  // three points whose second segment passes 0.2 of a size by the first
  // point, 5.6 sizes long: too small (its mesh: a triangle between its
  // first and last segments)
  const std::vector<SPoint3> passing = {
    SPoint3(0., 0., 0.), SPoint3(0., 0., -2.8), SPoint3(0.2, 0., 2.8)};
  EXPECT_TRUE(creaseTooSmallForMesh(passing, {}, size));
  // a crease of one point, or no size: nothing to say
  EXPECT_FALSE(creaseTooSmallForMesh({SPoint3(0., 0., 0.)}, {}, size));
  EXPECT_FALSE(creaseTooSmallForMesh(hairpin, {}, 0.));
}

// A plate (y = 0, 0 <= x <= 1) with a wall going up from x = 1 (the crease
// between them along x = 1, folded by `fold` radians): a polyline along
// the plate's far side x = 0 is 1 from the crease
namespace {

  testTriangulation plateAndWall(double fold)
  {
    testTriangulation t = rectangleGrid(4, 4, 2., 1.);
    for(auto &p : t.points)
      if(p.x() > 1.)
        p = SPoint3(1. + (p.x() - 1.) * std::cos(fold), p.y(),
                    (p.x() - 1.) * std::sin(fold));
    return t;
  }

} // namespace

TEST(creaseChains, creaseWithinADistanceOfACurve)
{
  const testTriangulation t = plateAndWall(M_PI / 2.);
  const std::vector<SPoint3> nearSide = {SPoint3(0.8, 0., 0.),
                                         SPoint3(0.8, 1., 0.)};
  const std::vector<SPoint3> farSide = {SPoint3(0., 0., 0.),
                                        SPoint3(0., 1., 0.)};
  EXPECT_TRUE(creaseWithin(t.points, t.triangles, nearSide, 0.25, M_PI / 3.));
  EXPECT_FALSE(creaseWithin(t.points, t.triangles, farSide, 0.25, M_PI / 3.));
  EXPECT_TRUE(creaseWithin(t.points, t.triangles, farSide, 1.01, M_PI / 3.));
  // a fold of 45 degrees is no crease of 60
  const testTriangulation gentle = plateAndWall(M_PI / 4.);
  EXPECT_FALSE(
    creaseWithin(gentle.points, gentle.triangles, nearSide, 0.25, M_PI / 3.));
  EXPECT_TRUE(
    creaseWithin(gentle.points, gentle.triangles, nearSide, 0.25, M_PI / 6.));
}
