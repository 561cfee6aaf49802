// Reparam on two threads (General.NumThreads = 2, Gmsh built with OpenMP):
// the layout verifies its parts in parallel and gives the same mesh; the
// curves and surfaces Reparam works on are meshed on one thread

#include <string>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamFaceMeshing.h"
#include "testPatches.h"
#include "triangleQuality.h"

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

  bool logHas(const std::vector<std::string> &log, const std::string &what)
  {
    for(const std::string &l : log)
      if(l.find(what) != std::string::npos) return true;
    return false;
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

TEST(reparamThreads, twoThreadsGiveTheSameMesh)
{
  // a torus: its one feature patch is cut into disks by the layout
  remeshWithRecipe(torus(48, 16, 2., 0.6), 0.2);
  const std::pair<std::size_t, double> one = meshSummary();
  std::pair<std::size_t, double> two;
  std::vector<std::string> log;
  {
    threadCount threads(2);
    if(Msg::GetMaxThreads() < 2) GTEST_SKIP() << "Gmsh built without OpenMP";
    log = remeshWithRecipe(torus(48, 16, 2., 0.6), 0.2);
    two = meshSummary();
  }
  EXPECT_FALSE(logHas(log, "Error"));
  EXPECT_TRUE(logHas(log, "on 2 threads"));
  EXPECT_TRUE(logHas(log, "meshed on one thread"));
  EXPECT_GT(one.first, 1000u);
  EXPECT_EQ(one.first, two.first);
  EXPECT_EQ(one.second, two.second);
}

TEST(reparamThreads, discreteEntitiesAreMeshedOnOneThread)
{
  remeshWithRecipe(hemisphere(12, 48), 0.1);
  // one thread: nothing to serialize
  EXPECT_TRUE(reparamMeshInParallel(GModel::current()));
  threadCount threads(2);
  if(Msg::GetMaxThreads() < 2) GTEST_SKIP() << "Gmsh built without OpenMP";
  EXPECT_FALSE(reparamMeshInParallel(GModel::current()));
  // Gmsh's own map: Gmsh's own behaviour
  gmsh::option::setNumber("Mesh.CompoundParametrization", 0);
  EXPECT_TRUE(reparamMeshInParallel(GModel::current()));
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  // a model without discrete entities
  gmsh::clear();
  gmsh::model::add("square");
  gmsh::model::geo::addPoint(0, 0, 0);
  gmsh::model::geo::addPoint(1, 0, 0);
  gmsh::model::geo::addLine(1, 2);
  gmsh::model::geo::synchronize();
  EXPECT_TRUE(reparamMeshInParallel(GModel::current()));
}
