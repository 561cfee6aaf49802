// Reparam - the one owner of what Reparam keeps between Gmsh's calls: face
// and model records made on first use, found, and started anew at the
// layout's start, at a face's CreateGeometry and at the model's report

#include <algorithm>
#include <cmath>
#include <mutex>
#include <shared_mutex>
#include <thread>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "SVector3.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamMesherFallback.h"
#include "reparamParametrize.h"
#include "reparamReport.h"
#include "reparamState.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  // t classified (no sharp edge: one face unless the layout cuts it), its
  // geometry created, with Reparam's automatic map and `layout`
  void createGeometryOf(const testTriangulation &t, int layout = 1)
  {
    gmsh::clear();
    gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
    gmsh::option::setNumber("Mesh.CompoundLayout", layout);
    addDiscreteSurface(t);
    gmsh::model::mesh::classifySurfaces(M_PI, true, true, M_PI);
    gmsh::model::mesh::createGeometry();
    gmsh::option::setNumber("Mesh.CompoundLayout", 1);
  }

  // The faces of the current model with an input triangulation
  std::vector<GFace *> parametrizedFaces()
  {
    std::vector<GFace *> faces;
    GModel *m = GModel::current();
    for(auto it = m->firstFace(); it != m->lastFace(); ++it)
      if(!(*it)->stl_triangles.empty()) faces.push_back(*it);
    return faces;
  }

} // namespace

TEST(reparamState, aFaceRecordIsMadeFoundAndGoesWhenItsGeometryStarts)
{
  // the 4 x 4 grid of the unit square: one face, 25 nodes, 32 triangles
  createGeometryOf(rectangleGrid(4, 4, 1., 1.));
  const std::vector<GFace *> faces = parametrizedFaces();
  ASSERT_EQ(faces.size(), 1u);
  GFace *gf = faces[0];
  const parametrizationRecord *p = findParametrization(gf);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->nodes, 25u);
  EXPECT_EQ(p->triangles, 32u);
  EXPECT_TRUE(p->bijective);
  EXPECT_GT(p->map, 0);
  {
    std::unique_lock<std::mutex> lock = lockRecords();
    const faceRecord *r = findFaceRecord(gf);
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(&*r->parametrization, p);
    EXPECT_EQ(r->failure, "");
    EXPECT_FALSE(r->keptInput);
  }
  EXPECT_EQ(reparamLastFailure(gf), "");

  // the start of its CreateGeometry: the record goes
  reparamBeginFaceGeometry(gf);
  EXPECT_EQ(findParametrization(gf), nullptr);
  std::unique_lock<std::mutex> lock = lockRecords();
  EXPECT_EQ(findFaceRecord(gf), nullptr);
  // made again on first use, empty
  faceRecord &made = faceRecordOf(gf);
  EXPECT_EQ(findFaceRecord(gf), &made);
  EXPECT_FALSE(made.parametrization);
  EXPECT_FALSE(made.optimization);
  EXPECT_EQ(made.curvature.field, nullptr);
}

TEST(reparamState, aParametrizationIsRecordedByFace)
{
  // the 4 x 4 grid's face: a record of its 25 nodes and 32 triangles is
  // found, one of another size is not (a face made where a deleted one
  // was), none after it is forgotten
  createGeometryOf(rectangleGrid(4, 4, 1., 1.));
  GFace *gf = parametrizedFaces().at(0);
  parametrizationRecord r;
  r.map = 3;
  r.nodes = 25;
  r.triangles = 32;
  r.mapsTried = {5, 3};
  recordParametrization(gf, &r);
  const parametrizationRecord *found = findParametrization(gf);
  ASSERT_NE(found, nullptr);
  EXPECT_EQ(found->map, 3);
  EXPECT_EQ(found->mapsTried, std::vector<int>({5, 3}));
  r.nodes = 24;
  recordParametrization(gf, &r);
  EXPECT_EQ(findParametrization(gf), nullptr);
  r.nodes = 25;
  recordParametrization(gf, &r);
  EXPECT_EQ(findParametrization(gf), found); // in place
  recordParametrization(gf, nullptr);
  EXPECT_EQ(findParametrization(gf), nullptr);
}

TEST(reparamState, recordsStayInPlaceWhileOthersAreMade)
{
  // the sphere, cut by the layout into several disks, each with its record
  createGeometryOf(sphere(24, 12));
  const std::vector<GFace *> faces = parametrizedFaces();
  ASSERT_GE(faces.size(), 2u);
  std::vector<const parametrizationRecord *> found;
  for(GFace *gf : faces) found.push_back(findParametrization(gf));
  for(std::size_t f = 0; f < faces.size(); f++) {
    ASSERT_NE(found[f], nullptr);
    EXPECT_EQ(found[f]->nodes, faces[f]->stl_vertices_uv.size());
  }
  // the first face's record starts anew: the others' stay where they were
  reparamBeginFaceGeometry(faces[0]);
  EXPECT_EQ(findParametrization(faces[0]), nullptr);
  for(std::size_t f = 1; f < faces.size(); f++)
    EXPECT_EQ(findParametrization(faces[f]), found[f]);
}

TEST(reparamState, aFaceNoMapTakesKeepsItsFailureAndInputUntilItsGeometry)
{
  // 130 triangles, one of them degenerate: the face that has it keeps its
  // input triangle
  createGeometryOf(gridWithSplitEdge(SPoint3(0., 0., 0.)));
  GModel *m = GModel::current();
  GFace *gf = nullptr;
  for(auto it = m->firstFace(); it != m->lastFace(); ++it)
    if(keptAsInput(*it)) gf = *it;
  ASSERT_NE(gf, nullptr);
  EXPECT_NE(reparamLastFailure(gf), "");
  {
    std::unique_lock<std::mutex> lock = lockRecords();
    const faceRecord *r = findFaceRecord(gf);
    ASSERT_NE(r, nullptr);
    ASSERT_TRUE(r->keptInput);
    // the layout cuts the degenerate triangle off as a face of its own
    EXPECT_EQ(r->keptInput->triangles.size(), 1u);
    EXPECT_EQ(r->keptInput->points.size(), 3u);
    EXPECT_EQ(r->keptInput->leftOut, 0u);
    EXPECT_FALSE(r->parametrization);
  }
  reparamBeginFaceGeometry(gf);
  EXPECT_FALSE(keptAsInput(gf));
  EXPECT_EQ(reparamLastFailure(gf), "");
}

TEST(reparamState, theLayoutStartsItsRecordAndTheModelsAnew)
{
  // the layout of a sphere: the maps it verified its parts with wait for
  // CreateGeometry; noise measured at the edge of the equilateral
  // triangles that would tile it, as many as its own
  const testTriangulation t = sphere(24, 12);
  double area = 0.;
  for(const auto &c : t.triangles)
    area += 0.5 * crossprod(SVector3(t.points[c[0]], t.points[c[1]]),
                            SVector3(t.points[c[0]], t.points[c[2]]))
                    .norm();
  gmsh::clear();
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  addDiscreteSurface(t);
  gmsh::model::mesh::classifySurfaces(M_PI, true, true, M_PI);
  EXPECT_GT(lastLayout().maps.size(), 1u);
  EXPECT_NEAR(lastLayout().noiseSize,
              std::sqrt(4. * area / (std::sqrt(3.) * t.triangles.size())),
              1e-9);
  EXPECT_GT(lastLayout().smoothCuts.size(), 0u); // its cuts, all smooth
  EXPECT_TRUE(lastLayout().mergedCreases.empty());
  const layoutRecord *first = &lastLayout();

  // another classification, by Gmsh's split loop, of a model with a
  // record: no layout, but its start all the same
  gmsh::clear();
  gmsh::option::setNumber("Mesh.CompoundLayout", 0);
  addDiscreteSurface(rectangleGrid(4, 4, 1., 1.));
  GModel *m = GModel::current();
  {
    std::unique_lock<std::mutex> lock = lockRecords();
    modelRecordOf(m).creaseCurves.insert(nullptr);
  }
  gmsh::model::mesh::classifySurfaces(M_PI, true, true, M_PI);
  gmsh::option::setNumber("Mesh.CompoundLayout", 1);
  EXPECT_NE(&lastLayout(), first);
  EXPECT_EQ(lastLayout().maps.size(), 0u);
  EXPECT_EQ(lastLayout().noiseSize, 0.);
  EXPECT_TRUE(lastLayout().smoothCuts.empty());
  EXPECT_TRUE(lastLayout().junctions.empty());
  EXPECT_EQ(lastLayout().refusedBeforeTheMap.load(), 0u);
  std::unique_lock<std::mutex> lock = lockRecords();
  EXPECT_EQ(findModelRecord(m), nullptr);
}

TEST(reparamState, theModelsReportEndsThePendingFaceReports)
{
  // the 4 x 4 grid meshed: its report printed at the end of Mesh 2; then
  // measured again by hand, and printed by the hook
  gmsh::option::setNumber("Mesh.CompoundReport", 1);
  createGeometryOf(rectangleGrid(4, 4, 1., 1.));
  gmsh::model::mesh::generate(2);
  EXPECT_TRUE(pendingFaceReports().empty());
  const std::vector<GFace *> faces = parametrizedFaces();
  ASSERT_EQ(faces.size(), 1u);
  reparamReportMeshedFace(faces[0], 0.);
  ASSERT_EQ(pendingFaceReports().size(), 1u);
  EXPECT_EQ(pendingFaceReports()[0].tag, faces[0]->tag());
  EXPECT_EQ(findFaceReport(faces[0]), &pendingFaceReports()[0]);
  reparamReportMeshedModel(GModel::current());
  EXPECT_TRUE(pendingFaceReports().empty());
  // with the report off, the reports go unprinted
  reparamReportMeshedFace(faces[0], 0.);
  EXPECT_EQ(pendingFaceReports().size(), 1u);
  gmsh::option::setNumber("Mesh.CompoundReport", 1);
  reparamReportMeshedModel(GModel::current());
  EXPECT_TRUE(pendingFaceReports().empty());
}

TEST(reparamState, eachThreadHasItsOwnFaceMeshingContext)
{
  faceMeshingContext &mine = thisThreadsFaceMeshing();
  EXPECT_EQ(mine.meshing, 0);
  EXPECT_EQ(mine.grading.face, nullptr);
  mine.tryingOtherMesher = true;
  EXPECT_TRUE(reparamTryingOtherMesher());
  const faceMeshingContext *theirs = nullptr;
  bool theyTry = true;
  const savedOptions *theirOptions = nullptr;
  std::thread other([&] {
    theirs = &thisThreadsFaceMeshing();
    theyTry = reparamTryingOtherMesher();
    theirOptions = &savedGmshOptions();
  });
  other.join();
  mine.tryingOtherMesher = false;
  EXPECT_NE(theirs, &mine);
  EXPECT_FALSE(theyTry);
  // Gmsh's options are global: their saved values too (none saved now)
  EXPECT_EQ(theirOptions, &savedGmshOptions());
  EXPECT_EQ(savedGmshOptions().crossFieldClosestPoint, -1);
  EXPECT_EQ(savedGmshOptions().smoothRatio, -1.);
}

TEST(reparamState, theLocksKeepOtherThreadsOut)
{
  // each lock held here: another thread cannot take it, then can
  auto tryFromAnotherThread = [](std::mutex &m) {
    bool taken = false;
    std::thread other([&] {
      taken = m.try_lock();
      if(taken) m.unlock();
    });
    other.join();
    return taken;
  };
  for(int which = 0; which < 3; which++) {
    std::unique_lock<std::mutex> lock = which == 0 ? lockRecords() :
                                        which == 1 ? lockReports() :
                                                     lockCurvatureFields();
    ASSERT_TRUE(lock.owns_lock());
    EXPECT_FALSE(tryFromAnotherThread(*lock.mutex())) << which;
    lock.unlock();
    EXPECT_TRUE(tryFromAnotherThread(*lock.mutex())) << which;
  }
  // the curves' lock: shared by faces being meshed, alone for a split
  curvesLock().lock_shared();
  bool shared = false, alone = true;
  std::thread other([&] {
    shared = curvesLock().try_lock_shared();
    if(shared) curvesLock().unlock_shared();
    alone = curvesLock().try_lock();
    if(alone) curvesLock().unlock();
  });
  other.join();
  curvesLock().unlock_shared();
  EXPECT_TRUE(shared);
  EXPECT_FALSE(alone);
}
