// Reparam - the hooks in Gmsh: option, parametrization, report and plugin

#include <cmath>
#include <cstdio>
#include <map>
#include <gtest/gtest.h>
#include "GModel.h"
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "PluginManager.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "meanValueMap.h"
#include "meshFidelity.h"
#include "reparamHooks.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "patchAssembly.h"
#include "reparamSurfaceMesh.h"
#include "reparamTriangleQuality.h"

using namespace reparam;

namespace {

  // Gmsh's own map leaves holes free: parity needs ours to do the same
  struct holesLeftFree {
    holesLeftFree() { gmsh::option::setNumber("Mesh.CompoundFillHoles", 0); }
    ~holesLeftFree() { gmsh::option::setNumber("Mesh.CompoundFillHoles", 1); }
  };

  std::vector<std::string> logOf(const std::function<void()> &f)
  {
    gmsh::logger::start();
    f();
    std::vector<std::string> log;
    gmsh::logger::get(log);
    gmsh::logger::stop();
    return log;
  }

  bool contains(const std::vector<std::string> &log, const std::string &s)
  {
    for(const auto &l : log)
      if(l.find(s) != std::string::npos) return true;
    return false;
  }

  // The remesh of the tutorial's STL with one parametrization: triangles out
  std::size_t remeshDome(int choice, std::vector<std::string> *log = nullptr)
  {
    gmsh::clear();
    gmsh::option::setNumber("Mesh.CompoundParametrization", choice);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.05);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.05);
    auto run = [&]() {
      gmsh::merge(tutorialFile("dome.stl"));
      gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
      gmsh::model::mesh::createGeometry();
      gmsh::model::mesh::generate(2);
    };
    if(log)
      *log = logOf(run);
    else
      run();
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(2, tags, nodes);
    gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
    return tags.size();
  }

} // namespace

TEST(gmshHook, optionDefaultAndRange)
{
  double value;
  gmsh::option::getNumber("Mesh.CompoundParametrization", value);
  EXPECT_EQ(value, 6.);
  std::vector<std::string> log =
    logOf([] { gmsh::option::setNumber("Mesh.CompoundParametrization", 9); });
  gmsh::option::getNumber("Mesh.CompoundParametrization", value);
  EXPECT_EQ(value, 6.);
  EXPECT_TRUE(contains(log, "must be an integer from 0 to 6"));
  gmsh::option::setNumber("Mesh.CompoundParametrization", 0);
  gmsh::option::getNumber("Mesh.CompoundParametrization", value);
  EXPECT_EQ(value, 0.);
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
}

TEST(gmshHook, automaticMapLogsItsChain)
{
  gmshTriangulation t(hemisphere(6, 24));
  gmshParametrization p;
  std::vector<std::string> log =
    logOf([&] { p = parametrizeWith(t.triangles, 6); });
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(p.uv.size(), p.nodes.size());
  // the first map of the chain is one-to-one on a hemisphere: it is kept
  EXPECT_TRUE(contains(log, "spectral conformal map: 0 flipped, 0 folds, 0 "
                            "degenerate -> one-to-one"));
  EXPECT_TRUE(contains(log, "Reparam: spectral conformal map of"));
  EXPECT_FALSE(contains(log, "mean value map"));
}

TEST(gmshHook, mapNotOneToOneIsReportedWhenChosenByHand)
{
  // the harmonic map flips on slivers; without repair the mean value map
  // takes over (a flipped map can hang the planar mesher), with a warning;
  // with repair the harmonic map is fixed. Lifted: a planar patch is mapped
  // by its projection whatever the option (planeProjection.h)
  gmshTriangulation t(liftPlanar(jitteredGrid(10, 0.95, 2), 0.3));
  gmsh::option::setNumber("Mesh.CompoundRepair", 0);
  gmshParametrization p;
  std::vector<std::string> log =
    logOf([&] { p = parametrizeWith(t.triangles, 1); });
  gmsh::option::setNumber("Mesh.CompoundRepair", 1);
  EXPECT_TRUE(p.ok);
  EXPECT_TRUE(contains(log, "is not one-to-one"));
  EXPECT_TRUE(contains(log, "using the mean value map instead"));
  EXPECT_TRUE(contains(log, "mean value map: 0 flipped, 0 folds"));
  log = logOf([&] { p = parametrizeWith(t.triangles, 1); });
  EXPECT_TRUE(p.ok);
  EXPECT_FALSE(contains(log, "is not one-to-one ("));
  EXPECT_TRUE(contains(log, "repair moved"));
}

TEST(gmshHook, badPatchFailsWithReason)
{
  testTriangulation closed = hemisphere(3, 8);
  // close the hemisphere with a fan onto a south pole
  closed.points.push_back(SPoint3(0., 0., -1.));
  int pole = (int)closed.points.size() - 1, rim = 1 + 2 * 8;
  for(int j = 0; j < 8; j++)
    closed.triangles.push_back({pole, rim + (j + 1) % 8, rim + j});
  gmshTriangulation t(closed);
  gmshParametrization p;
  std::vector<std::string> log =
    logOf([&] { p = parametrizeWith(t.triangles, 3); });
  EXPECT_FALSE(p.ok);
  EXPECT_TRUE(p.triangles.empty() && p.uv.empty() && p.nodes.empty());
  EXPECT_TRUE(contains(log, "the surface is closed"));
}

// Gmsh's own code assembles the same weights and boundary but solves by GMRES
// with ILU down to a 1e-8 relative residual (Solver/linearSystemCSR.h), so it
// is itself only accurate to about 1e-8: a 1e-9 agreement cannot be asked of
// it. We check (a) that both agree to that solver tolerance, up to the
// rotation or reflection that the start and direction of the boundary on the
// circle make, and (b) that our (u, v) solve Gmsh's equations to round-off.
static const double gmresTolerance = 1e-7;

// max over interior nodes of |A uv| / max |A_ii|, A assembled by Reparam
static double relativeResidual(const testTriangulation &tt,
                               const std::vector<SPoint2> &uv)
{
  discretePatch patch = makePatchOrDie(tt);
  Eigen::SparseMatrix<double> A =
    assembleWeightedLaplacian(patch, meanValueWeights);
  std::vector<char> outer(tt.points.size(), 0);
  for(int v : patch.boundaryLoops[patch.outerLoop]) outer[v] = 1;
  Eigen::VectorXd u(uv.size()), v(uv.size());
  for(std::size_t i = 0; i < uv.size(); i++) {
    u[i] = uv[i].x();
    v[i] = uv[i].y();
  }
  Eigen::VectorXd ru = A * u, rv = A * v;
  double worst = 0., scale = 0.;
  for(std::size_t i = 0; i < uv.size(); i++) {
    scale = std::max(scale, A.coeff(i, i));
    if(!outer[i]) worst = std::max({worst, std::fabs(ru[i]), std::fabs(rv[i])});
  }
  return worst / scale;
}

TEST(gmshHook, badNodeIsNamedWithItsGmshTag)
{
  // two rim nodes of a disk merged: boundary fans meet at one node
  testTriangulation t = polarDisk(3, 8);
  const int rim0 = 1 + 2 * 8, rim4 = 1 + 2 * 8 + 4;
  for(auto &tri : t.triangles)
    for(int &v : tri)
      if(v == rim4) v = rim0;
  gmshTriangulation g(t); // node rim4 is now in no triangle: not in the patch
  gmshParametrization p;
  std::vector<std::string> log =
    logOf([&] { p = parametrizeWith(g.triangles, 3); });
  EXPECT_FALSE(p.ok);
  char expected[64];
  std::snprintf(expected, sizeof(expected), "at node %lu (1, 0, 0)",
                g.vertices[rim0]->getNum());
  EXPECT_TRUE(contains(log, expected)) << expected;
  EXPECT_TRUE(contains(log, "a node joins several boundary fans"));
}

TEST(gmshHook, meanValueMatchesGmshOnSyntheticPatches)
{
  holesLeftFree free;
  for(const testTriangulation &tt :
      {hemisphere(12, 48), polarDisk(10, 40, 1.3, 0.2),
       liftPlanar(polarDiskWithHoles(10, 40, {{{3, 5, 0, 6}}}), 0.3)}) {
    gmshTriangulation t(tt);
    gmshParametrization stock = parametrizeWith(t.triangles, 0);
    gmshParametrization ours = parametrizeWith(t.triangles, 3);
    ASSERT_TRUE(stock.ok && ours.ok);
    ASSERT_EQ(stock.nodes, ours.nodes);
    ASSERT_EQ(stock.triangles, ours.triangles);
    EXPECT_LT(distanceUpToOrthogonal(ours.uv, stock.uv), gmresTolerance);
    // (u, v) in the fixture's node numbering
    std::map<MVertex *, std::size_t> index;
    for(std::size_t i = 0; i < t.vertices.size(); i++) index[t.vertices[i]] = i;
    std::vector<SPoint2> oursUv(tt.points.size()), stockUv(tt.points.size());
    for(std::size_t i = 0; i < ours.nodes.size(); i++) {
      oursUv[index[ours.nodes[i]]] = ours.uv[i];
      stockUv[index[ours.nodes[i]]] = stock.uv[i];
    }
    double oursResidual = relativeResidual(tt, oursUv);
    EXPECT_LT(oursResidual, 1e-13);
    // and Gmsh's own solution is the less accurate one
    EXPECT_GT(relativeResidual(tt, stockUv), 10. * oursResidual);
  }
}

TEST(gmshHook, meanValueMatchesGmshOnTutorialPatches)
{
  holesLeftFree free;
  gmsh::clear();
  gmsh::merge(tutorialFile("dome.stl"));
  gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
  int faces = 0;
  for(auto it = GModel::current()->firstFace();
      it != GModel::current()->lastFace(); ++it) {
    const std::vector<MTriangle *> &t = (*it)->triangles;
    if(t.empty()) continue;
    gmshParametrization stock = parametrizeWith(t, 0);
    gmshParametrization ours = parametrizeWith(t, 3);
    ASSERT_TRUE(stock.ok && ours.ok);
    ASSERT_EQ(stock.nodes, ours.nodes);
    EXPECT_LT(distanceUpToOrthogonal(ours.uv, stock.uv), gmresTolerance)
      << "surface " << (*it)->tag();
    faces++;
  }
  EXPECT_GE(faces, 1);
}

TEST(gmshHook, remeshMatchesGmshElementCount)
{
  // the same map on the same 1D meshes (Gmsh's even spacing, which
  // Mesh.CompoundCurveCorners changes on the slots' corners), the planar
  // mesher's mesh as it is (Mesh.CompoundOptimize collapses short edges),
  // with the same sizes (Gmsh's interpolation of the curves' sizes)
  holesLeftFree free;
  gmsh::option::setNumber("Mesh.CompoundCurveCorners", 0);
  gmsh::option::setNumber("Mesh.CompoundOptimize", 0);
  gmsh::option::setNumber("Mesh.CompoundMeshSizeGradient", 0);
  std::size_t stock = remeshDome(0), ours = remeshDome(3);
  gmsh::option::setNumber("Mesh.CompoundCurveCorners", 1);
  gmsh::option::setNumber("Mesh.CompoundOptimize", 2);
  gmsh::option::setNumber("Mesh.CompoundMeshSizeGradient", 0.5);
  ASSERT_GT(stock, 1000u);
  EXPECT_LE(std::fabs((double)ours - (double)stock), 0.01 * stock)
    << ours << " vs " << stock;
}

TEST(gmshHook, everyMapRemeshesTheTutorialWithItsHolesFilled)
{
  for(int choice : {1, 2, 3, 4, 5}) {
    std::vector<std::string> log;
    std::size_t triangles = remeshDome(choice, &log);
    // measured: 3219 to 3269 (3413 to 3619 with Gmsh's interpolation of
    // the sizes of the curves' segments, Mesh.CompoundMeshSizeGradient = 0)
    EXPECT_GT(triangles, 3100u) << choice;
    EXPECT_LT(triangles, 3450u) << choice;
    EXPECT_TRUE(contains(log, "2 holes (2 filled)")) << choice;
    EXPECT_FALSE(contains(log, "Error")) << choice;
  }
}

TEST(gmshHook, reportAndPluginGiveTheMeshQuality)
{
  std::vector<std::string> log;
  std::size_t n = remeshDome(3, &log);
  EXPECT_TRUE(contains(log, "Reparam: mean value map of"));
  EXPECT_TRUE(contains(log, "Reparam: surface"));

  std::vector<MTriangle *> all;
  for(auto it = GModel::current()->firstFace();
      it != GModel::current()->lastFace(); ++it)
    all.insert(all.end(), (*it)->triangles.begin(), (*it)->triangles.end());
  ASSERT_EQ(all.size(), n);
  kappaStatistics k = computeKappaStatistics(all);
  // the input: kappa min 0.095, mean 0.595, 12.6 % below 0.3
  EXPECT_GT(k.mean, 0.95);
  EXPECT_LT(k.shareBelow03, 0.005);
  EXPECT_GT(k.min, 0.1);

  ASSERT_NE(PluginManager::instance()->find("SurfaceMeshQuality"), nullptr);
  log = logOf([] { gmsh::plugin::run("SurfaceMeshQuality"); });
  char expected[256];
  std::snprintf(expected, sizeof(expected),
                "SurfaceMeshQuality: %lu triangles, kappa min %.4f mean %.4f",
                n, k.min, k.mean);
  EXPECT_TRUE(contains(log, expected)) << expected;
}

TEST(gmshHook, compoundOfClassifiedPatchesExitsCleanly)
{
  // The stock bug: a compound of classified STL patches logged "Curvature not
  // found" for every node and failed
  gmsh::clear();
  gmsh::merge(tutorialFile("dome.stl"));
  // patches of at most 1000 triangles: METIS splits the dome
  gmsh::option::setNumber("Mesh.ReparamMaxTriangles", 1000);
  gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
  gmsh::option::setNumber("Mesh.ReparamMaxTriangles", 250000);
  gmsh::model::mesh::createGeometry();
  std::vector<std::pair<int, int> > surfaces;
  gmsh::model::getEntities(surfaces, 2);
  ASSERT_GE(surfaces.size(), 2u);
  std::vector<int> tags;
  for(auto &s : surfaces) tags.push_back(s.second);
  gmsh::model::mesh::setCompound(2, tags);
  const uniformMeshSize meshSize(0.05);
  gmsh::option::setNumber("General.Verbosity", 99);
  std::vector<std::string> log = logOf([] { gmsh::model::mesh::generate(2); });
  gmsh::option::setNumber("General.Verbosity", 5);
  // the path of the stock bug was taken, and handled
  EXPECT_TRUE(contains(log, "No curvature for node"));
  EXPECT_FALSE(contains(log, "Curvature not found"));
  EXPECT_FALSE(contains(log, "Error"));
  std::vector<std::size_t> elements, nodes;
  gmsh::model::mesh::getElementsByType(2, elements, nodes);
  EXPECT_GT(elements.size(), 1000u);
}

TEST(gmshHook, remeshIsOrientedAlongTheInputByEveryElement)
{
  remeshDome(6);
  GFace *gf = nullptr;
  for(auto it = GModel::current()->firstFace();
      it != GModel::current()->lastFace(); ++it)
    if(!(*it)->stl_triangles.empty()) gf = *it;
  ASSERT_NE(gf, nullptr);
  const surfaceMesh input = inputTriangulationOf(gf);
  meshFidelity f = compareToInput(input, surfaceMeshOf(gf));
  EXPECT_GT(f.elements, 1000u);
  EXPECT_EQ(f.inverted, 0u);
  // on the input to a fraction of the 0.05 size (diagonal 2.2)
  EXPECT_LT(f.hausdorff, 0.01);
  EXPECT_LT(f.meanDistance, 1e-3);

  // reversed as a whole: the vote turns it back
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  for(std::size_t i = 0; i < gf->getNumMeshElements(); i++)
    gf->getMeshElement(i)->reverse();
  EXPECT_EQ(countInverted(input, surfaceMeshOf(gf)), f.elements);
  EXPECT_TRUE(reparamOrientMeshedFace(gf));
  EXPECT_EQ(countInverted(input, surfaceMeshOf(gf)), 0u);
  // a minority against the input is reported, not hidden
  for(std::size_t i = 0; i < 3; i++) gf->getMeshElement(i)->reverse();
  std::vector<std::string> log =
    logOf([gf] { EXPECT_TRUE(reparamOrientMeshedFace(gf)); });
  EXPECT_TRUE(contains(log, "3 of its " + std::to_string(f.elements) +
                              " elements point against the input normals"));
  EXPECT_EQ(countInverted(input, surfaceMeshOf(gf)), 3u);
  // Gmsh's own map keeps Gmsh's own orientation
  gmsh::option::setNumber("Mesh.CompoundParametrization", 0);
  EXPECT_FALSE(reparamOrientMeshedFace(gf));
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
}

namespace {

  // The ramp as a discrete surface of the current model, then
  // ClassifySurfaces (no sharp edge: only the parametrization test splits);
  // returns the maps the faces' parametrizations ended on
  std::vector<int> classifiedRampMaps(int split)
  {
    gmsh::clear();
    gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
    gmsh::option::setNumber("Mesh.CompoundSplit", split);
    // Gmsh's split loop, which Mesh.CompoundSplit acts in
    gmsh::option::setNumber("Mesh.CompoundLayout", 0);
    addDiscreteSurface(helicoidStrip(120, 6, 1.5, 1., 2., 0.05));
    gmsh::model::mesh::classifySurfaces(M_PI, true, true, M_PI);
    gmsh::model::mesh::createGeometry();
    gmsh::option::setNumber("Mesh.CompoundSplit", 0);
    gmsh::option::setNumber("Mesh.CompoundLayout", 1);
    gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
    std::vector<int> maps;
    for(auto it = GModel::current()->firstFace();
        it != GModel::current()->lastFace(); ++it) {
      const parametrizationRecord *p = findParametrization(*it);
      maps.push_back(p ? p->map : -1);
    }
    return maps;
  }

} // namespace

TEST(gmshHook, compoundSplitCutsARampWhoseConformalMapsFold)
{
  // 1.5 turns: both conformal maps fold, the automatic chain ends on mean
  // value; with Mesh.CompoundSplit the parts map conformally instead
  std::vector<int> kept = classifiedRampMaps(0);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0], (int)compoundParametrization::meanValue);
  std::vector<int> split = classifiedRampMaps(1);
  EXPECT_GE(split.size(), 2u);
  for(int map : split)
    EXPECT_TRUE(map == (int)compoundParametrization::spectral ||
                map == (int)compoundParametrization::conformal)
      << map;
}

TEST(gmshHook, mapDoesNotDependOnTheTrianglesOrder)
{
  // The patch layout verifies a part, CreateGeometry later gets the same
  // triangles in another order: every map must give the same (u, v) to the
  // last bit, else a part verified one-to-one may fold at CreateGeometry
  testTriangulation tt = jitteredGrid(12, 0.8, 7);
  tt = liftPlanar(tt, 0.4);
  gmshTriangulation t(tt);
  std::vector<MTriangle *> reversed(t.triangles.rbegin(), t.triangles.rend());
  for(int map : {3, 4, 5, 6}) {
    gmshParametrization a = parametrizeWith(t.triangles, map);
    gmshParametrization b = parametrizeWith(reversed, map);
    ASSERT_TRUE(a.ok && b.ok) << map;
    std::map<MVertex *, SPoint2> uv;
    for(std::size_t i = 0; i < a.nodes.size(); i++) uv[a.nodes[i]] = a.uv[i];
    ASSERT_EQ(uv.size(), b.nodes.size());
    for(std::size_t i = 0; i < b.nodes.size(); i++) {
      EXPECT_EQ(uv[b.nodes[i]].x(), b.uv[i].x()) << map;
      EXPECT_EQ(uv[b.nodes[i]].y(), b.uv[i].y()) << map;
    }
  }
}
