// Reparam - the curves ClassifySurfaces builds from Reparam's layout: every
// face bounded by closed loops, also where two loops touch at one node; the
// sharp edges that are features (Mesh.CompoundFeatureScale)

#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "testPatches.h"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace {

  // Two triangles touching at one node (a bow tie, as photogrammetry and
  // non-manifold exports have them), and a third one on the right: the
  // node they share is where the loops' curves break. Gmsh chains a loop's
  // segments in the order of their nodes' tags: `rank` (0, 1 or 2) is the
  // shared node's rank among the left triangle's tags.
  testTriangulation bowTie(int rank)
  {
    testTriangulation t;
    t.points.resize(3);
    const int shared = rank, up = (rank + 1) % 3, down = (rank + 2) % 3;
    t.points[shared] = SPoint3(0, 0, 0);
    t.points[up] = SPoint3(-1, 0.3, 0);
    t.points[down] = SPoint3(-1, -0.3, 0);
    t.points.insert(t.points.end(), {SPoint3(1, 0.2, 0), SPoint3(1, -0.2, 0),
                                     SPoint3(2, 0.3, 0), SPoint3(2, -0.3, 0)});
    t.triangles = {{{shared, up, down}},
                   {{shared, 4, 3}},
                   // a wider right part than the left triangle, so that the
                   // layout's noise test leaves both alone
                   {{3, 4, 6}},
                   {{3, 6, 5}}};
    return t;
  }

  // The nodes met an odd number of times by the segments of a surface's
  // curves: none when its boundary is closed loops
  std::size_t openEndsOfSurface(int tag)
  {
    gmsh::vectorpair curves;
    gmsh::model::getBoundary({{2, tag}}, curves, false, false, false);
    std::map<std::size_t, int> uses;
    for(const auto &c : curves) {
      std::vector<std::size_t> tags, nodes;
      gmsh::model::mesh::getElementsByType(1, tags, nodes, c.second);
      for(std::size_t n : nodes) uses[n]++;
    }
    std::size_t open = 0;
    for(const auto &u : uses)
      if(u.second % 2) open++;
    return open;
  }

  // Stairs of 12 unit treads and risers, 6 wide, a cell of the grid per
  // unit: the voxel faces of a mask of an inclined plane
  testTriangulation staircase()
  {
    const int steps = 12, perUnit = 1;
    testTriangulation t =
      rectangleGrid(2 * steps * perUnit, 6 * perUnit, 2. * steps, 6.);
    for(SPoint3 &p : t.points) {
      const double s = p.x(); // along the profile: tread, riser, tread...
      const int k = std::min((int)std::floor(s / 2.), steps - 1);
      const double along = s - 2. * k;
      p = along <= 1. ? SPoint3(k + along, p.y(), k) :
                        SPoint3(k + 1., p.y(), k + along - 1.);
    }
    return t;
  }

  std::size_t numSurfaces()
  {
    gmsh::vectorpair faces;
    gmsh::model::getEntities(faces, 2);
    return faces.size();
  }

} // namespace

TEST(layoutCurves, featureScaleSmoothsAStaircase)
{
  // every tread and riser a surface
  std::vector<std::string> log = remeshWithRecipe(staircase(), 0.5);
  EXPECT_EQ(numSurfaces(), 24u);
  gmsh::option::setNumber("Mesh.CompoundFeatureScale", 3);
  log = remeshWithRecipe(staircase(), 0.5);
  gmsh::option::setNumber("Mesh.CompoundFeatureScale", 0);
  // the steps near the ends stay: a few surfaces
  EXPECT_LE(numSurfaces(), 6u);
  bool logged = false;
  for(const std::string &l : log) {
    EXPECT_EQ(l.find("Error"), std::string::npos) << l;
    logged |= l.find("(Mesh.CompoundFeatureScale)") != std::string::npos;
  }
  EXPECT_TRUE(logged);
  EXPECT_TRUE(surfacesWithoutElements().empty());
}

TEST(layoutCurves, loopsTouchingAtOneNodeStayClosed)
{
  // Gmsh's rotation of a closed chain broken at one node only used to drop
  // its closing segment: "The 1D mesh seems not to be forming a closed
  // loop", and the face left unmeshed (a hole)
  for(int rank = 0; rank < 3; rank++) {
    SCOPED_TRACE("shared node's rank " + std::to_string(rank));
    const std::vector<std::string> log = remeshWithRecipe(bowTie(rank), 0.2);
    for(const std::string &l : log)
      EXPECT_EQ(l.find("Error"), std::string::npos) << l;
    gmsh::vectorpair faces;
    gmsh::model::getEntities(faces, 2);
    EXPECT_EQ(faces.size(), 2u);
    for(const auto &f : faces) EXPECT_EQ(openEndsOfSurface(f.second), 0u);
    EXPECT_TRUE(surfacesWithoutElements().empty());
    // the free edges of both loops, no edge of three triangles
    std::size_t nonManifold = 0;
    EXPECT_GT(freeMeshEdges(&nonManifold).size(), 6u);
    EXPECT_EQ(nonManifold, 0u);
  }
}
