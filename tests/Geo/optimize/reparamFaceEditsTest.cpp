// Reparam - what the steps editing the faces' meshes share: the faces'
// tags for a log line, marked elements taken out of a face's list

#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamFaceEdits.h"
#include "surfaceMesh.h"

using namespace reparam;

TEST(reparamFaceEdits, tagListNamesTheFacesInTheirOrder)
{
  gmsh::clear();
  gmsh::model::add("tags");
  gmsh::model::addDiscreteEntity(2, 7);
  gmsh::model::addDiscreteEntity(2, 3);
  GModel *m = GModel::current();
  EXPECT_EQ(reparamTagList({m->getFaceByTag(7), m->getFaceByTag(3)}), "7, 3");
  EXPECT_EQ(reparamTagList({m->getFaceByTag(3)}), "3");
  EXPECT_EQ(reparamTagList({}), "");
}

TEST(reparamFaceEdits, dropMarkedKeepsTheOthersInTheirOrder)
{
  MVertex a(0., 0., 0.), b(1., 0., 0.), c(0., 1., 0.);
  std::vector<MTriangle *> triangles;
  for(int i = 0; i < 4; i++) triangles.push_back(new MTriangle(&a, &b, &c));
  MTriangle *second = triangles[1], *fourth = triangles[3];
  reparamDropMarked(triangles, {true, false, true, false});
  ASSERT_EQ(triangles.size(), 2u);
  EXPECT_EQ(triangles[0], second);
  EXPECT_EQ(triangles[1], fourth);
  reparamDropMarked(triangles, {true, true});
  EXPECT_TRUE(triangles.empty());
}

TEST(reparamFaceEdits, meshOfFacesTrianglesFirstNodesShared)
{
  // surface 1: a quadrangle (1, 2, 3, 4); surface 2: a triangle (2, 5, 3)
  // on its side (2, 3)
  gmsh::clear();
  gmsh::model::add("joined");
  gmsh::model::addDiscreteEntity(2, 1);
  gmsh::model::addDiscreteEntity(2, 2);
  gmsh::model::mesh::addNodes(2, 1, {1, 2, 3, 4},
                              {0., 0., 0., 1., 0., 0., 1., 1., 0., 0., 1., 0.});
  gmsh::model::mesh::addNodes(2, 2, {5}, {2., 0.5, 0.});
  gmsh::model::mesh::addElementsByType(1, 3, {}, {1, 2, 3, 4});
  gmsh::model::mesh::addElementsByType(2, 2, {}, {2, 5, 3});
  GModel *m = GModel::current();
  std::vector<MVertex *> nodes;
  const surfaceMesh joined =
    reparamMeshOfFaces({m->getFaceByTag(1), m->getFaceByTag(2)}, nodes);
  ASSERT_EQ(joined.triangles.size(), 1u);
  ASSERT_EQ(joined.quadrangles.size(), 1u);
  // the triangle's nodes indexed first, the quadrangle's shared ones reused
  ASSERT_EQ(nodes.size(), 5u);
  ASSERT_EQ(joined.points.size(), 5u);
  std::vector<std::size_t> tags;
  for(int i : joined.triangles[0]) tags.push_back(nodes[i]->getNum());
  EXPECT_EQ(tags, std::vector<std::size_t>({2, 5, 3}));
  tags.clear();
  for(int i : joined.quadrangles[0]) tags.push_back(nodes[i]->getNum());
  EXPECT_EQ(tags, std::vector<std::size_t>({1, 2, 3, 4}));
  for(std::size_t i = 0; i < nodes.size(); i++)
    EXPECT_EQ(joined.points[i].distance(nodes[i]->point()), 0.);
}
