// Reparam - faces narrower than a quarter of their mesh size: their curves
// are crossed by the optimization, their slivers mended

#include <algorithm>
#include <cmath>
#include <string>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamLayout.h"
#include "reparamNoiseFaces.h"
#include "surfaceMesh.h"
#include "testPatches.h"
#include "triangleQuality.h"

using namespace reparam;

namespace {

  // A plate with a step: flat for x in [0, 1], a strip `width` wide rising
  // at 60 degrees, flat again for one more unit; 1 wide along y. Its two
  // creases (60 degrees) bound the strip as a feature patch, on a grid of
  // half the strip's width
  testTriangulation steppedPlate(double width)
  {
    const double step = 0.5 * width, length = 2. + width;
    testTriangulation t = rectangleGrid(
      (int)std::lround(length / step), (int)std::lround(1. / step), length, 1.);
    const double c = std::cos(M_PI / 3.), s = std::sin(M_PI / 3.);
    for(SPoint3 &p : t.points) {
      const double x = p.x();
      if(x <= 1.)
        p = SPoint3(x, p.y(), 0.);
      else if(x <= 1. + width + 1e-12)
        p = SPoint3(1. + (x - 1.) * c, p.y(), (x - 1.) * s);
      else
        p = SPoint3(1. + width * c + (x - 1. - width), p.y(), width * s);
    }
    return t;
  }

  double worstKappa()
  {
    double worst = 1.;
    GModel *m = GModel::current();
    for(auto it = m->firstFace(); it != m->lastFace(); ++it)
      for(MTriangle *t : (*it)->triangles)
        worst = std::min(worst, triangleKappa(t->getVertex(0)->point(),
                                              t->getVertex(1)->point(),
                                              t->getVertex(2)->point()));
    return worst;
  }

  bool logHas(const std::vector<std::string> &log, const std::string &what)
  {
    for(const std::string &l : log)
      if(l.find(what) != std::string::npos) return true;
    return false;
  }

} // namespace

TEST(noiseFaces, widthIsTwiceTheAreaOverTheBoundary)
{
  // a 1 x 0.1 rectangle of two triangles: 2 * 0.1 / 2.2
  surfaceMesh strip;
  strip.points = {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(1, 0.1, 0),
                  SPoint3(0, 0.1, 0)};
  strip.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  EXPECT_NEAR(triangulationWidth(strip), 0.2 / 2.2, 1e-12);
  double area, length;
  areaAndBoundaryLength(strip.points, {0, 1, 2, 0, 2, 3}, area, length);
  EXPECT_NEAR(area, 0.1, 1e-12);
  EXPECT_NEAR(length, 2.2, 1e-12);
  EXPECT_EQ(triangulationWidth(surfaceMesh()), 0.);
  // a closed tetrahedron has no boundary
  surfaceMesh closed;
  closed.points = {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(0, 1, 0),
                   SPoint3(0, 0, 1)};
  closed.triangles = {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{0, 3, 2}}};
  EXPECT_GT(triangulationWidth(closed), 1e299);
}

TEST(noiseFaces, aStripNarrowerThanAQuarterOfTheSizeIsCrossed)
{
  // strip 0.04 wide, meshed at 0.25: its curves' nodes alone would make
  // triangles of kappa about 0.3 across it
  const std::vector<std::string> log =
    remeshWithRecipe(steppedPlate(0.04), 0.25);
  EXPECT_FALSE(logHas(log, "Error"));
  EXPECT_TRUE(logHas(log, "narrower than a quarter of the mesh size"));
  EXPECT_GT(worstKappa(), 0.5); // measured 0.678; 0.334 with its curves kept
  // the report names the strip with its triangles' kappa mean
  EXPECT_TRUE(logHas(log, "on the 1 surface narrower than a quarter of the "
                          "size asked (3;"));
  EXPECT_TRUE(surfacesWithoutElements().empty());
  std::size_t nonManifold = 0;
  freeMeshEdges(&nonManifold);
  EXPECT_EQ(nonManifold, 0u);
}

TEST(noiseFaces, aStripWiderThanThatKeepsItsCurves)
{
  // the same strip meshed at 0.1: 0.4 of the size, no noise
  const std::vector<std::string> log =
    remeshWithRecipe(steppedPlate(0.04), 0.1);
  EXPECT_FALSE(logHas(log, "narrower than a quarter of the mesh size"));
  EXPECT_TRUE(reparamNoiseFaceCurves(GModel::current()).empty());
}

TEST(noiseFaces, aFinOnAnInnerEdgeStaysAFin)
{
  // a unit square on a grid of 0.05 with one triangle standing on an inner
  // edge (a fin, as photogrammetry leaves): the edge is used three times,
  // and the fin's curve along it has one face on both sides and the fin on
  // a third; the fin is noise at 0.25 but the optimization must not take
  // its curves as crossed (it folded the fin into the plate: its two free
  // edges, a boundary of the input, gone)
  testTriangulation t = rectangleGrid(20, 20, 1., 1.);
  const int a = 10 * 21 + 10, b = a + 1; // the edge (0.5, 0.5)-(0.55, 0.5)
  t.points.push_back(SPoint3(0.525, 0.5, 0.02));
  t.triangles.push_back({a, b, (int)t.points.size() - 1});
  const std::vector<std::string> log = remeshWithRecipe(t, 0.25);
  EXPECT_FALSE(logHas(log, "Error"));
  EXPECT_TRUE(surfacesWithoutElements().empty());
  // the fin's free edges stay free edges off the square's sides
  std::size_t nonManifold = 0, inner = 0;
  std::vector<double> coord, param;
  for(const auto &e : freeMeshEdges(&nonManifold)) {
    bool onSide = false;
    for(std::size_t tag : {e.first, e.second}) {
      gmsh::model::mesh::getNode(tag, coord, param);
      onSide = onSide || std::fabs(coord[0] - 0.5) > 0.49 ||
               std::fabs(coord[1] - 0.5) > 0.49;
    }
    if(!onSide) inner++;
  }
  EXPECT_GE(inner, 2u);
  EXPECT_GE(nonManifold, 1u);
  // and in its plane: no triangle of the plate folded up onto it
  std::size_t offPlane = 0;
  for(GFace *gf : GModel::current()->getFaces())
    for(MTriangle *tr : gf->triangles) {
      bool up = false, off = false;
      for(int k = 0; k < 3; k++) {
        up = up || tr->getVertex(k)->z() > 1e-9;
        off = off || std::fabs(tr->getVertex(k)->y() - 0.5) > 1e-9;
      }
      if(up && off) offPlane++;
    }
  EXPECT_EQ(offPlane, 0u);
  // its curve along the inner edge has three sides: never crossed
  EXPECT_TRUE(reparamNoiseFaceCurves(GModel::current()).empty());
}
