// Reparam - the local repair of a face's new mesh (edge splits and flips,
// node moves) keeps the mesh conforming, valid in (u, v) and on the surface

#include <algorithm>
#include <cmath>
#include <map>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "invertedElementRepair.h"

using namespace reparam;

namespace {

  double uvArea2(GFace *gf, MTriangle *t)
  {
    SPoint2 p[3];
    for(int k = 0; k < 3; k++) reparamMeshVertexOnFace(t->getVertex(k), gf, p[k]);
    return (p[1].x() - p[0].x()) * (p[2].y() - p[0].y()) -
           (p[1].y() - p[0].y()) * (p[2].x() - p[0].x());
  }

  // Edges used once: the face's boundary
  std::map<std::pair<MVertex *, MVertex *>, int> edgeUses(GFace *gf)
  {
    std::map<std::pair<MVertex *, MVertex *>, int> uses;
    for(MTriangle *t : gf->triangles)
      for(int k = 0; k < 3; k++) {
        MVertex *a = t->getVertex(k), *b = t->getVertex((k + 1) % 3);
        uses[a < b ? std::make_pair(a, b) : std::make_pair(b, a)]++;
      }
    return uses;
  }

} // namespace

TEST(invertedElementRepair, changesKeepTheMeshValidConformingAndOnTheSurface)
{
  // The dome remeshed; "against the input" stands for a test the mesh fails
  // here and there: the triangles larger than 95 % of the others. Splits
  // make them smaller, so the repair ends with none
  gmsh::clear();
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.1);
  gmsh::merge(tutorialFile("dome.stl"));
  gmsh::model::mesh::classifySurfaces(40 * M_PI / 180, true, true, M_PI);
  gmsh::model::mesh::createGeometry();
  gmsh::model::mesh::generate(2);
  GFace *gf = *GModel::current()->firstFace();
  ASSERT_GT(gf->triangles.size(), 100u);
  std::vector<double> areas;
  for(MTriangle *t : gf->triangles) areas.push_back(t->getVolume());
  std::sort(areas.begin(), areas.end());
  const double largest = areas[areas.size() * 95 / 100];
  const double sign = uvArea2(gf, gf->triangles[0]) > 0. ? 1. : -1.;
  std::map<std::pair<MVertex *, MVertex *>, int> before = edgeUses(gf);
  const std::size_t nodesBefore = gf->mesh_vertices.size();

  auto large = [largest](MTriangle *t) { return t->getVolume() > largest; };
  std::size_t largeBefore = 0;
  for(MTriangle *t : gf->triangles) largeBefore += large(t);
  ASSERT_GT(largeBefore, 0u);
  invertedRepair r = splitInvertedTriangles(gf, large, 10);
  EXPECT_EQ(r.before, largeBefore);
  EXPECT_EQ(r.after, 0u);
  EXPECT_GT(r.changes, 0u);
  EXPECT_GT(gf->mesh_vertices.size(), nodesBefore);

  // valid in (u, v): every triangle keeps the orientation of the others
  for(MTriangle *t : gf->triangles) EXPECT_GT(sign * uvArea2(gf, t), 0.);
  // conforming: inner edges twice, the boundary (the curves' mesh) as it was
  std::map<std::pair<MVertex *, MVertex *>, int> after = edgeUses(gf);
  std::size_t boundaryBefore = 0, boundaryAfter = 0;
  for(const auto &e : before) boundaryBefore += e.second == 1;
  for(const auto &e : after) {
    EXPECT_LE(e.second, 2);
    if(e.second == 1) {
      boundaryAfter++;
      EXPECT_EQ(before.count(e.first), 1u);
    }
  }
  EXPECT_EQ(boundaryAfter, boundaryBefore);
  // new nodes on the surface: at the point of their (u, v)
  for(MVertex *v : gf->mesh_vertices) {
    SPoint2 uv;
    reparamMeshVertexOnFace(v, gf, uv);
    GPoint p = gf->point(uv.x(), uv.y());
    EXPECT_LT(v->point().distance(SPoint3(p.x(), p.y(), p.z())), 1e-12);
  }
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
}
