// Reparam on two threads (General.NumThreads = 2, Gmsh built with OpenMP):
// the layout verifies its parts in parallel and gives the same patches; the
// curves and surfaces Reparam works on are meshed on one thread

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "testPatches.h"
#include "triangleQuality.h"
#include "reparamHooks.h"

using namespace reparam;

namespace {

  // Triangles and worst kappa of the current model's mesh
  std::pair<std::size_t, double> meshSummary()
  {
    std::size_t n = 0;
    double worst = 1.;
    GModel *m = GModel::current();
    for(auto it = m->firstFace(); it != m->lastFace(); ++it)
      for(MTriangle *t : (*it)->triangles) {
        n++;
        worst = std::min(worst, triangleKappa(t->getVertex(0)->point(),
                                              t->getVertex(1)->point(),
                                              t->getVertex(2)->point()));
      }
    return {n, worst};
  }

  std::string lineWith(const std::vector<std::string> &log,
                       const std::string &what)
  {
    for(const std::string &l : log)
      if(l.find(what) != std::string::npos) return l;
    return std::string();
  }

  bool logHas(const std::vector<std::string> &log, const std::string &what)
  {
    return !lineWith(log, what).empty();
  }

  // General.NumThreads = n for the test's scope
  struct threadCount {
    explicit threadCount(int n)
    {
      gmsh::option::setNumber("General.NumThreads", n);
    }
    ~threadCount() { gmsh::option::setNumber("General.NumThreads", 1); }
  };

} // namespace

TEST(reparamThreads, twoThreadsGiveTheSameLayout)
{
  // a torus: its one feature patch is cut into disks by the layout, the
  // parts verified on one thread, then on two
  const std::vector<std::string> one =
    remeshWithRecipe(torus(48, 16, 2., 0.6), 0.2);
  const std::size_t facesOne = GModel::current()->getNumFaces();
  const std::pair<std::size_t, double> meshOne = meshSummary();
  std::vector<std::string> two;
  std::size_t facesTwo = 0;
  std::pair<std::size_t, double> meshTwo;
  {
    threadCount threads(2);
    if(Msg::GetMaxThreads() < 2) GTEST_SKIP() << "Gmsh built without OpenMP";
    two = remeshWithRecipe(torus(48, 16, 2., 0.6), 0.2);
    facesTwo = GModel::current()->getNumFaces();
    meshTwo = meshSummary();
  }
  EXPECT_FALSE(logHas(two, "Error"));
  EXPECT_TRUE(logHas(two, "on 2 threads"));
  EXPECT_TRUE(logHas(two, "meshed on one thread"));
  // the same splits and patches (the layout's line up to its times)
  const std::string layoutOne = lineWith(one, "Reparam: layout of");
  const std::string layoutTwo = lineWith(two, "Reparam: layout of");
  ASSERT_FALSE(layoutOne.empty());
  EXPECT_EQ(layoutOne.substr(0, layoutOne.find("(clean")),
            layoutTwo.substr(0, layoutTwo.find("(clean")));
  EXPECT_GE(facesOne, 2u);
  EXPECT_EQ(facesOne, facesTwo);
  // Gmsh's planar meshes of the same faces may differ by a few triangles
  // from one run to the next in a process (it orders some nodes by their
  // addresses): alike, not equal
  EXPECT_GT(meshOne.first, 1000u);
  EXPECT_NEAR((double)meshTwo.first, (double)meshOne.first,
              0.01 * meshOne.first);
  EXPECT_GT(meshTwo.second, 0.5);
}

TEST(reparamThreads, discreteCurvesAreMeshedOnOneThreadSurfacesOnAll)
{
  remeshWithRecipe(hemisphere(12, 48), 0.1);
  // one thread: nothing to serialize
  EXPECT_TRUE(reparamMeshInParallel(GModel::current(), 1));
  EXPECT_TRUE(reparamMeshInParallel(GModel::current(), 2));
  threadCount threads(2);
  if(Msg::GetMaxThreads() < 2) GTEST_SKIP() << "Gmsh built without OpenMP";
  EXPECT_FALSE(reparamMeshInParallel(GModel::current(), 1));
  EXPECT_TRUE(reparamMeshInParallel(GModel::current(), 2));
  // quadrangles: on one thread
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  EXPECT_FALSE(reparamMeshInParallel(GModel::current(), 2));
  gmsh::option::setNumber("Mesh.RecombineAll", 0);
  // Gmsh's own map: Gmsh's own behaviour
  gmsh::option::setNumber("Mesh.CompoundParametrization", 0);
  EXPECT_TRUE(reparamMeshInParallel(GModel::current(), 1));
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  // a model without discrete entities
  gmsh::clear();
  gmsh::model::add("square");
  gmsh::model::geo::addPoint(0, 0, 0);
  gmsh::model::geo::addPoint(1, 0, 0);
  gmsh::model::geo::addLine(1, 2);
  gmsh::model::geo::synchronize();
  EXPECT_TRUE(reparamMeshInParallel(GModel::current(), 1));
}

TEST(reparamThreads, curveSplitWaitsForTheFacesBeingMeshed)
{
  remeshWithRecipe(hemisphere(12, 48), 0.1);
  GFace *gf = *GModel::current()->firstFace();
  // a face being meshed on this thread: another thread's split of curve
  // segments (Gmsh's, when a face cannot recover them) waits for its end
  reparamBeginFaceMeshing(gf);
  std::atomic<bool> split(false);
  std::thread other([&split]() {
    reparamBeginCurveSplit();
    split = true;
    reparamEndCurveSplit();
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(split.load());
  reparamEndFaceMeshing(gf);
  other.join();
  EXPECT_TRUE(split.load());
  // a split on the thread meshing the face lets its own lock go meanwhile
  reparamBeginFaceMeshing(gf);
  reparamBeginCurveSplit();
  reparamEndCurveSplit();
  reparamEndFaceMeshing(gf);
  // and no face being meshed: no wait
  reparamBeginCurveSplit();
  reparamEndCurveSplit();
}
