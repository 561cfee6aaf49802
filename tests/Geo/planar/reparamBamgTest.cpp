// Reparam - BAMG's arrays sized for a face Reparam parametrized, and BAMG's
// failure on such a face handled by Reparam

#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "MTriangle.h"
#include "reparamBamg.h"
#include "reparamHooks.h"
#include "reparamMeshValidity.h"

using namespace reparam;

TEST(reparamBamg, theBoundFollowsTheVertices)
{
  EXPECT_EQ(bamgMaxVertices(0), 20000);
  EXPECT_EQ(bamgMaxVertices(17), 20000);
  EXPECT_EQ(bamgMaxVertices(1000), 32000);
  EXPECT_EQ(bamgMaxVertices(20000), 640000);
  // never above BAMG's own default
  EXPECT_EQ(bamgMaxVertices(100000), 900000);
}

TEST(reparamBamg, aFaceReparamParametrizedIsBoundedAndMeshed)
{
  squareWithAShortCurve();
  gmsh::option::setNumber("Mesh.Algorithm", 7);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.1);
  gmsh::model::mesh::generate(2);
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
  GFace *gf = GModel::current()->getFaceByTag(1);
  ASSERT_TRUE(gf);
  // the unit square at 0.1: about 130 triangles, far below the bound
  EXPECT_GT(gf->triangles.size(), 80u);
  EXPECT_LT(gf->triangles.size(), 400u);
  EXPECT_TRUE(surfacesWithoutElements().empty());
  EXPECT_EQ(reparamBamgMaxVertices(gf, 100), 20000.);
  EXPECT_EQ(reparamBamgMaxVertices(gf, 1000), 32000.);
  // a failure is Reparam's to log, noted once
  const std::size_t triangles = gf->triangles.size();
  EXPECT_TRUE(reparamBamgFailed(gf));
  EXPECT_EQ(gf->triangles.size(), triangles);
  EXPECT_TRUE(takeBamgFailure(gf));
  EXPECT_FALSE(takeBamgFailure(gf));
}

TEST(reparamBamg, aFaceBamgGaveUpOnIsMeshedByDelaunay)
{
  // as Gmsh's BAMG mesher leaves a face it gave up on, then the validity
  // hook: Delaunay's mesh in its place, at the sizes asked
  gmsh::option::setNumber("Mesh.Algorithm", 7);
  GFace *gf = meshedSquareWithAShortCurve(0.1);
  ASSERT_TRUE(gf && !gf->triangles.empty());
  const MTriangle *first = gf->triangles[0];
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.1);
  ASSERT_TRUE(reparamBamgFailed(gf));
  EXPECT_FALSE(reparamPlanarMeshLeavesHole(gf));
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  ASSERT_FALSE(gf->triangles.empty());
  EXPECT_NE(gf->triangles[0], first);
  EXPECT_FALSE(takeBamgFailure(gf));
  // the unit square at 0.1
  EXPECT_GT(gf->triangles.size(), 80u);
  EXPECT_LT(gf->triangles.size(), 400u);
}

TEST(reparamBamg, anotherFaceKeepsBamgsDefaults)
{
  gmsh::clear();
  gmsh::model::geo::addPoint(0, 0, 0, 0.1, 1);
  gmsh::model::geo::addPoint(1, 0, 0, 0.1, 2);
  gmsh::model::geo::addPoint(1, 1, 0, 0.1, 3);
  gmsh::model::geo::addPoint(0, 1, 0, 0.1, 4);
  for(int i = 1; i <= 4; i++) gmsh::model::geo::addLine(i, i % 4 + 1, i);
  gmsh::model::geo::addCurveLoop({1, 2, 3, 4}, 1);
  gmsh::model::geo::addPlaneSurface({1}, 1);
  gmsh::model::geo::synchronize();
  GFace *gf = GModel::current()->getFaceByTag(1);
  ASSERT_TRUE(gf);
  EXPECT_EQ(reparamBamgMaxVertices(gf, 100), -1.1e100);
  EXPECT_FALSE(reparamBamgFailed(gf));
}
