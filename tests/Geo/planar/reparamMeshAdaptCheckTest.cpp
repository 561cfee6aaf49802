// Reparam - a MeshAdapt mesh that leaves a hole or elements against the
// input compared with the other planar meshers', the better kept

#include <algorithm>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamHooks.h"
#include "reparamMeshValidity.h"
#include "reparamMesherFallback.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  GFace *squareMeshedWith(int algorithm)
  {
    gmsh::option::setNumber("Mesh.Algorithm", algorithm);
    return meshedSquareWithAShortCurve(0.1);
  }

  // a triangle with an edge on the border taken out of gf: a hole
  void takeOutABorderTriangle(GFace *gf)
  {
    auto onBorder = std::find_if(
      gf->triangles.begin(), gf->triangles.end(), [](MTriangle *t) {
        for(int k = 0; k < 3; k++)
          if(t->getVertex(k)->onWhat()->dim() < 2 &&
             t->getVertex((k + 1) % 3)->onWhat()->dim() < 2)
            return true;
        return false;
      });
    ASSERT_TRUE(onBorder != gf->triangles.end());
    MTriangle *t = *onBorder;
    gf->triangles.erase(onBorder);
    delete t;
    gf->deleteVertexArrays();
  }

  struct meshAdaptCheck : public ::testing::Test {
    void TearDown() override { gmsh::option::setNumber("Mesh.Algorithm", 6); }
  };

} // namespace

TEST_F(meshAdaptCheck, aWholeMeshAdaptMeshIsKept)
{
  GFace *gf = squareMeshedWith(1);
  ASSERT_TRUE(gf && !gf->triangles.empty());
  const MTriangle *first = gf->triangles[0];
  const std::size_t triangles = gf->triangles.size();
  EXPECT_FALSE(reparamCheckMeshAdaptMesh(gf));
  EXPECT_EQ(gf->triangles.size(), triangles);
  EXPECT_EQ(gf->triangles[0], first);
}

TEST_F(meshAdaptCheck, aMeshAdaptMeshWithAHoleIsReplaced)
{
  GFace *gf = squareMeshedWith(1);
  ASSERT_TRUE(gf && !gf->triangles.empty());
  takeOutABorderTriangle(gf);
  ASSERT_GE(countUnusedCurveSegments(gf), 1u);
  EXPECT_TRUE(reparamCheckMeshAdaptMesh(gf));
  EXPECT_FALSE(gf->triangles.empty());
  EXPECT_EQ(countUnusedCurveSegments(gf), 0u);
  EXPECT_EQ(countTrianglesAgainstInput(gf), 0u);
  // the algorithm asked is MeshAdapt still
  EXPECT_EQ(gf->getMeshingAlgo(), 1);
}

TEST_F(meshAdaptCheck, anotherMeshersMeshIsNotItsToCheck)
{
  // Frontal-Delaunay's: the validity hook's (Geo/planar/reparamMeshValidity.h)
  GFace *gf = squareMeshedWith(6);
  ASSERT_TRUE(gf && !gf->triangles.empty());
  takeOutABorderTriangle(gf);
  const std::size_t triangles = gf->triangles.size();
  EXPECT_FALSE(reparamCheckMeshAdaptMesh(gf));
  EXPECT_EQ(gf->triangles.size(), triangles);
  EXPECT_GE(countUnusedCurveSegments(gf), 1u);
}
