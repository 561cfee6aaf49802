// Reparam - the sizes of a discrete face's short boundary segments graded
// into it (Mesh.CompoundMeshSizeGradient) instead of Gmsh's interpolation
// over the whole face

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <gtest/gtest.h>
#include "BackgroundMeshTools.h"
#include "GFace.h"
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "gradedBoundarySize.h"
#include "reparamSizeGrading.h"
#include "triangleQuality.h"

using namespace reparam;

TEST(gradedBoundarySize, sizeGrowsWithTheDistanceToTheSmallestNode)
{
  const gradedBoundarySize size({SPoint3(0, 0, 0), SPoint3(1, 0, 0)},
                                {0.02, 0.05}, 0.3, 0.1);
  EXPECT_NEAR(size(SPoint3(0, 0, 0), 0.1), 0.02, 1e-12);
  EXPECT_NEAR(size(SPoint3(0, 0.1, 0), 0.1), 0.02 + 0.03, 1e-12);
  // nearer the larger node, its size wins
  EXPECT_NEAR(size(SPoint3(1, 0.05, 0), 0.1), 0.05 + 0.015, 1e-12);
  // far from both: the bound
  EXPECT_NEAR(size(SPoint3(0.5, 3, 0), 0.1), 0.1, 1e-12);
  EXPECT_EQ(size.size(), 2u);
}

TEST(gradedBoundarySize, shortestSegmentAtEachNode)
{
  const std::vector<SPoint3> nodes = {SPoint3(0, 0, 0), SPoint3(0.02, 0, 0),
                                      SPoint3(0.2, 0, 0), SPoint3(5, 5, 5)};
  const std::vector<double> l = shortestSegmentAtNodes(nodes, {{0, 1}, {1, 2}});
  ASSERT_EQ(l.size(), 4u);
  EXPECT_NEAR(l[0], 0.02, 1e-12);
  EXPECT_NEAR(l[1], 0.02, 1e-12);
  EXPECT_NEAR(l[2], 0.18, 1e-12);
  EXPECT_EQ(l[3], 0.); // no segment
}

namespace {

  // gmsh::model::mesh::generate(dim) at a uniform `size` with
  // Mesh.CompoundMeshSizeGradient = gradient, the options reset after
  void generateAt(int dim, double size, double gradient)
  {
    gmsh::option::setNumber("Mesh.CompoundMeshSizeGradient", gradient);
    gmsh::option::setNumber("Mesh.MeshSizeMin", size);
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);
    gmsh::model::mesh::generate(dim);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
    gmsh::option::setNumber("Mesh.CompoundMeshSizeGradient", 0.5);
  }

  struct meshedSquare {
    std::size_t triangles = 0;
    double worstKappa = 1.;
  };

  meshedSquare meshSquare(double gradient, double size)
  {
    squareWithAShortCurve();
    generateAt(2, size, gradient);
    meshedSquare r;
    GFace *gf = GModel::current()->getFaceByTag(1);
    for(MTriangle *t : gf->triangles) {
      r.triangles++;
      r.worstKappa =
        std::min(r.worstKappa, triangleKappa(t->getVertex(0)->point(),
                                             t->getVertex(1)->point(),
                                             t->getVertex(2)->point()));
    }
    return r;
  }

} // namespace

TEST(reparamSizeGrading, theFaceSizesGrowAwayFromAShortCurve)
{
  squareWithAShortCurve();
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.1);
  // the curves' own grading off: their even segments, the short curve's
  // two of 0.01
  gmsh::option::setNumber("Mesh.CompoundMeshSizeGradient", 0);
  gmsh::model::mesh::generate(1);
  gmsh::option::setNumber("Mesh.CompoundMeshSizeGradient", 0.5);
  GFace *gf = GModel::current()->getFaceByTag(1);
  ASSERT_TRUE(gf);
  auto size = [gf](double x, double y) {
    return BGM_MeshSize(gf, 0., 0., x, y, 0.);
  };
  EXPECT_NEAR(size(0.01, 0.1), 0.1, 1e-12); // not while not meshing
  reparamBeginSizeGrading(gf);
  EXPECT_EQ(gf->getMeshSizeFromBoundary(), 0); // Gmsh's extension off
  // the short curve has 2 segments of 0.01 (Gmsh's Mesh.MinimumCurveNodes)
  EXPECT_NEAR(size(0., 0.), 0.01, 1e-9);
  // 0.1 above its middle node
  EXPECT_NEAR(size(0.01, 0.1), 0.01 + 0.5 * 0.1, 1e-9);
  EXPECT_NEAR(size(0.5, 0.5), 0.1, 1e-12);
  // the size without the grading, for the checks of the mesh made: 0.1
  EXPECT_NEAR(reparamUngradedMeshSize(gf, SPoint3(0.01, 0.1, 0.)), 0.1, 1e-12);
  EXPECT_NEAR(size(0.01, 0.1), 0.01 + 0.5 * 0.1, 1e-9); // graded again
  // other entities keep theirs
  GEdge *ge = GModel::current()->getEdgeByTag(2);
  EXPECT_NEAR(BGM_MeshSize(ge, 0., 0., 0.01, 0., 0.), 0.1, 1e-12);
  reparamEndSizeGrading(gf);
  EXPECT_EQ(gf->getMeshSizeFromBoundary(), 1);
  EXPECT_NEAR(size(0.01, 0.1), 0.1, 1e-12);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
}

TEST(reparamSizeGrading, aShortCurveGetsAGradedMeshOfTheSizeAsked)
{
  const meshedSquare interpolated = meshSquare(0., 0.05);
  const meshedSquare graded = meshSquare(0.5, 0.05);
  // a uniform mesh of the unit square at 0.05: about 2 / (0.05^2 sqrt(3) /
  // 2) = 924 triangles
  EXPECT_LT(graded.triangles, 1000u);
  // Gmsh's interpolation: 0.32 next to the short curve; the faces' grading
  // alone (even curve segments): 0.52; graded curves: 0.71
  EXPECT_GT(graded.worstKappa, 0.65);
  EXPECT_GT(graded.worstKappa, interpolated.worstKappa);
  printf("triangles %lu -> %lu, worst kappa %g -> %g\n", interpolated.triangles,
         graded.triangles, interpolated.worstKappa, graded.worstKappa);
}

namespace {

  // The lengths of the segments of curve 2 (the bottom side from the short
  // curve's end at x = 0.02 to the corner), from that end on
  std::vector<double> bottomSegments(double gradient, bool tip = false)
  {
    squareWithAShortCurve();
    if(tip) {
      // a point embedded in the square 0.03 above the bottom side's middle
      gmsh::model::addDiscreteEntity(0, 10);
      gmsh::model::mesh::addNodes(0, 10, {100000}, {0.5, 0.03, 0.});
      gmsh::model::mesh::embed(0, {10}, 2, 1);
    }
    generateAt(1, 0.1, gradient);
    std::vector<double> x;
    for(MLine *l : GModel::current()->getEdgeByTag(2)->lines)
      for(int k = 0; k < 2; k++) x.push_back(l->getVertex(k)->x());
    std::sort(x.begin(), x.end());
    x.erase(std::unique(x.begin(), x.end()), x.end());
    std::vector<double> lengths;
    for(std::size_t i = 0; i + 1 < x.size(); i++)
      lengths.push_back(x[i + 1] - x[i]);
    return lengths;
  }

} // namespace

TEST(reparamSizeGrading, curveSizesGrowFromTheEndsOfShortCurves)
{
  // the short curve (0.02) has 2 segments of 0.01; its neighbour starts
  // at about that and grows by half its distance to it, to 0.1
  const std::vector<double> graded = bottomSegments(0.5);
  ASSERT_GT(graded.size(), 10u);
  EXPECT_LT(graded.front(), 0.03);
  EXPECT_NEAR(graded.back(), 0.1, 0.02);
  for(std::size_t i = 0; i + 1 < graded.size(); i++)
    EXPECT_LT(graded[i + 1], 2. * graded[i]) << i; // no jump
  // Gmsh's own: even segments of about 0.1 from the short curve on
  const std::vector<double> even = bottomSegments(0.);
  EXPECT_GT(even.front(), 0.09);
  EXPECT_LT(even.size(), graded.size());
}

TEST(reparamSizeGrading, aCurveGetsFinerNearAPointEmbeddedCloseToIt)
{
  // a tip kept as a node 0.03 from the bottom side (a third of the size):
  // the side's segments there about that long, not one triangle of 0.1
  // across; away from it the size again
  const std::vector<double> plain = bottomSegments(0.5);
  const std::vector<double> withTip = bottomSegments(0.5, true);
  auto shortestNear = [](const std::vector<double> &lengths, double x0) {
    double x = 0.02, shortest = 1.;
    for(double l : lengths) {
      if(std::fabs(x + 0.5 * l - x0) < 0.1) shortest = std::min(shortest, l);
      x += l;
    }
    return shortest;
  };
  EXPECT_GT(shortestNear(plain, 0.5), 0.08);
  EXPECT_LT(shortestNear(withTip, 0.5), 0.045);
  EXPECT_GT(shortestNear(withTip, 0.5), 0.02);
  EXPECT_NEAR(withTip.back(), 0.1, 0.02);
  for(std::size_t i = 0; i + 1 < withTip.size(); i++) {
    EXPECT_LT(withTip[i + 1], 2. * withTip[i]) << i; // no jump
    EXPECT_LT(withTip[i], 2. * withTip[i + 1]) << i;
  }
}

TEST(reparamSizeGrading, aCurveMeshOfBillionsOfSegmentsIsRefused)
{
  // a size 1e-9 on the unit square: 1e9 segments a side, hours of Gmsh's
  // 1D mesher; refused with an error, and meshed again once sized
  squareWithAShortCurve();
  gmsh::option::setNumber("Mesh.MeshSizeMin", 1e-9);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e-9);
  gmsh::logger::start();
  gmsh::model::mesh::generate(1);
  std::vector<std::string> log;
  gmsh::logger::get(log);
  gmsh::logger::stop();
  bool refused = false;
  for(const std::string &l : log)
    refused = refused || l.find("segments (length 0.98, mesh size 1e-09): "
                                "not meshed") != std::string::npos;
  EXPECT_TRUE(refused);
  // the side keeps the input's segments (of 0.025), not a billion
  GEdge *side = GModel::current()->getEdgeByTag(2);
  EXPECT_LT(side->lines.size(), 50u);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.1);
  gmsh::model::mesh::generate(1);
  EXPECT_GE(side->lines.size(), 10u); // graded from the short curve
  EXPECT_LT(side->lines.size(), 20u);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
}

namespace {

  // A cube of side `side` as 12 discrete triangles, classified at 40
  // degrees into its 6 faces and 12 edges (the STL recipe's geometry)
  void classifiedCube(double side)
  {
    gmsh::clear();
    gmsh::model::add("cube");
    gmsh::model::addDiscreteEntity(2, 1);
    std::vector<double> xyz;
    for(int k = 0; k < 8; k++)
      for(int d = 0; d < 3; d++) xyz.push_back(side * ((k >> d) & 1));
    gmsh::model::mesh::addNodes(2, 1, {1, 2, 3, 4, 5, 6, 7, 8}, xyz);
    // each face as two triangles, outward
    const std::vector<std::size_t> corners = {
      1, 3, 4, 1, 4, 2, 5, 6, 8, 5, 8, 7, 1, 2, 6, 1, 6, 5,
      3, 7, 8, 3, 8, 4, 1, 5, 7, 1, 7, 3, 2, 4, 8, 2, 8, 6};
    std::vector<std::size_t> tags;
    for(std::size_t t = 0; t < corners.size() / 3; t++) tags.push_back(t + 1);
    gmsh::model::mesh::addElementsByType(1, 2, tags, corners);
    gmsh::model::mesh::classifySurfaces(40. * M_PI / 180., true, true, M_PI);
    gmsh::model::mesh::createGeometry();
  }

  std::size_t meshTriangles()
  {
    std::size_t n = 0;
    std::vector<int> types;
    std::vector<std::vector<std::size_t> > elements, nodes;
    gmsh::model::mesh::getElements(types, elements, nodes, 2);
    for(std::size_t i = 0; i < types.size(); i++)
      if(types[i] == 2) n += elements[i].size();
    return n;
  }

} // namespace

namespace {

  // The errors for the curves refused and the warnings for the surfaces on
  // them that one Mesh 2 logs
  std::pair<int, int> refusedByMesh2()
  {
    gmsh::logger::start();
    gmsh::model::mesh::generate(2);
    std::vector<std::string> log;
    gmsh::logger::get(log);
    gmsh::logger::stop();
    std::pair<int, int> n(0, 0);
    for(const std::string &l : log) {
      n.first +=
        l.find("segments (length") != std::string::npos && l.find("Error") == 0;
      n.second += l.find("not meshed: its curve") != std::string::npos &&
                  l.find("Warning") == 0;
    }
    return n;
  }

} // namespace

TEST(reparamSizeGrading, aModelFarLargerThanTheSizeIsAnErrorNotAHang)
{
  // coordinates of 1e30 with the points' default size of 1e22: 1e8
  // segments on each edge, refused; the faces on them are not meshed
  // either (MeshAdapt refined one towards that size for hours)
  classifiedCube(1e30);
  EXPECT_EQ(refusedByMesh2(), std::make_pair(12, 6));
  EXPECT_EQ(meshTriangles(), 0u);
  // a size far below a unit cube's: the same; at its scale, every face is
  // meshed again (its curves first)
  classifiedCube(1.);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e-8);
  EXPECT_EQ(refusedByMesh2(), std::make_pair(12, 6));
  EXPECT_EQ(meshTriangles(), 0u);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.2);
  gmsh::model::mesh::generate(1);
  gmsh::model::mesh::generate(2);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
  EXPECT_GT(meshTriangles(), 6u * 20u);
}

namespace {

  // A planar frame: the unit square less its middle, bars `bar` wide, on a
  // grid of 0.05
  testTriangulation frame(double bar)
  {
    const testTriangulation grid = rectangleGrid(20, 20, 1., 1.);
    testTriangulation t;
    std::map<int, int> index;
    for(const auto &tri : grid.triangles) {
      double x = 0., y = 0.;
      for(int k : tri) {
        x += grid.points[k].x() / 3.;
        y += grid.points[k].y() / 3.;
      }
      if(x > bar && x < 1. - bar && y > bar && y < 1. - bar) continue;
      std::array<int, 3> kept;
      for(int k = 0; k < 3; k++) {
        auto it = index.emplace(tri[k], (int)t.points.size()).first;
        if(it->second == (int)t.points.size())
          t.points.push_back(grid.points[tri[k]]);
        kept[k] = it->second;
      }
      t.triangles.push_back(kept);
    }
    return t;
  }

  // The worst kappa and the count of the current model's triangles
  std::pair<double, std::size_t> worstAndCount()
  {
    double worst = 1.;
    std::size_t count = 0;
    for(auto it = GModel::current()->firstFace();
        it != GModel::current()->lastFace(); ++it)
      for(MTriangle *t : (*it)->triangles) {
        worst = std::min(worst, triangleKappa(t->getVertex(0)->point(),
                                              t->getVertex(1)->point(),
                                              t->getVertex(2)->point()));
        count++;
      }
    return {worst, count};
  }

} // namespace

TEST(reparamSizeGrading, aStripNarrowerThanTheSizeGetsSizesOfItsWidth)
{
  // bars 0.1 wide meshed at 0.3: one triangle across them either way, of
  // the size along them, or of about their width with the strips' sizes
  double off = -1.;
  gmsh::option::getNumber("Mesh.CompoundMeshSizeFromStrips", off);
  EXPECT_EQ(off, 0.); // the default
  gmsh::option::setNumber("Mesh.CompoundMeshSizeFromStrips", 1);
  const std::vector<std::string> log = remeshWithRecipe(frame(0.1), 0.3);
  gmsh::option::setNumber("Mesh.CompoundMeshSizeFromStrips", 0);
  const auto strips = worstAndCount();
  EXPECT_TRUE(std::any_of(log.begin(), log.end(), [](const std::string &l) {
    return l.find("narrower than the size: their curves get sizes of their "
                  "width") != std::string::npos;
  }));
  const std::vector<std::string> plainLog = remeshWithRecipe(frame(0.1), 0.3);
  const auto plain = worstAndCount();
  EXPECT_FALSE(
    std::any_of(plainLog.begin(), plainLog.end(), [](const std::string &l) {
      return l.find("sizes of their width") != std::string::npos;
    }));
  printf("worst kappa %g -> %g, triangles %lu -> %lu\n", plain.first,
         strips.first, plain.second, strips.second);
  // measured: 0.52 (26 triangles) -> 0.82 (66)
  EXPECT_GT(strips.first, 0.75);
  EXPECT_LT(plain.first, 0.55);
  // the bars' length (3.6) over their width, on both sides: about 72
  EXPECT_GT(strips.second, 60u);
  EXPECT_LT(strips.second, 90u);
}

namespace {

  // The triangles at the two points embedded 0.03 apart in the unit
  // square's middle (tips kept as nodes), meshed at 0.1: how many, their
  // worst kappa and longest edge
  std::size_t meshAroundCloseTips(double &worst, double &longest)
  {
    squareWithAShortCurve();
    for(int k = 0; k < 2; k++) {
      gmsh::model::addDiscreteEntity(0, 10 + k);
      gmsh::model::mesh::addNodes(0, 10 + k, {100000u + k},
                                  {0.5 + 0.03 * k, 0.5, 0.});
    }
    gmsh::model::mesh::embed(0, {10, 11}, 2, 1);
    generateAt(2, 0.1, 0.5);
    worst = 1.;
    longest = 0.;
    std::size_t count = 0;
    GModel *m = GModel::current();
    for(MTriangle *t : m->getFaceByTag(1)->triangles) {
      bool atTip = false;
      for(int j = 0; j < 3; j++) {
        const SPoint3 p = t->getVertex(j)->point();
        atTip |=
          std::fabs(p.y() - 0.5) < 1e-12 &&
          (std::fabs(p.x() - 0.5) < 1e-12 || std::fabs(p.x() - 0.53) < 1e-12);
      }
      if(!atTip) continue;
      count++;
      worst = std::min(worst, triangleKappa(t->getVertex(0)->point(),
                                            t->getVertex(1)->point(),
                                            t->getVertex(2)->point()));
      for(int j = 0; j < 3; j++)
        longest = std::max(longest, t->getVertex(j)->point().distance(
                                      t->getVertex((j + 1) % 3)->point()));
    }
    return count;
  }

} // namespace

TEST(reparamSizeGrading, twoTipsCloseTogetherGetTrianglesOfTheirDistance)
{
  // two tips a third of the size apart: the face's sizes grow from their
  // distance, small triangles around them (without: worst kappa 0.63 there,
  // edges of 0.10; Gmsh's own sizes, gradient 0: 0.85, 0.078)
  double worst = 0., longest = 0.;
  // both tips are nodes of the mesh, each with its fan
  EXPECT_GE(meshAroundCloseTips(worst, longest), 8u);
  EXPECT_GT(worst, 0.75);
  EXPECT_LT(longest, 0.07);
  printf("at the tips: worst kappa %g, longest edge %g\n", worst, longest);
}
