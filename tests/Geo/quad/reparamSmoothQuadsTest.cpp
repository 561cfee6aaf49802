// Reparam - quadrangles of the faces Reparam parametrized (Frontal-Delaunay
// for quads + Blossom): smoothed in their (u, v) plane by Gmsh's
// recombination (patches/0015), then squared up on the input across the
// cut curves (Geo/quad/reparamSmoothQuads.cpp)

#include <algorithm>
#include <cmath>
#include <map>
#include <gtest/gtest.h>
#include "GEdge.h"
#include "GFace.h"
#include "GModel.h"
#include "MQuadrangle.h"
#include "MVertex.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "quadQuality.h"
#include "reparamOptimizeAcrossCuts.h"
#include "reparamSmoothQuads.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  struct quadMesh {
    std::size_t quads = 0, triangles = 0, freeEdges = 0, cuts = 0;
    std::size_t crossedCuts = 0;
    double etaMin = 1., etaMean = 0., farthestRadius = 0., nearestRadius = 2.;
  };

  // The recipe on t with Frontal-Delaunay for quads and Blossom, with map
  // `map` and Mesh.CompoundOptimize `optimize`
  void remeshIntoQuads(const testTriangulation &t, double size, int map,
                       int optimize)
  {
    gmsh::option::setNumber("Mesh.Algorithm", 8);
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.CompoundOptimize", optimize);
    gmsh::option::setNumber("Mesh.CompoundParametrization", map);
    gmsh::clear();
    gmsh::option::setNumber("Mesh.MeshSizeMin", size);
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);
    addDiscreteSurface(t);
    gmsh::model::mesh::classifySurfaces(40. * M_PI / 180, true, true, M_PI);
    gmsh::model::mesh::createGeometry();
    gmsh::model::mesh::generate(2);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
    gmsh::option::setNumber("Mesh.Algorithm", 6);
    gmsh::option::setNumber("Mesh.RecombineAll", 0);
    gmsh::option::setNumber("Mesh.CompoundOptimize", 2);
    gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  }

  quadMesh measure()
  {
    quadMesh q;
    GModel *m = GModel::current();
    std::map<std::pair<MVertex *, MVertex *>, int> uses;
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      GFace *gf = *it;
      q.triangles += gf->triangles.size();
      for(std::size_t e = 0; e < gf->getNumMeshElements(); e++) {
        MElement *el = gf->getMeshElement(e);
        const int n = (int)el->getNumVertices();
        for(int k = 0; k < n; k++) {
          MVertex *a = el->getVertex(k), *b = el->getVertex((k + 1) % n);
          uses[std::make_pair(std::min(a, b), std::max(a, b))]++;
          const double r = a->point().distance(SPoint3(0., 0., 0.));
          q.farthestRadius = std::max(q.farthestRadius, r);
          q.nearestRadius = std::min(q.nearestRadius, r);
        }
      }
      for(MQuadrangle *e : gf->quadrangles) {
        const double eta =
          quadEta(e->getVertex(0)->point(), e->getVertex(1)->point(),
                  e->getVertex(2)->point(), e->getVertex(3)->point());
        q.etaMin = std::min(q.etaMin, eta);
        q.etaMean += eta;
        q.quads++;
      }
    }
    q.etaMean /= std::max<std::size_t>(q.quads, 1);
    for(const auto &u : uses) q.freeEdges += u.second != 2;
    for(auto it = m->firstEdge(); it != m->lastEdge(); ++it)
      if((*it)->faces().size() == 2) {
        q.cuts++;
        q.crossedCuts += (*it)->lines.empty();
      }
    return q;
  }

  // The unit sphere's longitude-latitude triangulation, closed: the layout
  // cuts it into disks along its edges
  testTriangulation unitSphere() { return sphere(48, 24); }

} // namespace

TEST(smoothQuads, recombinationSmoothsInTheParametricPlane)
{
  // a hemisphere, one disk: Gmsh's own map (Gmsh's behaviour, Blossom's
  // quadrangles not smoothed on a discrete face) against Reparam's (the
  // same mesher, smoothed as on a CAD face), neither optimized after
  remeshIntoQuads(hemisphere(16, 64), 0.08, 0, 0);
  const quadMesh gmshMap = measure();
  remeshIntoQuads(hemisphere(16, 64), 0.08, 6, 0);
  const quadMesh reparamMap = measure();
  EXPECT_GT(gmshMap.quads, 300u);
  EXPECT_GT(reparamMap.quads, 300u);
  EXPECT_LT(gmshMap.etaMean, 0.78); // measured 0.736
  EXPECT_GT(reparamMap.etaMean, 0.85); // measured 0.885
  EXPECT_GT(reparamMap.etaMin, 0.3); // measured 0.476 (Gmsh's map: 0.118)
  EXPECT_EQ(reparamMap.freeEdges, gmshMap.freeEdges); // the border
}

TEST(smoothQuads, cutNodesMoveAcrossAndTheMeshStaysWhole)
{
  remeshIntoQuads(unitSphere(), 0.12, 6, 0);
  const quadMesh before = measure();
  ASSERT_GE(before.cuts, 1u);
  EXPECT_EQ(before.crossedCuts, 0u);
  EXPECT_EQ(before.freeEdges, 0u);
  EXPECT_EQ(reparamSmoothQuadMeshes(GModel::current()), 1);
  const quadMesh after = measure();
  // a few quadrangles collapsed (Mesh/quad/quadDiagonalCollapse.h): 915 -> 887
  EXPECT_LT(after.quads, before.quads);
  EXPECT_GT(after.quads, 0.95 * before.quads);
  EXPECT_EQ(after.freeEdges, 0u); // closed, manifold
  EXPECT_GE(after.crossedCuts, 1u);
  // measured 0.490 -> 0.535 (0.618 by the angles alone, without the edges'
  // ratio to the size in the node moves, Mesh/quad/quadNodeSmoothing.h)
  EXPECT_GT(after.etaMin, before.etaMin + 0.03);
  // 0.866 -> 0.881 (0.885 by the angles alone; 0.868 -> 0.881 without the
  // collapses)
  EXPECT_GT(after.etaMean, before.etaMean + 0.012);
  // the nodes on the input: a polyhedron inside the unit sphere, no node
  // deeper than the input's facets (0.996)
  EXPECT_LT(after.farthestRadius, 1. + 1e-9);
  EXPECT_GT(after.nearestRadius, before.nearestRadius - 1e-4);
  // done: the meshes are those it left
  EXPECT_EQ(reparamSmoothQuadMeshes(GModel::current()), 0);
}

TEST(smoothQuads, partOfCompoundOptimize)
{
  remeshIntoQuads(unitSphere(), 0.12, 6, 0);
  const quadMesh off = measure();
  remeshIntoQuads(unitSphere(), 0.12, 6, 2);
  const quadMesh on = measure();
  EXPECT_GT(on.etaMean, off.etaMean + 0.008);
  EXPECT_GE(on.crossedCuts, 1u);
}
