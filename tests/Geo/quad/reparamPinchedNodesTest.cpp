// Reparam - pinched nodes removed from Gmsh's meshes of two faces: a
// triangle of three nodes of a cut folded onto the quadrangle across it
// goes, the quadrangle becomes a triangle and the cut's two segments one;
// the same node on a curve that is no cut stays

#include <algorithm>
#include <gtest/gtest.h>
#include "GEdge.h"
#include "GFace.h"
#include "GModel.h"
#include "MLine.h"
#include "MQuadrangle.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamPinchedNodes.h"

using namespace reparam;

namespace {

  // Curve 1 from a (1) through m (2) to b (3), bent at m by 0.1; surface 1
  // above it: the quadrangle (b, x, a, m), x (4) at (1, 1); surface 2
  // below: the triangle (a, b, m) folded onto that quadrangle and the
  // triangle (a, c, b), c (5) at (1, -1)
  void foldedEarModel()
  {
    gmsh::clear();
    gmsh::model::add("ear");
    gmsh::model::addDiscreteEntity(0, 1);
    gmsh::model::addDiscreteEntity(0, 3);
    gmsh::model::addDiscreteEntity(1, 1, {1, 3});
    gmsh::model::addDiscreteEntity(2, 1, {1});
    gmsh::model::addDiscreteEntity(2, 2, {1});
    gmsh::model::mesh::addNodes(0, 1, {1}, {0., 0., 0.});
    gmsh::model::mesh::addNodes(0, 3, {3}, {2., 0., 0.});
    gmsh::model::mesh::addNodes(1, 1, {2}, {1., 0.1, 0.});
    gmsh::model::mesh::addNodes(2, 1, {4}, {1., 1., 0.});
    gmsh::model::mesh::addNodes(2, 2, {5}, {1., -1., 0.});
    gmsh::model::mesh::addElementsByType(1, 1, {}, {1, 2, 2, 3});
    gmsh::model::mesh::addElementsByType(1, 3, {}, {3, 4, 1, 2});
    gmsh::model::mesh::addElementsByType(2, 2, {}, {1, 3, 2, 1, 5, 3});
  }

  std::vector<std::size_t> tagsOf(MElement *e)
  {
    std::vector<std::size_t> tags;
    for(std::size_t k = 0; k < e->getNumVertices(); k++)
      tags.push_back(e->getVertex(k)->getNum());
    return tags;
  }

} // namespace

TEST(reparamPinchedNodes, aTriangleFoldedOntoAQuadrangleAcrossACutGoes)
{
  foldedEarModel();
  GModel *m = GModel::current();
  GFace *above = m->getFaceByTag(1), *below = m->getFaceByTag(2);
  GEdge *cut = m->getEdgeByTag(1);
  std::set<GFace *> changed;
  EXPECT_EQ(reparamRemovePinchedNodes({above, below}, {cut}, changed), 1u);
  EXPECT_EQ(changed, std::set<GFace *>({above, below}));
  // above: the quadrangle's three other corners in its order
  EXPECT_TRUE(above->quadrangles.empty());
  ASSERT_EQ(above->triangles.size(), 1u);
  EXPECT_EQ(tagsOf(above->triangles[0]), std::vector<std::size_t>({3, 4, 1}));
  // below: the folded triangle gone
  ASSERT_EQ(below->triangles.size(), 1u);
  EXPECT_EQ(tagsOf(below->triangles[0]), std::vector<std::size_t>({1, 5, 3}));
  // the cut: one segment from a to b, no node
  EXPECT_TRUE(cut->mesh_vertices.empty());
  ASSERT_EQ(cut->lines.size(), 1u);
  EXPECT_EQ(tagsOf(cut->lines[0]), std::vector<std::size_t>({1, 3}));
}

TEST(reparamPinchedNodes, aNodeOfACurveThatIsNoCutStays)
{
  foldedEarModel();
  GModel *m = GModel::current();
  std::set<GFace *> changed;
  EXPECT_EQ(reparamRemovePinchedNodes({m->getFaceByTag(1), m->getFaceByTag(2)},
                                      {}, changed),
            0u);
  EXPECT_TRUE(changed.empty());
  EXPECT_EQ(m->getFaceByTag(1)->quadrangles.size(), 1u);
  EXPECT_EQ(m->getFaceByTag(2)->triangles.size(), 2u);
  EXPECT_EQ(m->getEdgeByTag(1)->lines.size(), 2u);
}

TEST(reparamPinchedNodes, aTriangleTurningOverStays)
{
  // x moved between the chord of a and b and m: the quadrangle (b, x, a, m)
  // is a flat dart, its triangle (b, x, a) would point against its normal
  // (its diagonals' cross product)
  foldedEarModel();
  GModel *m = GModel::current();
  MVertex *x = nullptr;
  for(MVertex *v : m->getFaceByTag(1)->mesh_vertices) x = v;
  ASSERT_TRUE(x);
  x->setXYZ(1., 0.05, 0.);
  std::set<GFace *> changed;
  EXPECT_EQ(reparamRemovePinchedNodes({m->getFaceByTag(1), m->getFaceByTag(2)},
                                      {m->getEdgeByTag(1)}, changed),
            0u);
  EXPECT_EQ(m->getFaceByTag(1)->quadrangles.size(), 1u);
}
