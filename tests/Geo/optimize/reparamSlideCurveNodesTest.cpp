// Reparam - the nodes of the feature curves and borders slid along them

#include <cmath>
#include <map>
#include <gtest/gtest.h>
#include "GEdge.h"
#include "GFace.h"
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "gmshTestEnvironment.h"
#include "curveNodeSlide.h"
#include "reparamCurveMesh.h"
#include "reparamOptimizableMesh.h"
#include "reparamSlideCurveNodes.h"
#include "triangleQuality.h"

using namespace reparam;

namespace {

  double worstAround(GModel *m, const MVertex *v)
  {
    double worst = 1.;
    for(auto it = m->firstFace(); it != m->lastFace(); ++it)
      for(MTriangle *t : (*it)->triangles)
        for(int j = 0; j < 3; j++)
          if(t->getVertex(j) == v)
            worst = std::min(worst, triangleKappa(t->getVertex(0)->point(),
                                                  t->getVertex(1)->point(),
                                                  t->getVertex(2)->point()));
    return worst;
  }

} // namespace

TEST(reparamSlideCurveNodes, aBorderNodeAHairFromItsNeighbourSlidesBack)
{
  // the unit square remeshed at 0.1: a node of its bottom side moved to
  // 5 % of a segment from the next one (a sliver at the border, which no
  // optimizer before moves) slides back between its neighbours, on the side
  remeshWithRecipe(rectangleGrid(20, 20, 1., 1.), 0.1);
  GModel *m = GModel::current();
  GEdge *side = nullptr;
  MVertex *node = nullptr;
  double before = 0., after = 0.;
  for(auto it = m->firstEdge(); it != m->lastEdge() && !node; ++it) {
    std::map<MVertex *, MVertex *> next, previous;
    for(MLine *l : (*it)->lines) {
      next[l->getVertex(0)] = l->getVertex(1);
      previous[l->getVertex(1)] = l->getVertex(0);
    }
    for(MVertex *v : (*it)->mesh_vertices) {
      MVertex *a = next[v], *b = previous[v];
      if(!a || !b || a->onWhat() != *it || b->onWhat() != *it ||
         std::fabs(v->y()) > 1e-12 || std::fabs(a->y()) > 1e-12 ||
         std::fabs(b->y()) > 1e-12)
        continue;
      a->getParameter(0, after);
      b->getParameter(0, before);
      side = *it;
      node = v;
      break;
    }
  }
  ASSERT_TRUE(node);
  const double bad = after - 0.05 * (after - before);
  const GPoint p = side->point(bad);
  node->setXYZ(p.x(), p.y(), p.z());
  node->setParameter(0, bad);
  const double worstBefore = worstAround(m, node);
  EXPECT_LT(worstBefore, 0.2);

  EXPECT_GE(reparamSlideCurveNodes(m), 1);
  const double worstAfter = worstAround(m, node);
  EXPECT_GT(worstAfter, 0.6);
  double t = 0.;
  node->getParameter(0, t);
  EXPECT_GT(t, before);
  EXPECT_LT(t, bad);
  EXPECT_NEAR(node->y(), 0., 1e-12); // still on the side
  const GPoint q = side->point(t);
  EXPECT_NEAR(node->x(), q.x(), 1e-12);
  // the slide was judged where Gmsh's curve puts the node: parameter i at
  // the input polyline's node i
  std::vector<SPoint3> polyline;
  ASSERT_TRUE(reparamInputPolyline(side, polyline));
  EXPECT_LT(pointOnPolyline(polyline, t).distance(node->point()), 1e-12);
}

TEST(reparamSlideCurveNodes, onlyFacesReparamMeshedWithTrianglesMayChange)
{
  remeshWithRecipe(rectangleGrid(10, 10, 1., 1.), 0.2);
  GModel *m = GModel::current();
  ASSERT_GT(m->getNumFaces(), 0u);
  GFace *gf = *m->firstFace();
  EXPECT_TRUE(reparamOptimizableFace(gf));
  // without its triangles (or with quadrangles) it is not
  std::vector<MTriangle *> triangles;
  triangles.swap(gf->triangles);
  EXPECT_FALSE(reparamOptimizableFace(gf));
  triangles.swap(gf->triangles);
  EXPECT_TRUE(reparamOptimizableFace(gf));
}
