// Reparam - the report after meshing: its table, its JSON, and what the
// stages record for it on a real remesh

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "SVector3.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamInputMesh.h"
#include "reparamReport.h"
#include "reparamState.h"
#include "reparamTriangleQuality.h"
#include "triangleQuality.h"

using namespace reparam;

namespace {

  faceReport face(int tag, std::vector<int> maps, std::size_t triangles,
                  double kappaMin, double kappaMean, std::size_t edges,
                  double tau, SPoint3 boxMax, double hausdorff,
                  double meanDistance, std::size_t inverted)
  {
    faceReport r;
    r.tag = tag;
    r.reparametrized = true;
    r.parametrization.mapsTried = maps;
    r.parametrization.map = maps.back();
    r.parametrization.bijective = true;
    r.parametrization.solveTime = 0.25;
    r.meshTime = 1.;
    r.quality.triangles = triangles;
    r.quality.kappaMin = kappaMin;
    r.quality.kappaMean = kappaMean;
    r.quality.edges = edges;
    r.quality.tau = tau;
    r.hasInput = true;
    r.inputBox += SPoint3(0., 0., 0.);
    r.inputBox += boxMax;
    r.fidelity.elements = triangles;
    r.fidelity.hausdorff = hausdorff;
    r.fidelity.meanDistance = meanDistance;
    r.fidelity.diagonal = r.inputBox.diag();
    r.fidelity.inverted = inverted;
    r.oriented = true;
    return r;
  }

  std::string number(double x)
  {
    char s[32];
    snprintf(s, sizeof(s), "%.6g", x);
    return s;
  }

  bool has(const std::string &text, const std::string &s)
  {
    return text.find(s) != std::string::npos;
  }

} // namespace

TEST(reparamReport, totalCombinesFacesByTheirWeights)
{
  std::vector<faceReport> reports = {
    face(1, {3}, 100, 0.5, 0.9, 150, 90., SPoint3(1, 0, 0), 0.1, 0.01, 0),
    face(2, {5, 4}, 300, 0.3, 0.8, 450, 80., SPoint3(3, 4, 0), 0.2, 0.02, 2)};
  reports[1].quality.quadrangles = 10;
  reports[1].quality.etaMin = 0.5;
  reports[1].quality.etaMean = 0.7;

  std::vector<std::string> table = reportTable(reports);
  ASSERT_EQ(table.size(), 4u); // header, 2 faces, total
  EXPECT_EQ(table[1].substr(0, 12), "1         MV");
  EXPECT_EQ(table[2].substr(0, 24), "2         spectral>LSCM ");
  EXPECT_EQ(table[3].substr(0, 17), "total     2 surf.");
  // kappa min over faces, mean weighted by triangles: (90 + 240) / 400
  EXPECT_TRUE(has(table[3], " 0.300  0.825 ")) << table[3];
  // tau: exponential of the mean over all edges, not the mean of the taus
  double tau =
    100. * std::exp((150. * std::log(0.9) + 450. * std::log(0.8)) / 600.);
  char s[16];
  snprintf(s, sizeof(s), " %5.1f ", tau);
  EXPECT_TRUE(has(table[3], s)) << table[3] << " / " << s;

  std::string json = reportJson(reports);
  EXPECT_TRUE(has(json, "\"mapsTried\": [\"spectral conformal\", \"finite "
                        "element conformal (LSCM)\"]"));
  std::string total = json.substr(json.find("\"total\""));
  EXPECT_TRUE(has(total, "\"kappaMean\": 0.825,"));
  EXPECT_TRUE(has(total, "\"tau\": " + number(tau) + ","));
  EXPECT_TRUE(has(total, "\"etaMin\": 0.5, \"etaMean\": 0.7,"));
  // distances against the union of the inputs' boxes (diagonal 5)
  EXPECT_TRUE(has(total, "\"hausdorffPercent\": 4,"));
  EXPECT_TRUE(has(total, "\"meanDistancePercent\": 0.35,"));
  EXPECT_TRUE(has(total,
                  "\"inverted\": 2, \"poorTriangleCauses\": "
                  "{\"sharpCurveAngle\": 0, \"shortCurveSegment\": 0, "
                  "\"narrowStrip\": 0, \"inside\": 0}, \"optimization\": "
                  "null}"));
  EXPECT_EQ(poorTrianglesLine(reports), "");
  // the causes of the poor triangles: summed, named
  reports[0].poorTriangles[(int)poorTriangleCause::sharpCurveAngle] = 2;
  reports[1].poorTriangles[(int)poorTriangleCause::sharpCurveAngle] = 1;
  reports[1].poorTriangles[(int)poorTriangleCause::inside] = 1;
  EXPECT_EQ(poorTrianglesLine(reports),
            "4 triangles below kappa 0.3: 3 where curves meet at a sharp "
            "angle, 1 inside surfaces");
  const std::string causes = reportJson(reports);
  EXPECT_TRUE(has(causes.substr(causes.find("\"total\"")),
                  "\"poorTriangleCauses\": {\"sharpCurveAngle\": 3, "
                  "\"shortCurveSegment\": 0, \"narrowStrip\": 0, "
                  "\"inside\": 1}"));
  reports[0].poorTriangles = reports[1].poorTriangles = poorTriangleCounts{};
  EXPECT_TRUE(has(total, "\"solve\": 0.5,"));
  EXPECT_EQ(optimizationLine(reports), ""); // not optimized

  // Mesh.CompoundOptimize's records: the worst before, the sums
  reports[0].optimization.done = reports[1].optimization.done = true;
  reports[0].optimization.kappaMinBefore = 0.2;
  reports[1].optimization.kappaMinBefore = 0.1;
  reports[0].optimization.seconds = 0.5;
  reports[1].optimization.seconds = 0.25;
  reports[0].optimization.inserted = 3;
  reports[1].optimization.inserted = 1;
  reports[1].optimization.againstBefore = 5;
  reports[1].optimization.againstAfter = 2;
  const std::string optimized = reportJson(reports);
  EXPECT_TRUE(has(optimized.substr(optimized.find("\"total\"")),
                  "\"optimization\": {\"kappaMinBefore\": 0.1, \"seconds\": "
                  "0.75, \"insertedInputNodes\": 4, \"longEdgeSplits\": 0, "
                  "\"shortEdgeCollapses\": 0, \"flips\": 0, \"moves\": 0, "
                  "\"againstInputBefore\": 5, "
                  "\"againstInputAfter\": 2}}"));
  EXPECT_TRUE(has(optimizationLine(reports),
                  "kappa min 0.1 -> 0.3, 4 input nodes the mesh cut off "
                  "inserted"))
    << optimizationLine(reports);
  EXPECT_TRUE(has(total, "\"planarMesh\": 2}"));
  // a face without quadrangles has no eta: null, not 0
  std::string first = json.substr(0, json.find("\"surface\": 2"));
  EXPECT_TRUE(has(first, "\"etaMin\": null"));
}

TEST(reparamReport, farthestPointOfTheTotalIsTheWorstFaces)
{
  std::vector<faceReport> reports = {
    face(1, {3}, 100, 0.5, 0.9, 150, 90., SPoint3(1, 0, 0), 0.1, 0.01, 0),
    face(2, {3}, 300, 0.3, 0.8, 450, 80., SPoint3(3, 4, 0), 0.2, 0.02, 0)};
  reports[0].fidelity.farthest = SPoint3(7, 7, 7);
  reports[1].fidelity.farthest = SPoint3(1, 2, 3);
  reports[1].fidelity.farthestOnInput = true;
  EXPECT_EQ(farthestPointLine(reports),
            "largest distance to the input 0.2 (4 % of the diagonal) at (1, "
            "2, 3): an input point far from the mesh");
  std::string total = reportJson(reports);
  total = total.substr(total.find("\"total\""));
  EXPECT_TRUE(has(total, "\"hausdorffAt\": [1, 2, 3], \"hausdorffFrom\": "
                         "\"input\""))
    << total;
  // the whole model's distances, when given, are the total's
  meshFidelity whole;
  whole.hausdorff = 0.5;
  whole.farthest = SPoint3(0, 0, 1);
  EXPECT_EQ(farthestPointLine(reports, &whole),
            "largest distance to the input 0.5 (10 % of the diagonal) at (0, "
            "0, 1): a mesh point far from the input");
}

TEST(reparamReport, remeshReportsWhatEachStageDid)
{
  gmsh::clear();
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  const uniformMeshSize meshSize(0.05);
  const std::string file = testing::TempDir() + "reparamReport.json";
  std::remove(file.c_str());
  gmsh::option::setString("Mesh.CompoundReportFile", file);
  gmsh::merge(tutorialFile("dome.stl"));
  gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
  gmsh::model::mesh::createGeometry();

  GFace *gf = nullptr;
  for(auto it = GModel::current()->firstFace();
      it != GModel::current()->lastFace(); ++it)
    if(!(*it)->stl_triangles.empty()) gf = *it;
  ASSERT_NE(gf, nullptr);
  const parametrizationRecord *p = findParametrization(gf);
  ASSERT_NE(p, nullptr);
  // the dome is a disk with two holes: spectral is one-to-one at once
  EXPECT_EQ(p->mapsTried, std::vector<int>{5});
  EXPECT_EQ(p->map, 5);
  EXPECT_TRUE(p->bijective);
  EXPECT_EQ(p->triangles, 3300u);
  EXPECT_EQ(p->holes, 2u);
  EXPECT_EQ(p->filledHoles, 2u);

  gmsh::model::mesh::generate(2);
  gmsh::option::setString("Mesh.CompoundReportFile", "");
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  EXPECT_TRUE(pendingFaceReports().empty()); // printed and forgotten

  std::ifstream in(file);
  ASSERT_TRUE(in.good()) << file;
  std::stringstream text;
  text << in.rdbuf();
  std::string json = text.str();
  kappaStatistics k = computeKappaStatistics(gf->triangles);
  EXPECT_GT(k.triangles, 3000u);
  EXPECT_TRUE(has(json, "\"surface\": " + std::to_string(gf->tag())));
  EXPECT_TRUE(has(json, "\"map\": \"spectral conformal\""));
  EXPECT_TRUE(has(json, "\"triangles\": " + std::to_string(k.triangles)));
  EXPECT_TRUE(has(json, "\"kappaMin\": " + number(k.min)));
  EXPECT_TRUE(has(json, "\"kappaMean\": " + number(k.mean)));
  EXPECT_TRUE(has(json, "\"inverted\": 0, \"poorTriangleCauses\": {"));
  EXPECT_TRUE(has(json, "\"inside\": 0}, \"optimization\": {"));
  // Mesh.CompoundOptimize's record: the worst kappa before it, no worse
  // after, and what it did
  EXPECT_TRUE(has(json, "\"optimization\": {\"kappaMinBefore\": "));
  const std::size_t at = json.find("\"kappaMinBefore\": ");
  ASSERT_NE(at, std::string::npos);
  const double before = std::atof(json.c_str() + at + 18);
  EXPECT_GT(before, 0.);
  EXPECT_LE(before, k.min);
  EXPECT_TRUE(has(json, "\"againstInputAfter\": 0}"));

  // off: nothing measured, nothing kept
  gmsh::option::setNumber("Mesh.CompoundReport", 0);
  gmsh::model::mesh::generate(2);
  EXPECT_TRUE(pendingFaceReports().empty());
  gmsh::option::setNumber("Mesh.CompoundReport", 1);
}

TEST(reparamReport, surfaceKeptAsItsInputIsNamed)
{
  // A NaN coordinate in the classified dome: its CreateGeometry fails, the
  // face keeps its input triangles, the NaN node moved to the mean of its
  // neighbours, and the report names it
  gmsh::clear();
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  const uniformMeshSize meshSize(0.05);
  gmsh::merge(tutorialFile("dome.stl"));
  gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
  std::vector<std::pair<int, int> > surfaces;
  gmsh::model::getEntities(surfaces, 2);
  ASSERT_EQ(surfaces.size(), 1u);
  std::vector<std::size_t> nodes, tags, elementNodes;
  std::vector<double> coords, params;
  gmsh::model::mesh::getNodes(nodes, coords, params, 2, surfaces[0].second);
  ASSERT_FALSE(nodes.empty());
  gmsh::model::mesh::getElementsByType(2, tags, elementNodes,
                                       surfaces[0].second);
  std::size_t aroundNaN = 0;
  for(std::size_t n : elementNodes) aroundNaN += n == nodes[0];
  ASSERT_GT(aroundNaN, 0u);
  double inputArea = 0.;
  for(auto it = GModel::current()->firstFace();
      it != GModel::current()->lastFace(); ++it)
    for(MTriangle *t : (*it)->triangles) inputArea += t->getVolume();
  gmsh::model::mesh::setNode(nodes[0], {std::nan(""), 0., 0.}, {});
  const std::string file = testing::TempDir() + "reparamReportKept.json";
  std::remove(file.c_str());
  gmsh::option::setString("Mesh.CompoundReportFile", file);
  gmsh::model::mesh::createGeometry();
  gmsh::model::mesh::generate(2);
  gmsh::option::setString("Mesh.CompoundReportFile", "");
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);

  EXPECT_TRUE(unparametrizedFaces(GModel::current()).empty());
  EXPECT_EQ(facesKeptAsInput(GModel::current()),
            std::vector<int>{surfaces[0].second});
  std::vector<std::size_t> keptTags, keptNodes;
  gmsh::model::mesh::getElementsByType(2, keptTags, keptNodes,
                                       surfaces[0].second);
  // its triangles, the boundary's stitched to the curves' nodes: about as
  // many, covering the same area, no NaN
  EXPECT_NEAR((double)keptTags.size(), (double)tags.size(), 0.01 * tags.size());
  auto area = [](const std::vector<std::size_t> &triangleNodes) {
    double sum = 0.;
    for(std::size_t i = 0; i + 2 < triangleNodes.size(); i += 3) {
      std::vector<double> p[3], par;
      for(int j = 0; j < 3; j++)
        gmsh::model::mesh::getNode(triangleNodes[i + j], p[j], par);
      SVector3 n = crossprod(
        SVector3(p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]),
        SVector3(p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]));
      sum += 0.5 * n.norm();
    }
    return sum;
  };
  EXPECT_NEAR(area(keptNodes), inputArea, 1e-3 * inputArea);
  gmsh::model::mesh::getNodes(nodes, coords, params, 2, surfaces[0].second);
  for(double x : coords) EXPECT_TRUE(std::isfinite(x));
  std::ifstream in(file);
  ASSERT_TRUE(in.good()) << "no report written";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_TRUE(has(text.str(), "\"surfaces\": [\n  ],"));
  EXPECT_TRUE(has(text.str(), "\"unmeshedSurfaces\": [],"));
  EXPECT_TRUE(has(text.str(), "\"inputKeptSurfaces\": [" +
                                std::to_string(surfaces[0].second) + "]"))
    << text.str();
  EXPECT_TRUE(has(reportJson({}, {2, 5}), "\"unmeshedSurfaces\": [2, 5]"));
  EXPECT_TRUE(
    has(reportJson({}, {}, nullptr, {3}), "\"inputKeptSurfaces\": [3]"));
  EXPECT_TRUE(has(reportJson({}), "\"narrowSurfaces\": []"));
  EXPECT_TRUE(has(reportJson({}, {}, nullptr, {}, {4, 12}),
                  "\"narrowSurfaces\": [4, 12]"));
}

TEST(reparamReport, narrowFacesAreNamedWithTheirKappaMean)
{
  std::vector<faceReport> reports = {
    face(1, {3}, 300, 0.5, 0.96, 450, 90., SPoint3(1, 0, 0), 0.1, 0.01, 0),
    face(2, {3}, 100, 0.2, 0.6, 150, 60., SPoint3(1, 0, 0), 0.1, 0.01, 0),
    face(3, {3}, 0, 0., 0., 0, 0., SPoint3(1, 0, 0), 0.1, 0.01, 0)};
  // none narrow, or all of them: nothing to compare
  EXPECT_EQ(narrowFacesLine(reports, {}), "");
  EXPECT_EQ(narrowFacesLine(reports, {1, 2}), "");
  // the mean weighted by the triangles: (300 * 0.96 + 100 * 0.6) / 400;
  // a narrow face left without triangles is not counted
  EXPECT_EQ(narrowFacesLine(reports, {2, 3}),
            "kappa mean 0.87: 0.6 on the 1 surface narrower than a quarter "
            "of the size asked (2; 100 triangles), 0.96 on the others");
}
