// Reparam - a face's planar mesh that leaves a hole or triangles against
// the input compared with the other planar mesher's, the better kept

#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamMeshValidity.h"
#include "reparamMesherFallback.h"

namespace {

  GFace *meshedSquare()
  {
    squareWithAShortCurve();
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.1);
    gmsh::model::mesh::generate(2);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
    return GModel::current()->getFaceByTag(1);
  }

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
