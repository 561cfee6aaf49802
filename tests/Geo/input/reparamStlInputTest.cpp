// Reparam - an STL with NaN or infinite coordinates: its bad facets are
// dropped with a warning instead of crashing Gmsh's reader

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <gtest/gtest.h>
#include "gmsh.h"
#include "reparamHooks.h"


namespace {

  // Merges file into a cleared model; whether the log has `text`
  bool mergeLogs(const std::string &file, const std::string &text)
  {
    gmsh::clear();
    gmsh::logger::start();
    gmsh::merge(file);
    std::vector<std::string> log;
    gmsh::logger::get(log);
    gmsh::logger::stop();
    for(const auto &l : log)
      if(l.find(text) != std::string::npos) return true;
    return false;
  }

  // The model's triangles
  std::size_t triangleCount()
  {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(2, tags, nodes);
    return tags.size();
  }

} // namespace

TEST(reparamStlInput, facetsWithNonFiniteCornersAreDropped)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::vector<SPoint3> > points = {
    {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(0, 1, 0), SPoint3(nan, 0, 0),
     SPoint3(1, 0, 0), SPoint3(0, 1, 0), SPoint3(0, 0, 0), SPoint3(2, 2, 0),
     SPoint3(0, 2, 0)},
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
    std::fprintf(fp,
                 "facet normal 0 0 1\nouter loop\nvertex %s\nvertex %s\n"
                 "vertex %s\nendloop\nendfacet\n",
                 f[0], f[1], f[2]);
  std::fprintf(fp, "endsolid s\n");
  std::fclose(fp);
  EXPECT_TRUE(mergeLogs(file, "1 STL facets with a NaN"));
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

namespace {

  // An ASCII STL of a 4 x 4 grid of the unit square (32 facets, all up)
  // with the facets `reversed` turned down and facet 0 written twice
  std::string gridStl(const std::vector<int> &reversed)
  {
    const std::string file = std::string(::testing::TempDir()) + "reversed.stl";
    FILE *fp = std::fopen(file.c_str(), "w");
    std::fprintf(fp, "solid s\n");
    int n = 0;
    auto facet = [&](double ax, double ay, double bx, double by, double cx,
                     double cy) {
      bool down = false;
      for(int r : reversed) down = down || r == n;
      if(down) std::swap(bx, cx), std::swap(by, cy);
      std::fprintf(fp,
                   "facet normal 0 0 1\nouter loop\nvertex %g %g 0\n"
                   "vertex %g %g 0\nvertex %g %g 0\nendloop\nendfacet\n",
                   ax, ay, bx, by, cx, cy);
      n++;
    };
    for(int i = 0; i < 4; i++)
      for(int j = 0; j < 4; j++) {
        const double x = i / 4., y = j / 4., h = 0.25;
        facet(x, y, x + h, y, x + h, y + h);
        facet(x, y, x + h, y + h, x, y + h);
      }
    facet(0, 0, 0.25, 0, 0.25, 0.25); // facet 0 again
    std::fprintf(fp, "endsolid s\n");
    std::fclose(fp);
    return file;
  }

  // Edges of the model's triangles used twice in the same direction
  std::size_t edgesRunTwiceTheSameWay()
  {
    std::map<std::pair<std::size_t, std::size_t>, int> directed;
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(2, tags, nodes);
    std::size_t twice = 0;
    for(std::size_t i = 0; i + 2 < nodes.size(); i += 3)
      for(int k = 0; k < 3; k++)
        twice += ++directed[{nodes[i + k], nodes[i + (k + 1) % 3]}] == 2;
    return twice;
  }

} // namespace

TEST(reparamStlInput, reversedFacetsAreTurnedAndRepeatedOnesDropped)
{
  const std::string file = gridStl({3, 12, 13, 30});
  EXPECT_TRUE(mergeLogs(file, "STL input repaired: 4 facets turned to agree "
                              "with their neighbours, 1 facets repeating "
                              "another's nodes dropped"));
  EXPECT_EQ(triangleCount(), 32u);
  EXPECT_EQ(edgesRunTwiceTheSameWay(), 0u);
  // Gmsh's own map reads the file as it is (its reader keeps one of two
  // facets on the same nodes, but not their orientation)
  gmsh::clear();
  gmsh::option::setNumber("Mesh.CompoundParametrization", 0);
  gmsh::merge(file);
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  EXPECT_GT(edgesRunTwiceTheSameWay(), 0u);
}

TEST(reparamStlInput, anEmptyFileIsAnError)
{
  const std::string file = std::string(::testing::TempDir()) + "empty.stl";
  FILE *fp = std::fopen(file.c_str(), "w");
  ASSERT_NE(fp, nullptr);
  std::fprintf(fp, "solid e\nendsolid e\n");
  std::fclose(fp);
  EXPECT_TRUE(mergeLogs(file, "Error: Reparam: the STL file has no complete "
                              "facet with finite coordinates"));
  std::remove(file.c_str());
}

TEST(reparamStlInput, aFileOfZeroAreaFacetsIsAnError)
{
  // collinear corners, and a repeated corner
  std::vector<std::vector<SPoint3> > points = {
    {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(2, 0, 0), SPoint3(0, 0, 0),
     SPoint3(0, 0, 0), SPoint3(1, 1, 0)}};
  SBoundingBox3d box;
  gmsh::logger::start();
  reparamDropInvalidStlFacets(points, box);
  std::vector<std::string> log;
  gmsh::logger::get(log);
  gmsh::logger::stop();
  bool error = false;
  for(const auto &l : log)
    error = error || l.find("the 2 facets of the STL file all have zero "
                            "area") != std::string::npos;
  EXPECT_TRUE(error);
}

namespace {

  // An ASCII STL of an octahedron of half-axes r, r and r c around
  // (x, 0, 0) per entry (x, r, c)
  std::string octahedraStl(const std::string &name,
                           const std::vector<std::array<double, 3> > &pieces)
  {
    const std::string file = std::string(::testing::TempDir()) + name;
    FILE *fp = std::fopen(file.c_str(), "w");
    std::fprintf(fp, "solid s\n");
    for(const std::array<double, 3> &p : pieces) {
      const double x = p[0], r = p[1], c = r * p[2];
      const double ring[4][3] = {
        {x + r, 0, 0}, {x, r, 0}, {x - r, 0, 0}, {x, -r, 0}};
      const double top[3] = {x, 0, c}, bottom[3] = {x, 0, -c};
      auto facet = [&](const double *a, const double *b, const double *d) {
        std::fprintf(fp,
                     "facet normal 0 0 1\nouter loop\nvertex %.17g %.17g "
                     "%.17g\nvertex %.17g %.17g %.17g\nvertex %.17g %.17g "
                     "%.17g\nendloop\nendfacet\n",
                     a[0], a[1], a[2], b[0], b[1], b[2], d[0], d[1], d[2]);
      };
      for(int k = 0; k < 4; k++) {
        facet(ring[k], ring[(k + 1) % 4], top);
        facet(ring[(k + 1) % 4], ring[k], bottom);
      }
    }
    std::fprintf(fp, "endsolid s\n");
    std::fclose(fp);
    return file;
  }

} // namespace

TEST(reparamStlInput, aFlatClosedPieceSmallerThanTheFacetsIsDropped)
{
  // a round octahedron of radius 1 (facets' size 1.3) and a flat one of
  // radius 0.1 a thousandth as thick: dropped whole, the round one kept
  const std::string file =
    octahedraStl("flat.stl", {{{0., 1., 1.}}, {{3., 0.1, 1e-3}}});
  EXPECT_TRUE(mergeLogs(file, "0 facets turned to agree with their "
                              "neighbours, 8 facets dropped (repeating "
                              "another's nodes, or of 1 closed pieces"));
  EXPECT_EQ(triangleCount(), 8u);
  std::vector<std::size_t> nodeTags;
  std::vector<double> xyz, uvw;
  gmsh::model::mesh::getNodes(nodeTags, xyz, uvw);
  for(std::size_t i = 0; i < xyz.size(); i += 3) EXPECT_LE(xyz[i], 1.);
  // the same flat piece as large as the facets is the input's: kept
  const std::string large =
    octahedraStl("flatLarge.stl", {{{0., 1., 1.}}, {{3., 1., 1e-3}}});
  EXPECT_FALSE(mergeLogs(large, "STL input repaired"));
  EXPECT_EQ(triangleCount(), 16u);
}
