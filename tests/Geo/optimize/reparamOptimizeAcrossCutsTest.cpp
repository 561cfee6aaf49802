// Reparam - the faces a closed patch was cut into, optimized together across
// their cut curves (Mesh.CompoundOptimize): the zig-zag cut is crossed, the
// mesh stays whole, on the input and turned along it

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include "GEdge.h"
#include "GFace.h"
#include "GModel.h"
#include "GVertex.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamHooks.h"
#include "reparamOptimizeAcrossCuts.h"
#include "testPatches.h"
#include "triangleQuality.h"

using namespace reparam;

namespace {

  // A pseudo-random number in [-1, 1] of a grid node (the same on both
  // sides of the sphere's seam)
  double noiseAt(int i, int j, int salt)
  {
    unsigned h = 2654435761u * (unsigned)(i + 7919 * j + 104729 * salt);
    h ^= h >> 13;
    h *= 2246822519u;
    h ^= h >> 16;
    return 2. * (h % 10000) / 9999. - 1.;
  }

  // The unit sphere's longitude-latitude triangulation with its inner nodes
  // moved at random by up to `amount` of a grid step in longitude and
  // latitude: the layout's cut follows its edges in a zig-zag
  testTriangulation jitteredSphere(int nLongitude, int nLatitude, double amount)
  {
    testTriangulation t = rectangleGrid(nLongitude, nLatitude, 1., 1.);
    for(SPoint3 &p : t.points) {
      const int i = (int)std::lround(p.x() * nLongitude) % nLongitude;
      const int j = (int)std::lround(p.y() * nLatitude);
      if(j == 0 || j == nLatitude) {
        p = SPoint3(0., 0., j ? 1. : -1.); // the poles
        continue;
      }
      const double phi =
        2. * M_PI * (p.x() + amount * noiseAt(i, j, 0) / nLongitude);
      const double theta =
        M_PI * (p.y() + amount * noiseAt(i, j, 1) / nLatitude);
      p = SPoint3(std::sin(theta) * std::cos(phi),
                  std::sin(theta) * std::sin(phi), -std::cos(theta));
    }
    return weld(t, 1e-9);
  }

  struct sphereMesh {
    double worstKappa = 1.;
    double worstRadius = 1., farthestRadius = 1.;
    std::size_t inward = 0, triangles = 0;
    std::size_t crossedCuts = 0, cuts = 0, faces = 0;
  };

  // The recipe on a closed unit sphere whose input edges zig-zag (the
  // layout cuts it into disks along them) with Mesh.CompoundOptimize =
  // optimize; false if the log has an error
  bool remeshSphere(int optimize)
  {
    gmsh::option::setNumber("Mesh.CompoundOptimize", optimize);
    const std::vector<std::string> log =
      remeshWithRecipe(jitteredSphere(32, 16, 0.2), 0.08);
    gmsh::option::setNumber("Mesh.CompoundOptimize", 2);
    for(const std::string &l : log)
      if(l.find("Error") != std::string::npos) return false;
    return true;
  }

  // The current model's mesh of the unit sphere
  sphereMesh measureSphere()
  {
    sphereMesh s;
    GModel *m = GModel::current();
    for(const cutGroup &g : facesJoinedByCuts(m, {})) {
      s.faces += g.faces.size();
      s.cuts += g.cuts.size();
      for(GEdge *ge : g.cuts) s.crossedCuts += ge->lines.empty();
    }
    for(auto it = m->firstFace(); it != m->lastFace(); ++it)
      for(MTriangle *t : (*it)->triangles) {
        const SPoint3 a = t->getVertex(0)->point(),
                      b = t->getVertex(1)->point(),
                      c = t->getVertex(2)->point();
        s.triangles++;
        s.worstKappa = std::min(s.worstKappa, triangleKappa(a, b, c));
        // the input is turned outwards
        const SVector3 n = crossprod(SVector3(a, b), SVector3(a, c));
        const SPoint3 g = (a + b + c) * (1. / 3.);
        if(dot(n, SVector3(g.x(), g.y(), g.z())) < 0.) s.inward++;
        for(int k = 0; k < 3; k++) {
          const double r = t->getVertex(k)->point().distance(SPoint3(0, 0, 0));
          s.worstRadius = std::min(s.worstRadius, r);
          s.farthestRadius = std::max(s.farthestRadius, r);
        }
      }
    return s;
  }

  // Every other node of the cut curves slid 80 % of the way to the next one
  // along the curve, as Gmsh's 1D mesher bunches them at a zig-zag's kinks:
  // slivers on both sides of the cut, that only a change across it can mend
  void bunchCutNodes()
  {
    for(const cutGroup &g : facesJoinedByCuts(GModel::current(), {}))
      for(GEdge *ge : g.cuts) {
        std::vector<std::pair<double, MVertex *> > nodes;
        for(MVertex *v : ge->mesh_vertices) {
          double t;
          if(v->getParameter(0, t)) nodes.push_back(std::make_pair(t, v));
        }
        std::sort(nodes.begin(), nodes.end());
        for(std::size_t k = 1; k + 1 < nodes.size(); k += 2) {
          const double t =
            nodes[k].first + 0.8 * (nodes[k + 1].first - nodes[k].first);
          const GPoint p = ge->point(t);
          nodes[k].second->setParameter(0, t);
          nodes[k].second->setXYZ(p.x(), p.y(), p.z());
        }
      }
  }

} // namespace

TEST(optimizeAcrossCuts, zigZagCutIsCrossedAndTheMeshStaysWhole)
{
  // the planar meshes as they are, the cut's nodes bunched, then the
  // meshes optimized together across the cut
  ASSERT_TRUE(remeshSphere(0));
  bunchCutNodes();
  const sphereMesh before = measureSphere();
  EXPECT_EQ(before.faces, 2u);
  EXPECT_EQ(before.cuts, 1u);
  EXPECT_EQ(before.crossedCuts, 0u);
  EXPECT_LT(before.worstKappa, 0.1); // measured 0.068
  EXPECT_EQ(reparamOptimizeMeshedModel(GModel::current()), 1);
  const sphereMesh after = measureSphere();
  EXPECT_EQ(after.crossedCuts, 1u);
  EXPECT_GT(after.worstKappa, 0.6); // measured 0.640
  EXPECT_TRUE(surfacesWithoutElements().empty());
  std::size_t nonManifold = 0;
  EXPECT_TRUE(freeMeshEdges(&nonManifold).empty());
  EXPECT_EQ(nonManifold, 0u);
  // every node on the input, a polyhedron inside the unit sphere
  EXPECT_GT(after.worstRadius, before.worstRadius - 1e-3);
  EXPECT_LT(after.farthestRadius, 1. + 1e-9);
  EXPECT_EQ(after.inward, 0u);
  // done: its mesh is the one it left
  EXPECT_EQ(reparamOptimizeMeshedModel(GModel::current()), 0);
}

TEST(optimizeAcrossCuts, aPointOnlyCutsMeetAtMovesLikeTheirNodes)
{
  // the sphere's cut is a closed curve through one model point, which marks
  // nothing of the input: the mesh's node there moves with the cut's, and
  // the point keeps its own node (its place) and point element, which no
  // triangle uses
  ASSERT_TRUE(remeshSphere(0));
  const std::vector<cutGroup> groups = facesJoinedByCuts(GModel::current(), {});
  ASSERT_EQ(groups.size(), 1u);
  ASSERT_EQ(groups[0].cuts.size(), 1u);
  GVertex *gv = groups[0].cuts[0]->getBeginVertex();
  ASSERT_EQ(gv, groups[0].cuts[0]->getEndVertex());
  ASSERT_EQ(gv->mesh_vertices.size(), 1u);
  ASSERT_EQ(gv->points.size(), 1u);
  MVertex *node = gv->mesh_vertices[0];
  const SPoint3 place = node->point();
  const auto used = [&]() {
    for(auto it = GModel::current()->firstFace();
        it != GModel::current()->lastFace(); ++it)
      for(MTriangle *t : (*it)->triangles)
        for(int k = 0; k < 3; k++)
          if(t->getVertex(k) == node) return true;
    return false;
  };
  ASSERT_TRUE(used());
  bunchCutNodes();
  EXPECT_EQ(reparamOptimizeMeshedModel(GModel::current()), 1);
  ASSERT_EQ(gv->mesh_vertices.size(), 1u);
  EXPECT_EQ(gv->mesh_vertices[0], node);
  EXPECT_EQ(gv->points.size(), 1u);
  EXPECT_EQ(SPoint3(gv->x(), gv->y(), gv->z()).distance(place), 0.);
  EXPECT_FALSE(used());
  EXPECT_TRUE(surfacesWithoutElements().empty());
  std::size_t nonManifold = 0;
  EXPECT_TRUE(freeMeshEdges(&nonManifold).empty());
  EXPECT_EQ(nonManifold, 0u);
  EXPECT_GT(measureSphere().worstKappa, 0.6);
}

TEST(optimizeAcrossCuts, offWithoutCompoundOptimize)
{
  ASSERT_TRUE(remeshSphere(0));
  gmsh::option::setNumber("Mesh.CompoundOptimize", 0);
  EXPECT_EQ(reparamOptimizeMeshedModel(GModel::current()), 0);
  gmsh::option::setNumber("Mesh.CompoundOptimize", 2);
  EXPECT_EQ(measureSphere().crossedCuts, 0u);
}

TEST(optimizeAcrossCuts, aPatchCutIntoNoDiskHasNoGroup)
{
  // a hemisphere is one disk: no cut, nothing to join
  remeshWithRecipe(hemisphere(12, 48), 0.1);
  EXPECT_TRUE(facesJoinedByCuts(GModel::current(), {}).empty());
}
