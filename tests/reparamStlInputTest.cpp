// Reparam - an STL with NaN or infinite coordinates: its bad facets are
// dropped with a warning instead of crashing Gmsh's reader

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <gtest/gtest.h>
#include "gmsh.h"
#include "reparamStlInput.h"

TEST(reparamStlInput, facetsWithNonFiniteCornersAreDropped)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::vector<SPoint3> > points = {
    {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(0, 1, 0),
     SPoint3(nan, 0, 0), SPoint3(1, 0, 0), SPoint3(0, 1, 0),
     SPoint3(0, 0, 0), SPoint3(2, 2, 0), SPoint3(0, 2, 0)},
    {SPoint3(0, 0, inf), SPoint3(1, 0, 0), SPoint3(0, 1, 0)}};
  SBoundingBox3d box;
  box += SPoint3(nan, nan, nan);
  EXPECT_EQ(reparamDropInvalidStlFacets(points, box), 2u);
  ASSERT_EQ(points[0].size(), 6u);
  EXPECT_EQ(points[0][3].x(), 0.);
  EXPECT_EQ(points[0][4].x(), 2.);
  EXPECT_TRUE(points[1].empty());
  EXPECT_EQ(box.max().x(), 2.);
  EXPECT_EQ(box.min().x(), 0.);
  // nothing to drop: the box is left as it is
  SBoundingBox3d unchanged;
  unchanged += SPoint3(5, 5, 5);
  EXPECT_EQ(reparamDropInvalidStlFacets(points, unchanged), 0u);
  EXPECT_EQ(unchanged.min().x(), 5.);
}

TEST(reparamStlInput, anStlWithANanNodeIsReadAndMeshedWithoutIt)
{
  // a square of 4 facets around a centre node, one facet with a NaN corner
  const std::string file = std::string(::testing::TempDir()) + "nan.stl";
  FILE *fp = std::fopen(file.c_str(), "w");
  ASSERT_NE(fp, nullptr);
  const char *corners[4][3] = {{"0 0 0", "1 0 0", "0.5 0.5 0"},
                               {"1 0 0", "1 1 0", "0.5 0.5 0"},
                               {"1 1 0", "0 1 0", "0.5 0.5 0"},
                               {"0 1 0", "nan 0 0", "0.5 0.5 0"}};
  std::fprintf(fp, "solid s\n");
  for(auto &f : corners)
    std::fprintf(fp, "facet normal 0 0 1\nouter loop\nvertex %s\nvertex %s\n"
                     "vertex %s\nendloop\nendfacet\n", f[0], f[1], f[2]);
  std::fprintf(fp, "endsolid s\n");
  std::fclose(fp);
  gmsh::clear();
  gmsh::logger::start();
  gmsh::merge(file);
  std::vector<std::string> log;
  gmsh::logger::get(log);
  gmsh::logger::stop();
  bool warned = false;
  for(const auto &l : log)
    warned |= l.find("1 STL facets with a NaN") != std::string::npos;
  EXPECT_TRUE(warned);
  std::vector<std::size_t> tags, nodes;
  gmsh::model::mesh::getElementsByType(2, tags, nodes);
  EXPECT_EQ(tags.size(), 3u);
  std::remove(file.c_str());
}

TEST(reparamStlInput, theCompleteFacetsOfAFileCutShortAreRead)
{
  // binary: 50 bytes a facet
  EXPECT_EQ(reparamCompleteStlFacets(10, 500), 10u);
  EXPECT_EQ(reparamCompleteStlFacets(10, 499), 9u);
  EXPECT_EQ(reparamCompleteStlFacets(10, 0), 0u);
  // ASCII: a last facet with two corners only
  std::vector<std::vector<SPoint3> > points = {
    {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(0, 1, 0), SPoint3(1, 1, 0),
     SPoint3(2, 1, 0)}};
  SBoundingBox3d box;
  EXPECT_EQ(reparamDropInvalidStlFacets(points, box), 0u);
  EXPECT_EQ(points[0].size(), 3u);
}
