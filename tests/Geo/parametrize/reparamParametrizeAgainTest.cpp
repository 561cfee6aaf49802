// Reparam - a map chosen after CreateGeometry is the one the next mesh
// uses (Geo/parametrize/reparamParametrizeAgain.h): the faces whose map
// options changed are parametrized again before Mesh 2, to the bit what
// CreateGeometry would compute with the same options; nothing is computed
// again when nothing changed; a change of an option only ClassifySurfaces
// reads is named once.

#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>
#include "GFace.h"
#include "GModel.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamParametrize.h"
#include "reparamParametrizeAgain.h"
#include "reparamReport.h"
#include "reparamTrianglePatch.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  // The (u, v) and recorded map of every discrete face
  struct faceMaps {
    std::vector<std::vector<SPoint2> > uv;
    std::vector<int> maps; // -1: Gmsh's own
  };

  faceMaps mapsOfFaces()
  {
    faceMaps f;
    GModel *m = GModel::current();
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      const parametrizationRecord *r = findParametrization(*it);
      f.maps.push_back(r ? r->map : -1);
      f.uv.push_back((*it)->stl_vertices_uv);
    }
    return f;
  }

  // t classified and its geometry created with the map `before`; then
  // `after` set (-1: left) and the layout's maps dropped, so that what
  // CreateGeometry computes is compared, not what the layout kept
  void createGeometry(const testTriangulation &t, int before)
  {
    gmsh::clear();
    gmsh::option::setNumber("Mesh.CompoundParametrization", before);
    addDiscreteSurface(t);
    gmsh::model::mesh::classifySurfaces(40. * M_PI / 180., true, true, M_PI);
    reparamForgetLayoutMaps();
    gmsh::model::mesh::createGeometry();
  }

  std::vector<std::string> meshLog()
  {
    gmsh::logger::start();
    gmsh::model::mesh::generate(2);
    std::vector<std::string> log;
    gmsh::logger::get(log);
    gmsh::logger::stop();
    return log;
  }

  std::size_t linesWith(const std::vector<std::string> &log,
                        const std::string &text)
  {
    std::size_t n = 0;
    for(const std::string &l : log) n += l.find(text) != std::string::npos;
    return n;
  }

  void expectSameMaps(const faceMaps &a, const faceMaps &b)
  {
    ASSERT_EQ(a.uv.size(), b.uv.size());
    EXPECT_EQ(a.maps, b.maps);
    for(std::size_t f = 0; f < a.uv.size(); f++) {
      ASSERT_EQ(a.uv[f].size(), b.uv[f].size());
      for(std::size_t i = 0; i < a.uv[f].size(); i++) {
        EXPECT_EQ(a.uv[f][i].x(), b.uv[f][i].x());
        EXPECT_EQ(a.uv[f][i].y(), b.uv[f][i].y());
      }
    }
  }

} // namespace

TEST(parametrizeAgain, aMapChosenAfterCreateGeometryIsTheOneMeshed)
{
  const uniformMeshSize size(0.2);
  createGeometry(sphere(48, 24), 4);
  const faceMaps direct = mapsOfFaces();
  ASSERT_GE(direct.maps.size(), 2u); // the sphere cut into disks
  for(int map : direct.maps) EXPECT_EQ(map, 4);

  createGeometry(sphere(48, 24), 6);
  for(int map : mapsOfFaces().maps) EXPECT_NE(map, 4);
  gmsh::option::setNumber("Mesh.CompoundParametrization", 4);
  const std::vector<std::string> log = meshLog();
  EXPECT_EQ(linesWith(log, "parametrized again: Mesh.CompoundParametrization "
                           "6 -> 4 since CreateGeometry"),
            direct.maps.size());
  EXPECT_EQ(linesWith(log, "Error"), 0u);
  // the (u, v) the faces were meshed with: CreateGeometry's with map 4
  expectSameMaps(mapsOfFaces(), direct);
  EXPECT_TRUE(surfacesWithoutElements().empty());
}

TEST(parametrizeAgain, nothingComputedAgainWhenNothingChanged)
{
  const uniformMeshSize size(0.2);
  createGeometry(sphere(48, 24), 6);
  const faceMaps created = mapsOfFaces();
  const std::vector<std::string> first = meshLog(), second = meshLog();
  EXPECT_EQ(linesWith(first, "parametrized again"), 0u);
  EXPECT_EQ(linesWith(second, "parametrized again"), 0u);
  expectSameMaps(mapsOfFaces(), created);
  // a change back and forth between two meshes is no change
  gmsh::option::setNumber("Mesh.CompoundParametrization", 3);
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  EXPECT_EQ(linesWith(meshLog(), "parametrized again"), 0u);
}

TEST(parametrizeAgain, toGmshsOwnMapAndBack)
{
  const uniformMeshSize size(0.2);
  createGeometry(sphere(48, 24), 3);
  const faceMaps meanValue = mapsOfFaces();
  gmsh::option::setNumber("Mesh.CompoundParametrization", 0);
  std::vector<std::string> log = meshLog();
  EXPECT_EQ(linesWith(log, "Mesh.CompoundParametrization 3 -> 0"),
            meanValue.maps.size());
  const faceMaps gmshs = mapsOfFaces();
  for(std::size_t f = 0; f < gmshs.maps.size(); f++) {
    EXPECT_EQ(gmshs.maps[f], -1); // no record: Gmsh's own map
    // another map: another (u, v) of the same nodes
    ASSERT_EQ(gmshs.uv[f].size(), meanValue.uv[f].size());
    EXPECT_NE(gmshs.uv[f][0].x(), meanValue.uv[f][0].x());
  }
  EXPECT_TRUE(surfacesWithoutElements().empty());
  // back to mean value: the nodes in CreateGeometry's order, its (u, v)
  gmsh::option::setNumber("Mesh.CompoundParametrization", 3);
  log = meshLog();
  EXPECT_EQ(linesWith(log, "Mesh.CompoundParametrization 0 -> 3"),
            meanValue.maps.size());
  expectSameMaps(mapsOfFaces(), meanValue);
}

TEST(parametrizeAgain, holeFillingChangedAfterCreateGeometry)
{
  const uniformMeshSize size(0.1);
  // lifted: a planar patch is projected on its plane whatever the map
  const testTriangulation disk =
    liftPlanar(polarDiskWithHoles(16, 48, {{{4, 7, 4, 12}}}), 0.3);
  gmsh::option::setNumber("Mesh.CompoundFillHoles", 0);
  createGeometry(disk, 4);
  const faceMaps unfilled = mapsOfFaces();
  gmsh::option::setNumber("Mesh.CompoundFillHoles", 1);
  createGeometry(disk, 4);
  const faceMaps filled = mapsOfFaces();
  ASSERT_EQ(filled.uv.size(), 1u);

  gmsh::option::setNumber("Mesh.CompoundFillHoles", 0);
  const std::vector<std::string> log = meshLog();
  EXPECT_EQ(linesWith(log, "Mesh.CompoundFillHoles 1 -> 0 since"), 1u);
  expectSameMaps(mapsOfFaces(), unfilled);
  EXPECT_NE(unfilled.uv[0][0].x(), filled.uv[0][0].x());
}

TEST(parametrizeAgain, aLayoutOptionChangedIsNamedOnce)
{
  const uniformMeshSize size(0.2);
  createGeometry(sphere(48, 24), 6);
  gmsh::option::setNumber("Mesh.CompoundSplit", 1);
  const std::vector<std::string> first = meshLog(), second = meshLog();
  EXPECT_EQ(
    linesWith(first, "Mesh.CompoundSplit 0 -> 1 since ClassifySurfaces"), 1u);
  EXPECT_EQ(linesWith(first, "Warning"), 1u);
  EXPECT_EQ(linesWith(second, "since ClassifySurfaces"), 0u);
  EXPECT_EQ(linesWith(first, "parametrized again"), 0u);
}

TEST(parametrizeAgain, optionChangesAreListed)
{
  mapOptionsRecord was, now;
  was.map = 6;
  now.map = 4;
  now.fillHoles = false;
  EXPECT_EQ(mapOptionsChange(was, now), "Mesh.CompoundParametrization 6 -> 4, "
                                        "Mesh.CompoundFillHoles 1 -> 0");
  EXPECT_EQ(mapOptionsChange(was, was), "");
  layoutOptionsRecord a, b;
  b.noiseSize = 0.5;
  EXPECT_EQ(layoutOptionsChange(a, b), "Mesh.CompoundNoiseSize 0 -> 0.5");
  EXPECT_EQ(layoutOptionsChange(b, b), "");
}

TEST(parametrizeAgain, aPatchOfTheArraysIsTheTrianglesPatch)
{
  // the same triangles, given to the face as arrays in first-appearance
  // order, make the same patch with the orders patchOfTriangles found
  const testTriangulation t = sphericalCap(8, 24, 1.);
  gmshTriangulation g(t);
  std::vector<MTriangle *> reversed(g.triangles.rbegin(), g.triangles.rend());
  const trianglePatch p = patchOfTriangles(reversed);
  ASSERT_TRUE(p.error.ok());
  std::vector<int> flat;
  for(const auto &tri : p.triangles)
    flat.insert(flat.end(), tri.begin(), tri.end());
  const trianglePatch q =
    patchOfArrays(p.points, flat, p.canonical, p.triangleOrder);
  ASSERT_TRUE(q.error.ok());
  EXPECT_TRUE(q.nodes.empty());
  ASSERT_EQ(q.patch.points.size(), p.patch.points.size());
  for(std::size_t i = 0; i < p.patch.points.size(); i++)
    EXPECT_EQ(q.patch.points[i].distance(p.patch.points[i]), 0.);
  EXPECT_EQ(q.patch.triangles, p.patch.triangles);
  // without orders: the arrays' own, another numbering of the same patch
  const trianglePatch r = patchOfArrays(p.points, flat, {}, {});
  ASSERT_TRUE(r.error.ok());
  EXPECT_EQ(r.patch.triangles.size(), p.patch.triangles.size());
  EXPECT_NE(r.patch.triangles, p.patch.triangles);
}
