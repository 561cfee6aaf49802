// Reparam - an element of a recombined face pointing against the input,
// split again with its neighbour into elements along it; a face with none
// stays as it is

#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MQuadrangle.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamResplitAgainst.h"

using namespace reparam;

namespace {

  // Surface 1 over the input [-1, 1] x [0, 1] (z = 0, two triangles facing
  // +z): the quadrangles (-1, 0)-(0, 1) and (0, 0)-(1, 1), and a triangle
  // on the latter's right side folded back into it, its third corner at
  // (0.5, 0.5): it faces -z
  GFace *foldedTriangleFace(bool folded)
  {
    gmsh::clear();
    gmsh::model::add("fold");
    gmsh::model::addDiscreteEntity(2, 1);
    // 1 (0, 0), 2 (1, 0), 3 (1, 1), 4 (0, 1), 5 (0.5, 0.5) or (1.5, 0.5),
    // 6 (-1, 0), 7 (-1, 1)
    gmsh::model::mesh::addNodes(
      2, 1, {1, 2, 3, 4, 5, 6, 7},
      {0.,  0., 0.,  1., 0., 0.,  1., 1., 0., 0., 1., 0., folded ? 0.5 : 1.5,
       0.5, 0., -1., 0., 0., -1., 1., 0.});
    gmsh::model::mesh::addElementsByType(1, 3, {}, {6, 1, 4, 7, 1, 2, 3, 4});
    gmsh::model::mesh::addElementsByType(1, 2, {}, {2, 5, 3});
    GFace *gf = GModel::current()->getFaceByTag(1);
    gf->stl_vertices_xyz = {SPoint3(-1., 0., 0.), SPoint3(1., 0., 0.),
                            SPoint3(1., 1., 0.), SPoint3(-1., 1., 0.)};
    gf->stl_triangles = {0, 1, 2, 0, 2, 3};
    return gf;
  }

  // Twice the signed area in (x, y) of element e
  double area2(MElement *e)
  {
    double a = 0.;
    const std::size_t n = e->getNumVertices();
    for(std::size_t k = 0; k < n; k++) {
      MVertex *p = e->getVertex(k), *q = e->getVertex((k + 1) % n);
      a += p->x() * q->y() - q->x() * p->y();
    }
    return a;
  }

} // namespace

TEST(reparamResplitAgainst, aFoldedTriangleAndItsNeighbourSplitAgain)
{
  GFace *gf = foldedTriangleFace(true);
  EXPECT_LT(area2(gf->triangles[0]), 0.);
  EXPECT_EQ(reparamResplitElementsAgainstInput(gf), 1u);
  // the quadrangle on the left stays; the pentagon of the other two,
  // (1, 0), (0.5, 0.5), (1, 1), (0, 1), (0, 0) (the unit square less the
  // triangle the fold covered twice, area 0.75), in elements facing +z
  // that cover it once
  double sum = 0.;
  std::size_t elements = 0;
  for(std::size_t i = 0; i < gf->getNumMeshElements(); i++) {
    MElement *e = gf->getMeshElement(i);
    EXPECT_GT(area2(e), 0.);
    sum += area2(e);
    elements++;
  }
  EXPECT_NEAR(sum, 2. * (1. + 0.75), 1e-12);
  EXPECT_GE(elements, 3u);
  EXPECT_LE(elements, 4u);
  bool leftStays = false;
  for(MQuadrangle *q : gf->quadrangles)
    leftStays = leftStays || q->getVertex(0)->getNum() == 6;
  EXPECT_TRUE(leftStays);
  // nothing left to do
  EXPECT_EQ(reparamResplitElementsAgainstInput(gf), 0u);
}

TEST(reparamResplitAgainst, aFaceAlongItsInputStays)
{
  GFace *gf = foldedTriangleFace(false);
  EXPECT_EQ(reparamResplitElementsAgainstInput(gf), 0u);
  EXPECT_EQ(gf->quadrangles.size(), 2u);
  EXPECT_EQ(gf->triangles.size(), 1u);
}
