// Reparam - a face of Gmsh's model as plain arrays

#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "gmsh.h"
#include "reparamSurfaceMesh.h"

using namespace reparam;

namespace {

  // A new model with one discrete surface: the unit square (nodes 1-4) as a
  // quadrangle and the triangle (2, 5, 3) beside it
  GFace *squareAndTriangle()
  {
    gmsh::clear();
    const int s = gmsh::model::addDiscreteEntity(2);
    gmsh::model::mesh::addNodes(
      2, s, {1, 2, 3, 4, 5},
      {0., 0., 0., 1., 0., 0., 1., 1., 0., 0., 1., 0., 2., 0.5, 0.});
    gmsh::model::mesh::addElementsByType(s, 3, {}, {1, 2, 3, 4});
    gmsh::model::mesh::addElementsByType(s, 2, {}, {2, 5, 3});
    return GModel::current()->getFaceByTag(s);
  }

} // namespace

TEST(reparamSurfaceMesh, nodesNumberedAsTheElementsFirstUseThem)
{
  GFace *gf = squareAndTriangle();
  ASSERT_NE(gf, nullptr);
  const surfaceMesh m = surfaceMeshOf(gf);
  // the triangles first: nodes 2, 5, 3 are 0, 1, 2; then 1 and 4
  ASSERT_EQ(m.points.size(), 5u);
  ASSERT_EQ(m.triangles.size(), 1u);
  ASSERT_EQ(m.quadrangles.size(), 1u);
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{{0, 1, 2}}));
  EXPECT_EQ(m.quadrangles[0], (std::array<int, 4>{{3, 0, 2, 4}}));
  EXPECT_EQ(m.points[1].x(), 2.);
  EXPECT_EQ(m.points[1].y(), 0.5);
  EXPECT_EQ(m.points[4].x(), 0.);
  EXPECT_EQ(m.points[4].y(), 1.);
  EXPECT_EQ(m.numElements(), 2u);
}

TEST(reparamSurfaceMesh, inputTriangulationIsTheFacesStlArrays)
{
  GFace *gf = squareAndTriangle();
  ASSERT_NE(gf, nullptr);
  EXPECT_EQ(inputTriangulationOf(gf).numElements(), 0u);
  gf->stl_vertices_xyz = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                          SPoint3(1., 1., 0.), SPoint3(0., 1., 0.5)};
  gf->stl_triangles = {0, 1, 2, 0, 2, 3};
  const surfaceMesh m = inputTriangulationOf(gf);
  ASSERT_EQ(m.points.size(), 4u);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[1], (std::array<int, 3>{{0, 2, 3}}));
  EXPECT_EQ(m.points[3].z(), 0.5);
  EXPECT_TRUE(m.quadrangles.empty());
  gmsh::clear();
}
