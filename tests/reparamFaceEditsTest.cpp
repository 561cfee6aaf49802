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
