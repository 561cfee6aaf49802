// Reparam - Plugin(SurfaceMeshQuality), Plugin(Parametrization) and the
// views they create

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "PView.h"
#include "PViewDataList.h"
#include "PViewOptions.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "quadQuality.h"
#include "reparamTriangleQuality.h"
#include "reparamViews.h"
#include "triangleQuality.h"

using namespace reparam;

namespace {

  void clearViews()
  {
    while(!PView::list.empty()) delete PView::list.back();
  }

  PViewDataList *viewData(const std::string &name)
  {
    for(PView *v : PView::list)
      if(v->getData()->getName() == name)
        return dynamic_cast<PViewDataList *>(v->getData());
    return nullptr;
  }

  PView *view(const std::string &name)
  {
    for(PView *v : PView::list)
      if(v->getData()->getName() == name) return v;
    return nullptr;
  }

  // List-based triangle i of `list` (9 coordinates then N values)
  SPoint3 corner(const std::vector<double> &list, std::size_t i, int corner,
                 int values)
  {
    const double *t = &list[i * (9 + values)];
    return SPoint3(t[corner], t[3 + corner], t[6 + corner]);
  }

  GFace *classifiedDome(int map)
  {
    gmsh::clear();
    clearViews();
    gmsh::option::setNumber("Mesh.CompoundParametrization", map);
    gmsh::merge(tutorialFile("dome.stl"));
    gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
    gmsh::model::mesh::createGeometry();
    gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
    for(auto it = GModel::current()->firstFace();
        it != GModel::current()->lastFace(); ++it)
      if(!(*it)->stl_triangles.empty()) return *it;
    return nullptr;
  }

  // Plugin(SurfaceMeshQuality)'s line against a reference: Hausdorff and
  // mean distance in %, elements against it (false if not logged)
  bool referenceLine(const std::vector<std::string> &log, double &hausdorff,
                     double &mean, unsigned long &against)
  {
    for(const std::string &line : log) {
      std::size_t at = line.find("): Hausdorff ");
      if(line.find("SurfaceMeshQuality: against") == std::string::npos ||
         at == std::string::npos)
        continue;
      return std::sscanf(line.c_str() + at,
                         "): Hausdorff %lf%% (mean %lf%%) of its diagonal, "
                         "%lu elements",
                         &hausdorff, &mean, &against) == 3;
    }
    return false;
  }

  std::vector<std::string> pluginLog(const std::string &reference)
  {
    gmsh::plugin::setString("SurfaceMeshQuality", "Reference", reference);
    gmsh::plugin::setNumber("SurfaceMeshQuality", "CreateViews", 0);
    gmsh::logger::start();
    gmsh::plugin::run("SurfaceMeshQuality");
    std::vector<std::string> log;
    gmsh::logger::get(log);
    gmsh::logger::stop();
    gmsh::plugin::setString("SurfaceMeshQuality", "Reference", "");
    gmsh::plugin::setNumber("SurfaceMeshQuality", "CreateViews", 1);
    return log;
  }

  // A stock mesh of the unit square moved by (dx, 0, dz)
  void meshedSquare(double dx, double dz)
  {
    gmsh::clear();
    int p[4];
    for(int i = 0; i < 4; i++)
      p[i] =
        gmsh::model::geo::addPoint(dx + (i == 1 || i == 2), (i >= 2), dz, 0.1);
    std::vector<int> lines;
    for(int i = 0; i < 4; i++)
      lines.push_back(gmsh::model::geo::addLine(p[i], p[(i + 1) % 4]));
    gmsh::model::geo::addPlaneSurface({gmsh::model::geo::addCurveLoop(lines)});
    gmsh::model::geo::synchronize();
    gmsh::model::mesh::generate(2);
  }

} // namespace

TEST(reparamViews, histogramSharesAddUpAndClampOutliers)
{
  std::vector<double> shares =
    histogram({0., 0.05, 0.1, 0.5, 0.99, 1., 2., -1.}, 10, 0., 1.);
  ASSERT_EQ(shares.size(), 10u);
  // bin 0: 0, 0.05 and -1 (clamped); bin 1: 0.1; bin 5: 0.5; bin 9: 0.99,
  // 1 (the closed end) and 2 (clamped)
  EXPECT_DOUBLE_EQ(shares[0], 37.5);
  EXPECT_DOUBLE_EQ(shares[1], 12.5);
  EXPECT_DOUBLE_EQ(shares[5], 12.5);
  EXPECT_DOUBLE_EQ(shares[9], 37.5);
  EXPECT_DOUBLE_EQ(std::accumulate(shares.begin(), shares.end(), 0.), 100.);
  EXPECT_EQ(histogram({}, 4, 0., 1.), std::vector<double>(4, 0.));
}

TEST(reparamViews, elementAndNodalViewsKeepTheirElements)
{
  clearViews();
  surfaceMesh m;
  m.points = {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(1, 1, 0),
              SPoint3(0, 1, 0), SPoint3(2, 0, 1)};
  m.triangles = {{1, 4, 2}};
  m.quadrangles = {{0, 1, 2, 3}};
  elementValueView("element", m, {0.5, 0.75});
  nodalValueView("nodal", m, {0., 1., 2., 3., 4.});
  PViewDataList *e = viewData("element"), *n = viewData("nodal");
  ASSERT_NE(e, nullptr);
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(e->NbST, 1);
  EXPECT_EQ(e->NbSQ, 1);
  // triangle: x of its corners, then y, then z, then one value per corner
  EXPECT_EQ(e->ST,
            std::vector<double>({1, 2, 1, 0, 0, 1, 0, 1, 0, 0.5, 0.5, 0.5}));
  EXPECT_EQ(std::vector<double>(e->SQ.begin() + 12, e->SQ.end()),
            std::vector<double>(4, 0.75));
  EXPECT_EQ(std::vector<double>(n->ST.begin() + 9, n->ST.end()),
            std::vector<double>({1., 4., 2.}));
  EXPECT_EQ(std::vector<double>(n->SQ.begin() + 12, n->SQ.end()),
            std::vector<double>({0., 1., 2., 3.}));

  histogramView("kappa", {25., 75.}, 0., 1.);
  PView *h = view("kappa_histogram");
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->getOptions()->type, PViewOptions::Plot2D);
  clearViews();
}

TEST(surfaceMeshQualityPlugin, kappaViewAndHistogramOfTheRemesh)
{
  ASSERT_NE(classifiedDome(6), nullptr);
  const uniformMeshSize meshSize(0.05);
  gmsh::model::mesh::generate(2);
  std::vector<MTriangle *> all;
  for(auto it = GModel::current()->firstFace();
      it != GModel::current()->lastFace(); ++it)
    all.insert(all.end(), (*it)->triangles.begin(), (*it)->triangles.end());
  kappaStatistics k = computeKappaStatistics(all);

  gmsh::plugin::setNumber("SurfaceMeshQuality", "SurfaceTag", -1);
  gmsh::plugin::setNumber("SurfaceMeshQuality", "CreateViews", 1);
  gmsh::plugin::setNumber("SurfaceMeshQuality", "HistogramBins", 10);
  gmsh::plugin::run("SurfaceMeshQuality");
  PViewDataList *kappa = viewData("kappa");
  PViewDataList *histogram = viewData("kappa_histogram");
  ASSERT_NE(kappa, nullptr);
  ASSERT_NE(histogram, nullptr);
  EXPECT_EQ(viewData("eta"), nullptr); // no quadrangles
  ASSERT_EQ((std::size_t)kappa->NbST, all.size());
  double sum = 0., min = 1.;
  for(std::size_t i = 0; i < all.size(); i++) {
    double value = kappa->ST[i * 12 + 9];
    EXPECT_NEAR(value,
                triangleKappa(corner(kappa->ST, i, 0, 3),
                              corner(kappa->ST, i, 1, 3),
                              corner(kappa->ST, i, 2, 3)),
                1e-12);
    sum += value;
    min = std::min(min, value);
  }
  EXPECT_NEAR(sum / all.size(), k.mean, 1e-12);
  EXPECT_NEAR(min, k.min, 1e-12);
  // 10 bins of 0.1, in % of the triangles; none below 0.5 (kappa min 0.55:
  // the nodes on the corners of the dome's slots, 0.74 when Gmsh's even
  // spacing cut them)
  ASSERT_EQ(histogram->NbSP, 10);
  double total = 0., below = 0.;
  for(int i = 0; i < 10; i++) {
    total += histogram->SP[4 * i + 3];
    if(i < 5) below += histogram->SP[4 * i + 3];
  }
  EXPECT_NEAR(total, 100., 1e-9);
  EXPECT_GT(k.min, 0.5);
  EXPECT_EQ(below, 0.);
  clearViews();
}

TEST(surfaceMeshQualityPlugin, etaOfAStockQuadMesh)
{
  // A stock Gmsh mesh: a transfinite, recombined 2 x 1 rectangle is 8 x 4
  // squares (eta 1); a sheared one has eta 1 - (2 / pi)(pi / 4) = 0.5
  gmsh::clear();
  clearViews();
  gmsh::model::add("quads");
  int p1 = gmsh::model::geo::addPoint(0, 0, 0);
  int p2 = gmsh::model::geo::addPoint(2, 0, 0);
  int p3 = gmsh::model::geo::addPoint(3, 1, 0);
  int p4 = gmsh::model::geo::addPoint(1, 1, 0);
  int l1 = gmsh::model::geo::addLine(p1, p2);
  int l2 = gmsh::model::geo::addLine(p2, p3);
  int l3 = gmsh::model::geo::addLine(p3, p4);
  int l4 = gmsh::model::geo::addLine(p4, p1);
  int loop = gmsh::model::geo::addCurveLoop({l1, l2, l3, l4});
  int s = gmsh::model::geo::addPlaneSurface({loop});
  gmsh::model::geo::mesh::setTransfiniteCurve(l1, 9);
  gmsh::model::geo::mesh::setTransfiniteCurve(l3, 9);
  gmsh::model::geo::mesh::setTransfiniteCurve(l2, 5);
  gmsh::model::geo::mesh::setTransfiniteCurve(l4, 5);
  gmsh::model::geo::mesh::setTransfiniteSurface(s);
  gmsh::model::geo::mesh::setRecombine(2, s);
  gmsh::model::geo::synchronize();
  gmsh::model::mesh::generate(2);

  gmsh::plugin::setNumber("SurfaceMeshQuality", "SurfaceTag", s);
  gmsh::plugin::run("SurfaceMeshQuality");
  gmsh::plugin::setNumber("SurfaceMeshQuality", "SurfaceTag", -1);
  PViewDataList *eta = viewData("eta");
  ASSERT_NE(eta, nullptr);
  EXPECT_EQ(viewData("kappa"), nullptr);
  ASSERT_EQ(eta->NbSQ, 32);
  for(int i = 0; i < 32; i++)
    EXPECT_NEAR(eta->SQ[i * 16 + 12], 0.5, 1e-10) << i;
  clearViews();
  gmsh::model::remove();
}

TEST(surfaceMeshQualityPlugin, distancesToAReferenceFile)
{
  // The reference: the unit square at z = 0 in two facets (diagonal of its
  // box sqrt 2)
  const std::string file =
    std::string(::testing::TempDir()) + "reparam_reference_square.stl";
  {
    std::ofstream stl(file);
    stl << "solid square\n"
        << "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
        << "vertex 1 1 0\nendloop\nendfacet\n"
        << "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\n"
        << "vertex 0 1 0\nendloop\nendfacet\nendsolid square\n";
  }
  double hausdorff = -1., mean = -1.;
  unsigned long against = 99;
  // a stock mesh of the square 0.01 above it: every sample 0.01 away
  meshedSquare(0., 0.01);
  std::vector<std::string> log = pluginLog(file);
  ASSERT_TRUE(referenceLine(log, hausdorff, mean, against));
  EXPECT_NEAR(hausdorff, 100. * 0.01 / std::sqrt(2.), 1e-3);
  EXPECT_NEAR(mean, 100. * 0.01 / std::sqrt(2.), 1e-3);
  EXPECT_EQ(against, 0u);
  // moved by half its side: its far half 0.5 from the reference, and the
  // reference's near half 0.5 from it
  meshedSquare(0.5, 0.);
  log = pluginLog(file);
  ASSERT_TRUE(referenceLine(log, hausdorff, mean, against));
  // (logged to 4 digits)
  EXPECT_NEAR(hausdorff, 100. * 0.5 / std::sqrt(2.), 1e-2);
  EXPECT_GT(mean, 5.);
  EXPECT_LT(mean, 100. * 0.5 / std::sqrt(2.));
  // the current model is left as it was: its one surface, meshed
  std::vector<std::pair<int, int> > surfaces;
  gmsh::model::getEntities(surfaces, 2);
  EXPECT_EQ(surfaces.size(), 1u);
  std::vector<std::size_t> tags, nodes;
  gmsh::model::mesh::getElementsByType(2, tags, nodes);
  EXPECT_GT(tags.size(), 100u);
  // a missing file: a warning, no line
  log = pluginLog(file + ".missing");
  EXPECT_FALSE(referenceLine(log, hausdorff, mean, against));
  bool warned = false;
  for(const std::string &line : log)
    warned |= line.find("no surface mesh in reference") != std::string::npos;
  EXPECT_TRUE(warned);
  std::remove(file.c_str());
  gmsh::clear();
}

TEST(parametrizationPlugin, uvOnTheSurfaceAndFlattened)
{
  // mean value (3): the outer boundary on the unit circle
  GFace *gf = classifiedDome(3);
  ASSERT_NE(gf, nullptr);
  gmsh::plugin::setNumber("Parametrization", "SurfaceTag", gf->tag());
  gmsh::plugin::run("Parametrization");
  gmsh::plugin::setNumber("Parametrization", "SurfaceTag", -1);
  PViewDataList *u = viewData("u"), *v = viewData("v");
  PViewDataList *flat = viewData("flattened");
  PViewDataList *angle = viewData("angle distortion");
  PViewDataList *area = viewData("area distortion");
  ASSERT_TRUE(u && v && flat && angle && area);
  const std::size_t n = gf->stl_triangles.size() / 3;
  ASSERT_EQ((std::size_t)u->NbST, n);
  ASSERT_EQ((std::size_t)flat->NbST, n);
  EXPECT_EQ(view("u")->getOptions()->intervalsType, PViewOptions::Iso);

  // u, v at the corners of the 3D triangles are the face's own; flattened
  // corners sit at (u, v, 0)
  double uvArea = 0., unitDiskArea = 0., weightedArea = 0., area3d = 0.;
  std::size_t onCircle = 0;
  for(std::size_t t = 0; t < n; t++) {
    for(int c = 0; c < 3; c++) {
      int node = gf->stl_triangles[3 * t + c];
      SPoint3 x = corner(u->ST, t, c, 3);
      EXPECT_LT(x.distance(gf->stl_vertices_xyz[node]), 1e-12);
      double uc = u->ST[t * 12 + 9 + c], vc = v->ST[t * 12 + 9 + c];
      EXPECT_EQ(uc, gf->stl_vertices_uv[node].x());
      EXPECT_EQ(vc, gf->stl_vertices_uv[node].y());
      SPoint3 f = corner(flat->ST, t, c, 3);
      EXPECT_LT(f.distance(SPoint3(uc, vc, 0.)), 1e-12);
      if(std::fabs(uc * uc + vc * vc - 1.) < 1e-9) onCircle++;
    }
    SPoint3 a = corner(flat->ST, t, 0, 3), b = corner(flat->ST, t, 1, 3),
            c = corner(flat->ST, t, 2, 3);
    double signedArea = 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) -
                               (c.x() - a.x()) * (b.y() - a.y()));
    uvArea += std::fabs(signedArea);
    SPoint3 p = corner(u->ST, t, 0, 3), q = corner(u->ST, t, 1, 3),
            r = corner(u->ST, t, 2, 3);
    double a3 = 0.5 * crossprod(SVector3(p, q), SVector3(p, r)).norm();
    area3d += a3;
    // area distortion = (uv share) / (3D share): weighted by the 3D areas
    // it adds up to the whole uv area
    weightedArea += area->ST[t * 12 + 9] * a3;
    EXPECT_GE(angle->ST[t * 12 + 9], 1.); // sigma max / sigma min
  }
  // the boundary polygon inscribed in the unit circle, holes filled
  unitDiskArea = M_PI;
  EXPECT_GT(onCircle, 100u);
  EXPECT_LT(uvArea, unitDiskArea);
  EXPECT_GT(uvArea, 0.9 * unitDiskArea);
  EXPECT_NEAR(weightedArea / area3d, 1., 1e-9);
  clearViews();
}

TEST(parametrizationPlugin, spectralIsMoreConformalThanTutte)
{
  double mean[2];
  int maps[2] = {5, 2};
  for(int i = 0; i < 2; i++) {
    GFace *gf = classifiedDome(maps[i]);
    ASSERT_NE(gf, nullptr);
    gmsh::plugin::run("Parametrization");
    PViewDataList *angle = viewData("angle distortion");
    ASSERT_NE(angle, nullptr);
    double sum = 0.;
    for(int t = 0; t < angle->NbST; t++) sum += angle->ST[t * 12 + 9];
    mean[i] = sum / angle->NbST;
  }
  // measured: spectral 1.005, Tutte 1.4 on the dome's slivers
  EXPECT_LT(mean[0], 1.02);
  EXPECT_GT(mean[1], 1.1);
  clearViews();
}
