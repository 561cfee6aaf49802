// Reparam - the STL recipe's new meshes optimized on their input
// (Mesh.CompoundOptimize): better worst triangles, nodes whose (u, v) still
// maps to them, ridges the mesh cut off brought back, the mesh whole

#include <algorithm>
#include <cmath>
#include <map>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "closestTriangle.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "testPatches.h"
#include "triangleQuality.h"

using namespace reparam;

namespace {

  struct remeshed {
    std::vector<SPoint3> points;
    std::vector<std::array<int, 3> > triangles;
    double worstKappa = 1.;
    double worstUvMismatch = 0.; // |point(u, v) - xyz| over the face nodes
    std::size_t freeEdges = 0;
    bool optimizedLogged = false;
  };

  // The recipe on t at `size` with Mesh.CompoundOptimize = optimize and
  // ClassifySurfaces{featureAngle, 1, 1, 180 deg}; what came out
  remeshed remesh(const testTriangulation &t, double size, int optimize,
                  double featureAngle = 40.)
  {
    gmsh::option::setNumber("Mesh.CompoundOptimize", optimize);
    const std::vector<std::string> log =
      remeshWithRecipe(t, size, featureAngle);
    gmsh::option::setNumber("Mesh.CompoundOptimize", 2);
    remeshed r;
    for(const std::string &line : log)
      r.optimizedLogged =
        r.optimizedLogged ||
        line.find("optimized on the input") != std::string::npos;
    std::map<MVertex *, int> index;
    GModel *m = GModel::current();
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      GFace *gf = *it;
      for(MTriangle *tri : gf->triangles) {
        std::array<int, 3> c;
        for(int k = 0; k < 3; k++) {
          MVertex *v = tri->getVertex(k);
          auto found = index.find(v);
          if(found == index.end()) {
            found = index.insert(std::make_pair(v, (int)r.points.size())).first;
            r.points.push_back(v->point());
          }
          c[k] = found->second;
        }
        r.triangles.push_back(c);
        r.worstKappa =
          std::min(r.worstKappa, triangleKappa(r.points[c[0]], r.points[c[1]],
                                               r.points[c[2]]));
      }
      for(MVertex *v : gf->mesh_vertices) {
        double u, w;
        if(!v->getParameter(0, u) || !v->getParameter(1, w)) continue;
        const GPoint p = gf->point(u, w);
        r.worstUvMismatch = std::max(
          r.worstUvMismatch, v->point().distance(SPoint3(p.x(), p.y(), p.z())));
      }
    }
    r.freeEdges = freeMeshEdges().size();
    return r;
  }

  // The largest distance of the inner ridge nodes of the roof (x = 0.5,
  // off the border, whose curve the optimizer does not change) to the
  // remeshed surface
  double ridgeCutOff(const testTriangulation &roof, const remeshed &r)
  {
    const closestTriangleSearch onMesh(r.points, r.triangles);
    double d = 0.;
    for(const SPoint3 &p : roof.points)
      if(std::fabs(p.x() - 0.5) < 1e-9 && p.y() > 0.2 && p.y() < 0.8)
        d = std::max(d, onMesh.closest(p).distance);
    return d;
  }

} // namespace

TEST(reparamOptimizeFace, betterWorstTrianglesNodesStillOnTheMap)
{
  // A jittered grid on a bump: coarse, irregular input triangles under a
  // mesh of the same size, where Frontal-Delaunay's triangles are good in
  // (u, v) but not all in 3D
  testTriangulation input = liftPlanar(jitteredGrid(24, 0.9, 7), 0.25);
  const remeshed plain = remesh(input, 0.03, 0);
  const remeshed optimized = remesh(input, 0.03, 1);
  EXPECT_FALSE(plain.optimizedLogged);
  EXPECT_TRUE(optimized.optimizedLogged);
  EXPECT_GE(optimized.worstKappa, plain.worstKappa);
  EXPECT_GT(optimized.worstKappa, 0.4);
  // the moved nodes' (u, v) is where they are
  EXPECT_LT(optimized.worstUvMismatch, 1e-9);
  // whole: only the square's sides are free
  EXPECT_EQ(optimized.freeEdges, plain.freeEdges);
  EXPECT_GT(optimized.triangles.size(), 1000u);
}

TEST(reparamOptimizeFace, aRidgeBelowTheFeatureAngleIsNotCutOff)
{
  // A roof whose ridge (77 degrees between the normals, no feature for
  // ClassifySurfaces{80 deg}) runs between the nodes of a coarse mesh: the
  // input's ridge nodes the mesh cuts off are inserted. (A ridge below 40
  // degrees is cut off by less than a quarter of the size unless the
  // mesher's edges are much longer than the size: split first)
  testTriangulation roof = rectangleGrid(40, 40, 1., 1.);
  for(SPoint3 &p : roof.points)
    p = SPoint3(p.x(), p.y(), 0.8 * (0.5 - std::fabs(p.x() - 0.5)));
  // sizes as Gmsh extends them from the border's short segments at the
  // ridge (graded, the mesh there is coarser and cuts the ridge off by
  // barely more than a quarter of the size: nothing to compare)
  gmsh::option::setNumber("Mesh.CompoundMeshSizeGradient", 0);
  const remeshed plain = remesh(roof, 0.17, 0, 80.);
  const remeshed optimized = remesh(roof, 0.17, 1, 80.);
  gmsh::option::setNumber("Mesh.CompoundMeshSizeGradient", 0.5);
  const double before = ridgeCutOff(roof, plain),
               after = ridgeCutOff(roof, optimized);
  EXPECT_GT(before, 0.25 * 0.17);
  // none left farther than the insertion threshold, a quarter of the size
  // (0.055 -> 0.036)
  EXPECT_LT(after, 0.25 * 0.17);
  EXPECT_LT(after, 0.7 * before);
  EXPECT_LT(optimized.worstUvMismatch, 1e-9);
  EXPECT_EQ(optimized.freeEdges, plain.freeEdges);
}

TEST(reparamOptimizeFace, levelTwoCollapsesWhatTheCurvesMadeTooFine)
{
  // A square with a small plateau in its middle, on walls one input cell
  // wide: their short curves' segments make the planar mesher refine the
  // square around them (Mesh.MeshSizeExtendFromBoundary), finer than asked;
  // Mesh.CompoundOptimize = 2 collapses short edges there: fewer triangles,
  // none worse than 0.3, the mesh whole and its nodes on the map
  testTriangulation plateau = rectangleGrid(40, 40, 1., 1.);
  for(SPoint3 &p : plateau.points)
    if(std::fabs(p.x() - 0.5) < 0.06 && std::fabs(p.y() - 0.5) < 0.06)
      p = SPoint3(p.x(), p.y(), 0.05);
  // Gmsh's extension of the sizes (graded, 426 -> 384 triangles)
  gmsh::option::setNumber("Mesh.CompoundMeshSizeGradient", 0);
  const remeshed one = remesh(plateau, 0.1, 1);
  const remeshed two = remesh(plateau, 0.1, 2);
  gmsh::option::setNumber("Mesh.CompoundMeshSizeGradient", 0.5);
  EXPECT_LT(two.triangles.size(), 0.85 * one.triangles.size()); // 552 -> 420
  EXPECT_GE(two.worstKappa, std::min(one.worstKappa, 0.3));
  EXPECT_EQ(two.freeEdges, one.freeEdges);
  // the square is planar: Gmsh's own (u, v) on its mean plane
  EXPECT_LT(one.worstUvMismatch, 1e-9);
  EXPECT_LT(two.worstUvMismatch, 1e-9);
}
