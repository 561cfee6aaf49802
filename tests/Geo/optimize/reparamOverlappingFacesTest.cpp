// Reparam - two faces meshed onto each other (a part thinner than the mesh
// size between them, its curves' nodes alone on both sides) are found, and
// one of them is meshed with its input triangles: the part reopens, no
// edge is left inside both; the input's own non-manifold edges are none

#include <cmath>
#include <string>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamInputMesh.h"
#include "reparamOverlappingFaces.h"

using namespace reparam;

namespace {

  // A closed curve 1 from point 1 (node 1 at the origin) and faces 1 and
  // 2 bounded by it, without other nodes or elements yet
  void twoFacesOnALoop(const std::string &name)
  {
    gmsh::clear();
    gmsh::model::add(name);
    gmsh::model::addDiscreteEntity(0, 1);
    gmsh::model::addDiscreteEntity(1, 1, {1, 1});
    gmsh::model::addDiscreteEntity(2, 1, {1});
    gmsh::model::addDiscreteEntity(2, 2, {1});
    gmsh::model::mesh::addNodes(0, 1, {1}, {0., 0., 0.});
  }

  // A closed curve 1 through the unit square's corners (nodes 1-4, node 1
  // on point 1), faces 1 (above) and 2 (below) on it, both meshed with the
  // same two triangles across the diagonal 1-3 (turned the other way
  // below): the mesh of a pillow thinner than the size
  void flatPillowModel()
  {
    twoFacesOnALoop("pillow");
    gmsh::model::mesh::addNodes(1, 1, {2, 3, 4},
                                {1., 0., 0., 1., 1., 0., 0., 1., 0.});
    gmsh::model::mesh::addElementsByType(1, 1, {}, {1, 2, 2, 3, 3, 4, 4, 1});
    gmsh::model::mesh::addElementsByType(1, 2, {}, {1, 2, 3, 1, 3, 4});
    gmsh::model::mesh::addElementsByType(2, 2, {}, {1, 3, 2, 1, 4, 3});
  }

  // The input of a face: the square's corners and a fifth point at height
  // `apex` over (0.5, y) (none: 0), as a fan (or two triangles across
  // the diagonal 0-2, or with `otherDiagonal` 1-3), turned up or down
  void setInput(GFace *gf, double apex, bool up, bool otherDiagonal = false,
                double y = 0.5)
  {
    gf->stl_vertices_xyz = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                            SPoint3(1., 1., 0.), SPoint3(0., 1., 0.)};
    std::vector<std::array<int, 3> > t;
    if(apex != 0.) {
      gf->stl_vertices_xyz.push_back(SPoint3(0.5, y, apex));
      t = {{{0, 1, 4}}, {{1, 2, 4}}, {{2, 3, 4}}, {{3, 0, 4}}};
    }
    else if(otherDiagonal)
      t = {{{0, 1, 3}}, {{1, 2, 3}}};
    else
      t = {{{0, 1, 2}}, {{0, 2, 3}}};
    gf->stl_triangles.clear();
    for(std::array<int, 3> &c : t) {
      if(!up) std::swap(c[0], c[1]);
      gf->stl_triangles.insert(gf->stl_triangles.end(), c.begin(), c.end());
    }
  }

  double highestNode(GFace *gf)
  {
    double z = 0.;
    for(MTriangle *t : gf->triangles)
      for(int k = 0; k < 3; k++)
        z = std::max(z, std::fabs(t->getVertex(k)->z()));
    return z;
  }

} // namespace

TEST(reparamOverlappingFaces, aPillowMeshedFlatReopensAsItsInput)
{
  flatPillowModel();
  GModel *m = GModel::current();
  GFace *above = m->getFaceByTag(1), *below = m->getFaceByTag(2);
  setInput(above, 0.1, true);
  setInput(below, -0.1, false);
  const std::vector<overlappingFaces> pairs = facesMeshedOntoEachOther(m);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].first, above);
  EXPECT_EQ(pairs[0].second, below);
  // the diagonal 1-3, inside both, and the two triangles of both
  EXPECT_EQ(pairs[0].overlaps, 3u);
  std::size_t nonManifold = 0;
  freeMeshEdges(&nonManifold);
  EXPECT_EQ(nonManifold, 1u);

  EXPECT_EQ(reparamSeparateOverlappingFaces(m), 1u);
  EXPECT_TRUE(facesMeshedOntoEachOther(m).empty());
  // one face is its input again (its fan's apex 0.1 off the square), the
  // other kept; every edge of two triangles, none free
  EXPECT_EQ(keptAsInput(above) + keptAsInput(below), 1);
  EXPECT_NEAR(std::max(highestNode(above), highestNode(below)), 0.1, 1e-12);
  EXPECT_EQ(above->triangles.size() + below->triangles.size(), 6u);
  EXPECT_TRUE(freeMeshEdges(&nonManifold).empty());
  EXPECT_EQ(nonManifold, 0u);
}

TEST(reparamOverlappingFaces, theSameTriangleInTwoFacesIsAnOverlap)
{
  // a pillow of three nodes: one triangle in each face, no edge inside
  twoFacesOnALoop("triangle");
  gmsh::model::mesh::addNodes(1, 1, {2, 3}, {1., 0., 0., 0., 1., 0.});
  gmsh::model::mesh::addElementsByType(1, 1, {}, {1, 2, 2, 3, 3, 1});
  gmsh::model::mesh::addElementsByType(1, 2, {}, {1, 2, 3});
  gmsh::model::mesh::addElementsByType(2, 2, {}, {1, 3, 2});
  const std::vector<overlappingFaces> pairs =
    facesMeshedOntoEachOther(GModel::current());
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].overlaps, 1u);
}

TEST(reparamOverlappingFaces, theInputsOwnDoubledSheetIsNone)
{
  // the same meshes where the inputs are the flat square twice: the
  // diagonal is an edge of four input triangles and the triangles are the
  // input's own twice, which the mesh keeps (gmsh2x_squirrel's input has
  // two faces touching along an edge)
  flatPillowModel();
  GModel *m = GModel::current();
  setInput(m->getFaceByTag(1), 0., true);
  setInput(m->getFaceByTag(2), 0., false);
  EXPECT_TRUE(facesMeshedOntoEachOther(m).empty());
  EXPECT_EQ(reparamSeparateOverlappingFaces(m), 0u);
  EXPECT_EQ(m->getFaceByTag(1)->triangles.size(), 2u);
}

TEST(reparamOverlappingFaces, facesSideBySideDoNotOverlap)
{
  // two faces each with an edge inside, on either side of a curve
  gmsh::clear();
  gmsh::model::add("sideBySide");
  gmsh::model::addDiscreteEntity(0, 1);
  gmsh::model::addDiscreteEntity(0, 2);
  gmsh::model::addDiscreteEntity(1, 1, {1, 2});
  gmsh::model::addDiscreteEntity(2, 1, {1});
  gmsh::model::addDiscreteEntity(2, 2, {1});
  gmsh::model::mesh::addNodes(0, 1, {1}, {0., 0., 0.});
  gmsh::model::mesh::addNodes(0, 2, {2}, {1., 0., 0.});
  gmsh::model::mesh::addNodes(2, 1, {3, 4}, {1., 1., 0., 0., 1., 0.});
  gmsh::model::mesh::addNodes(2, 2, {5, 6}, {1., -1., 0., 0., -1., 0.});
  gmsh::model::mesh::addElementsByType(1, 1, {}, {1, 2});
  gmsh::model::mesh::addElementsByType(1, 2, {}, {1, 2, 3, 1, 3, 4});
  gmsh::model::mesh::addElementsByType(2, 2, {}, {1, 5, 2, 1, 6, 5});
  EXPECT_TRUE(facesMeshedOntoEachOther(GModel::current()).empty());
}

TEST(reparamOverlappingFaces, theOtherFaceIsTriedWhenTheFirstStaysOnIt)
{
  // above's input keeps the diagonal 1-3 inside (a node at the centroid of
  // one of its halves): as its input it still shares that diagonal with
  // below; below's input, a fan, parts them
  flatPillowModel();
  GModel *m = GModel::current();
  GFace *above = m->getFaceByTag(1), *below = m->getFaceByTag(2);
  above->stl_vertices_xyz = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                             SPoint3(1., 1., 0.), SPoint3(0., 1., 0.),
                             SPoint3(2. / 3., 1. / 3., 0.)};
  above->stl_triangles = {0, 1, 4, 1, 2, 4, 2, 0, 4, 0, 2, 3};
  setInput(below, -0.1, false);
  ASSERT_EQ(facesMeshedOntoEachOther(m).size(), 1u);
  EXPECT_EQ(reparamSeparateOverlappingFaces(m), 1u);
  EXPECT_TRUE(facesMeshedOntoEachOther(m).empty());
  EXPECT_TRUE(keptAsInput(below));
  // and nothing is left to do
  const std::size_t triangles =
    above->triangles.size() + below->triangles.size();
  EXPECT_EQ(reparamSeparateOverlappingFaces(m), 0u);
  EXPECT_EQ(above->triangles.size() + below->triangles.size(), triangles);
}

TEST(reparamOverlappingFaces, aFaceWhoseNodesTheOtherUsesKeepsItsMesh)
{
  // both faces meshed as the same fan around a node of face 1 (the
  // optimization across the cuts moves triangles from face to face: the
  // other face's triangles then use that face's nodes): face 1, tried
  // first, would delete the node face 2's triangles stand on; face 2 is
  // meshed with its input instead
  twoFacesOnALoop("sharedNode");
  gmsh::model::mesh::addNodes(1, 1, {2, 3, 4},
                              {1., 0., 0., 1., 1., 0., 0., 1., 0.});
  gmsh::model::mesh::addNodes(2, 1, {5}, {0.5, 0.5, 0.});
  gmsh::model::mesh::addElementsByType(1, 1, {}, {1, 2, 2, 3, 3, 4, 4, 1});
  gmsh::model::mesh::addElementsByType(1, 2, {},
                                       {1, 2, 5, 2, 3, 5, 3, 4, 5, 4, 1, 5});
  gmsh::model::mesh::addElementsByType(2, 2, {},
                                       {1, 5, 2, 2, 5, 3, 3, 5, 4, 4, 5, 1});
  GModel *m = GModel::current();
  GFace *above = m->getFaceByTag(1), *below = m->getFaceByTag(2);
  setInput(above, 0.1, true);
  setInput(below, -0.1, false);
  MVertex *shared = above->mesh_vertices.at(0);
  ASSERT_EQ(facesMeshedOntoEachOther(m).size(), 1u);
  EXPECT_EQ(reparamSeparateOverlappingFaces(m), 1u);
  EXPECT_FALSE(keptAsInput(above));
  EXPECT_TRUE(keptAsInput(below));
  ASSERT_EQ(above->mesh_vertices.size(), 1u);
  EXPECT_EQ(above->mesh_vertices[0], shared);
  EXPECT_EQ(above->triangles.size(), 4u);
  EXPECT_NEAR(highestNode(below), 0.1, 1e-12);
  EXPECT_TRUE(facesMeshedOntoEachOther(m).empty());
}

TEST(reparamOverlappingFaces, anInputWithoutInnerNodeIsNoMeshToGive)
{
  // both inputs two triangles between the corners: stitched to the curves
  // they make the same kind of flat pair (pelvis_tlem2's pockets): left,
  // neither face kept as its input
  flatPillowModel();
  GModel *m = GModel::current();
  setInput(m->getFaceByTag(1), 0., true);
  setInput(m->getFaceByTag(2), 0., false, true);
  ASSERT_EQ(facesMeshedOntoEachOther(m).size(), 1u);
  EXPECT_EQ(reparamSeparateOverlappingFaces(m), 0u);
  EXPECT_FALSE(keptAsInput(m->getFaceByTag(1)));
  EXPECT_FALSE(keptAsInput(m->getFaceByTag(2)));
}

TEST(reparamOverlappingFaces, anInputOfSliversIsNoMeshToGive)
{
  // both inputs fans whose apex lies 0.0005 off the side 0-1 (a triangle of
  // kappa about 0.002, as a CAD triangulation's fans): the pair stays as it
  // is, named in the warning, neither face kept as its input
  flatPillowModel();
  GModel *m = GModel::current();
  GFace *above = m->getFaceByTag(1), *below = m->getFaceByTag(2);
  setInput(above, 0.0005, true, false, 0.0005);
  setInput(below, -0.0005, false, false, 0.0005);
  ASSERT_EQ(facesMeshedOntoEachOther(m).size(), 1u);
  EXPECT_EQ(reparamSeparateOverlappingFaces(m), 0u);
  EXPECT_EQ(facesMeshedOntoEachOther(m).size(), 1u);
  EXPECT_FALSE(keptAsInput(above));
  EXPECT_FALSE(keptAsInput(below));
  EXPECT_EQ(above->triangles.size(), 2u);
}
