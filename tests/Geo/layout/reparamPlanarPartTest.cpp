// Reparam - a planar part of the layout is mapped by its projection on its
// plane, Gmsh's own parametrization of a planar discrete face: its hole
// left free, the input's rounding-scale folds counted as degenerate, not
// as flips that would cut it

#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "testPatches.h"
#include <gtest/gtest.h>
#include <cmath>
#include <string>

namespace {

  // A plate with a window, and on its outline a sliver turned over onto it
  // by `overlap` of the plate (the outline of a CAD export doubling back
  // between two nodes that were one before rounding)
  testTriangulation plateWithTurnedSliver(double overlap)
  {
    testTriangulation t = polarDiskWithHoles(8, 48, {{{3, 6, 0, 12}}});
    for(const auto &tri : t.triangles)
      for(int k = 0; k < 3; k++) {
        const int a = tri[k], b = tri[(k + 1) % 3];
        const double ra = std::hypot(t.points[a].x(), t.points[a].y()),
                     rb = std::hypot(t.points[b].x(), t.points[b].y());
        if(std::fabs(ra - 1.) > 1e-12 || std::fabs(rb - 1.) > 1e-12) continue;
        const SPoint3 m = (t.points[a] + t.points[b]) * (0.5 * (1. - overlap));
        t.points.push_back(m);
        t.triangles.push_back({{b, a, (int)t.points.size() - 1}});
        return t;
      }
    return t;
  }

  std::size_t countLines(const std::vector<std::string> &log,
                         const std::string &what)
  {
    std::size_t n = 0;
    for(const std::string &l : log) n += l.find(what) != std::string::npos;
    return n;
  }

} // namespace

TEST(planarPart, isMappedOnItsPlaneWithItsHoleAndItsRoundingFolds)
{
  const testTriangulation plate = plateWithTurnedSliver(1e-9);
  std::vector<std::string> log = remeshWithRecipe(plate, 0.1);
  EXPECT_EQ(countLines(log, "parts because"), 0u);
  EXPECT_GT(countLines(log, "plane projection map: 0 flipped, 0 folds, 1 "
                            "degenerate -> one-to-one"),
            0u);
  EXPECT_GT(countLines(log, "1 hole (0 filled)"), 0u);
  EXPECT_EQ(countLines(log, "Error"), 0u);
  EXPECT_EQ(countLines(log, "Warning"), 0u);
  gmsh::vectorpair faces;
  gmsh::model::getEntities(faces, 2);
  EXPECT_EQ(faces.size(), 1u);
  EXPECT_TRUE(surfacesWithoutElements().empty());
  // the window stays a hole: two loops of free edges, none of three
  std::size_t nonManifold = 0;
  EXPECT_GT(freeMeshEdges(&nonManifold).size(), 48u);
  EXPECT_EQ(nonManifold, 0u);
}
