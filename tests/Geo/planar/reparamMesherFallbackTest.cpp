// Reparam - a face's planar mesh that leaves a hole or triangles against
// the input compared with the other planar mesher's, the better kept

#include <cmath>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MQuadrangle.h"
#include "MTriangle.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamHooks.h"
#include "reparamMeshValidity.h"
#include "reparamMesherFallback.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  GFace *meshedSquare() { return meshedSquareWithAShortCurve(0.1); }

} // namespace

TEST(reparamMeshValidity, aMissingTriangleLeavesCurveSegmentsUnused)
{
  GFace *gf = meshedSquare();
  ASSERT_TRUE(gf && !gf->triangles.empty());
  EXPECT_EQ(countUnusedCurveSegments(gf), 0u);
  // a triangle with an edge on the border taken out: that segment unused
  MTriangle *onBorder = nullptr;
  for(MTriangle *t : gf->triangles)
    for(int k = 0; k < 3 && !onBorder; k++)
      if(t->getVertex(k)->onWhat()->dim() < 2 &&
         t->getVertex((k + 1) % 3)->onWhat()->dim() < 2)
        onBorder = t;
  ASSERT_TRUE(onBorder);
  gf->triangles.erase(
    std::find(gf->triangles.begin(), gf->triangles.end(), onBorder));
  EXPECT_GE(countUnusedCurveSegments(gf), 1u);
  delete onBorder;
}

TEST(reparamMesherFallback, theOtherMesherIsKeptOnlyWhenBetter)
{
  GFace *gf = meshedSquare();
  ASSERT_TRUE(gf && !gf->triangles.empty());
  const MTriangle *first = gf->triangles[0];
  const std::size_t triangles = gf->triangles.size();
  // no defect: Delaunay's mesh cannot do better, Frontal-Delaunay's stays
  EXPECT_FALSE(reparamTryOtherMesher(gf, meshDefects()));
  EXPECT_EQ(gf->triangles.size(), triangles);
  EXPECT_EQ(gf->triangles[0], first);
  EXPECT_FALSE(reparamTryingOtherMesher());
  // told the current mesh has a hole: Delaunay's whole mesh replaces it
  meshDefects hole;
  hole.unusedCurveSegments = 1;
  EXPECT_TRUE(reparamTryOtherMesher(gf, hole));
  EXPECT_FALSE(gf->triangles.empty());
  EXPECT_EQ(countUnusedCurveSegments(gf), 0u);
  EXPECT_EQ(countTrianglesAgainstInput(gf), 0u);
  EXPECT_TRUE(freeMeshEdges().size() > 0u); // the square's sides only
}

TEST(reparamMesherFallback, quadrangleMeshesToo)
{
  gmsh::option::setNumber("Mesh.Algorithm", 8);
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  GFace *gf = meshedSquare();
  ASSERT_TRUE(gf && !gf->quadrangles.empty());
  // the quadrangles' sides count (they were not: every border segment of a
  // recombined mesh unused)
  EXPECT_EQ(countUnusedCurveSegments(gf), 0u);
  EXPECT_EQ(countLongEdges(gf), 0u);
  const MQuadrangle *first = gf->quadrangles[0];
  EXPECT_FALSE(reparamTryOtherMesher(gf, meshDefects()));
  EXPECT_EQ(gf->quadrangles[0], first);
  // told the current mesh has elements against the input: Delaunay's,
  // recombined as well, replaces it
  meshDefects against;
  against.againstInput = 2;
  EXPECT_TRUE(reparamTryOtherMesher(gf, against));
  EXPECT_FALSE(gf->quadrangles.empty());
  EXPECT_EQ(countUnusedCurveSegments(gf), 0u);
  EXPECT_EQ(countTrianglesAgainstInput(gf), 0u);
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.RecombineAll", 0);
}

namespace {

  // A closed cylinder (radius 0.126, height 0.75) whose wall is one row of
  // 72 needle triangles as tall as the cylinder, as CAD exports a hole's
  // wall; its caps fans around their centres
  testTriangulation needleCylinder()
  {
    const int n = 36;
    const double r = 0.126, height = 0.75;
    testTriangulation t;
    for(int level = 0; level < 2; level++)
      for(int i = 0; i < n; i++)
        t.points.push_back(SPoint3(r * std::cos(2. * M_PI * i / n),
                                   r * std::sin(2. * M_PI * i / n),
                                   level * height));
    t.points.push_back(SPoint3(0., 0., 0.));
    t.points.push_back(SPoint3(0., 0., height));
    for(int i = 0; i < n; i++) {
      const int j = (i + 1) % n;
      t.triangles.push_back({{i, j, n + j}});
      t.triangles.push_back({{i, n + j, n + i}});
      t.triangles.push_back({{2 * n, j, i}});
      t.triangles.push_back({{2 * n + 1, n + i, n + j}});
    }
    return t;
  }

} // namespace

TEST(reparamMeshValidity, aFaceTheMesherDidNotFillIsMeshedAgain)
{
  // Frontal-Delaunay finds no point to insert in the wall's (u, v) image
  // and leaves triangles across the whole wall (four sizes tall, kappa
  // 0.24): the long edges are counted and the wall is meshed again, by
  // MeshAdapt here
  const double size = 0.189;
  const std::vector<std::string> log = remeshWithRecipe(needleCylinder(), size);
  bool counted = false, remeshed = false;
  for(const std::string &line : log) {
    counted = counted || line.find("edges longer than twice the size") !=
                           std::string::npos;
    remeshed = remeshed || line.find("remeshed with") != std::string::npos;
  }
  EXPECT_TRUE(counted);
  EXPECT_TRUE(remeshed);
  EXPECT_TRUE(surfacesWithoutElements().empty());
  EXPECT_TRUE(freeMeshEdges().empty()); // closed
  double worst = 1.;
  std::size_t longEdges = 0;
  GModel *m = GModel::current();
  for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
    longEdges += countLongEdges(*it);
    for(MTriangle *t : (*it)->triangles)
      worst = std::min(worst, t->gammaShapeMeasure());
  }
  EXPECT_EQ(longEdges, 0u);
  EXPECT_GT(worst, 0.5);
}

TEST(reparamMesherFallback, underBamgTheOtherMesherTakesTheSizes)
{
  // BAMG's mesh of a 20 x 20 square at the size 3, then Delaunay's in its
  // place while BAMG is the global algorithm: Gmsh's Delaunay insertion
  // reads it and then took a size of 1 (fertility's faces BAMG left with
  // holes: 2.7 times the triangles)
  gmsh::option::setNumber("Mesh.Algorithm", 7);
  remeshWithRecipe(rectangleGrid(40, 40, 20., 20.), 3.);
  ASSERT_EQ(GModel::current()->getNumFaces(), 1u);
  GFace *gf = *GModel::current()->firstFace();
  ASSERT_TRUE(gf && !gf->triangles.empty());
  const std::size_t bamg = gf->triangles.size();
  // the recipe's sizes again (it resets them)
  gmsh::option::setNumber("Mesh.MeshSizeMin", 3.);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 3.);
  meshDefects hole;
  hole.unusedCurveSegments = 1;
  EXPECT_TRUE(reparamTryOtherMesher(gf, hole));
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
  EXPECT_EQ(countUnusedCurveSegments(gf), 0u);
  // about as many triangles as BAMG's (with a size of 1: 2.3 times)
  EXPECT_GT(3 * gf->triangles.size(), 2 * bamg);
  EXPECT_LT(2 * gf->triangles.size(), 3 * bamg);
  // the global algorithm is BAMG's again
  double algorithm = 0.;
  gmsh::option::getNumber("Mesh.Algorithm", algorithm);
  EXPECT_EQ(algorithm, 7.);
  gmsh::option::setNumber("Mesh.Algorithm", 6);
}

TEST(reparamMeshValidity, aQuadrangleMeshWithAHoleIsMeshedAgain)
{
  gmsh::option::setNumber("Mesh.Algorithm", 8);
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  GFace *gf = meshedSquare();
  ASSERT_TRUE(gf && !gf->quadrangles.empty());
  // a quadrangle with a side on the border taken out: a hole
  auto onBorder = std::find_if(
    gf->quadrangles.begin(), gf->quadrangles.end(), [](MQuadrangle *q) {
      for(int k = 0; k < 4; k++)
        if(q->getVertex(k)->onWhat()->dim() < 2 &&
           q->getVertex((k + 1) % 4)->onWhat()->dim() < 2)
          return true;
      return false;
    });
  ASSERT_TRUE(onBorder != gf->quadrangles.end());
  delete *onBorder;
  gf->quadrangles.erase(onBorder);
  gf->deleteVertexArrays();
  ASSERT_GE(countUnusedCurveSegments(gf), 1u);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.1);
  // Delaunay's mesh, recombined, in its place: no MeshAdapt from Gmsh
  EXPECT_FALSE(reparamPlanarMeshLeavesHole(gf));
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.RecombineAll", 0);
  EXPECT_FALSE(gf->quadrangles.empty());
  EXPECT_EQ(countUnusedCurveSegments(gf), 0u);
}

TEST(reparamMesherFallback, defectsInWords)
{
  meshDefects d;
  EXPECT_EQ(meshDefectsText(d), "0 triangles against the input");
  d.unusedCurveSegments = 1;
  d.againstInput = 2;
  d.longEdges = 3;
  EXPECT_EQ(meshDefectsText(d, "element"),
            "1 segment of its curves unused, 2 elements against the input, 3 "
            "edges longer than twice the size");
  d.unusedCurveSegments = 4;
  d.againstInput = (std::size_t)-1;
  d.longEdges = 0;
  EXPECT_EQ(meshDefectsText(d),
            "4 segments of its curves unused, triangles against the input "
            "not counted");
}
