// Reparam - the safety net: a face no map can parametrize keeps its input
// triangles, stitched to its curves' 1D meshes, and the mesh stays whole

#include <algorithm>
#include <cmath>
#include <map>
#include <gtest/gtest.h>
#include "GFace.h"
#include "GModel.h"
#include "boundaryStitch.h"
#include "gmsh.h"
#include "gmshTestEnvironment.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamLostSegments.h"

using namespace reparam;

namespace {

  double area(const std::vector<SPoint3> &p, const std::array<int, 3> &t)
  {
    return 0.5 *
           crossprod(SVector3(p[t[0]], p[t[1]]), SVector3(p[t[0]], p[t[2]]))
             .norm();
  }

  // The free edges of the current model's mesh not on the sides of the
  // unit square (a gap inside), and its edges of three triangles or more
  int freeEdgesOffTheUnitSquaresSides(std::size_t &nonManifold)
  {
    int inside = 0;
    for(const auto &e : freeMeshEdges(&nonManifold)) {
      std::vector<double> p1, p2, par;
      gmsh::model::mesh::getNode(e.first, p1, par);
      gmsh::model::mesh::getNode(e.second, p2, par);
      auto onSide = [](const std::vector<double> &p) {
        return std::fabs(p[0]) < 1e-12 || std::fabs(p[0] - 1) < 1e-12 ||
               std::fabs(p[1]) < 1e-12 || std::fabs(p[1] - 1) < 1e-12;
      };
      inside += !(onSide(p1) && onSide(p2));
    }
    return inside;
  }

  // A bumpy square remeshed by the recipe (one face, nothing against the
  // input) at size 0.05: its face
  GFace *remeshedBumpySquare()
  {
    testTriangulation t = rectangleGrid(10, 10, 1., 1.);
    for(SPoint3 &p : t.points)
      p = SPoint3(p.x(), p.y(),
                  0.1 * std::sin(3. * p.x()) * std::cos(2. * p.y()));
    remeshWithRecipe(t, 0.05);
    for(auto it = GModel::current()->firstFace();
        it != GModel::current()->lastFace(); ++it)
      if(!(*it)->stl_triangles.empty()) return *it;
    return nullptr;
  }

} // namespace

TEST(boundaryStitch, inputBoundaryNodesGiveWayToTheCurvesNodes)
{
  // a 4 x 4 grid of the unit square; the curves' nodes: the corners (on
  // input nodes) and two per side at 0.4 and 0.8 (between input nodes)
  const testTriangulation grid = rectangleGrid(4, 4, 1., 1.);
  std::vector<SPoint3> curve;
  for(double s : {0., 0.4, 0.8}) {
    curve.push_back(SPoint3(s, 0, 0));
    curve.push_back(SPoint3(1, s, 0));
    curve.push_back(SPoint3(1 - s, 1, 0));
    curve.push_back(SPoint3(0, 1 - s, 0));
  }
  stitchedTriangulation st =
    stitchToBoundaryNodes(grid.points, grid.triangles, curve, 1e-9);
  EXPECT_EQ(st.unplacedNodes, 0u);
  EXPECT_EQ(st.keptInputNodes, 0u);
  EXPECT_EQ(st.turnedTriangles, 0u);
  std::vector<SPoint3> all = grid.points;
  all.insert(all.end(), curve.begin(), curve.end());
  double covered = 0.;
  std::map<std::pair<int, int>, int> edges;
  for(const auto &t : st.triangles) {
    covered += area(all, t);
    EXPECT_GT(
      crossprod(SVector3(all[t[0]], all[t[1]]), SVector3(all[t[0]], all[t[2]]))
        .z(),
      0.);
    for(int k = 0; k < 3; k++)
      edges[std::make_pair(std::min(t[k], t[(k + 1) % 3]),
                           std::max(t[k], t[(k + 1) % 3]))]++;
  }
  EXPECT_NEAR(covered, 1., 1e-12);
  // the boundary: the 12 curve nodes' 12 segments, nothing else
  int boundaryEdges = 0;
  const int numInput = (int)grid.points.size();
  for(const auto &e : edges) {
    EXPECT_LE(e.second, 2);
    if(e.second != 1) continue;
    boundaryEdges++;
    EXPECT_GE(e.first.first, numInput);
    EXPECT_GE(e.first.second, numInput);
  }
  EXPECT_EQ(boundaryEdges, 12);
}

TEST(boundaryStitch, nodesOffTheBoundaryAreLeftOut)
{
  // the corners of a 2 x 2 grid and a node inside: the sides' middle nodes
  // collapse onto corners, the node inside is left out
  const testTriangulation grid = rectangleGrid(2, 2, 1., 1.);
  const std::vector<SPoint3> curve = {SPoint3(0, 0, 0), SPoint3(1, 0, 0),
                                      SPoint3(1, 1, 0), SPoint3(0, 1, 0),
                                      SPoint3(0.5, 0.5, 0.)};
  stitchedTriangulation st =
    stitchToBoundaryNodes(grid.points, grid.triangles, curve, 1e-9);
  EXPECT_EQ(st.unplacedNodes, 1u);
  EXPECT_EQ(st.keptInputNodes, 0u);
  std::vector<SPoint3> all = grid.points;
  all.insert(all.end(), curve.begin(), curve.end());
  double covered = 0.;
  for(const auto &t : st.triangles) covered += area(all, t);
  EXPECT_NEAR(covered, 1., 1e-12);
}

TEST(boundaryStitch, aSliversTipTriangleGoesWithItsInputNode)
{
  // the unit square in 2 triangles and a tip triangle on its right side;
  // the curve runs along the square's corners, straight past the tip node
  const std::vector<SPoint3> points = {SPoint3(0, 0, 0), SPoint3(1, 0, 0),
                                       SPoint3(1, 1, 0), SPoint3(0, 1, 0),
                                       SPoint3(1.5, 0.5, 0)};
  const std::vector<std::array<int, 3> > triangles = {
    {{0, 1, 2}}, {{0, 2, 3}}, {{1, 4, 2}}};
  const std::vector<SPoint3> curve(points.begin(), points.begin() + 4);
  stitchedTriangulation st =
    stitchToBoundaryNodes(points, triangles, curve, 1e-9);
  EXPECT_EQ(st.unplacedNodes, 0u);
  EXPECT_EQ(st.keptInputNodes, 0u);
  EXPECT_EQ(st.turnedTriangles, 0u);
  ASSERT_EQ(st.triangles.size(), 2u);
  std::vector<SPoint3> all = points;
  all.insert(all.end(), curve.begin(), curve.end());
  double covered = 0.;
  for(const auto &t : st.triangles) {
    covered += area(all, t);
    for(int n : t) EXPECT_GE(n, 5);
  }
  EXPECT_NEAR(covered, 1., 1e-12);
}

TEST(reparamInputMesh, faceWithADegenerateTriangleKeepsItAndTheMeshIsWhole)
{
  // an 8 x 8 grid of the unit square with a zero-area triangle (b, a, m)
  // along the edge ab of the cells (4, 4) and (4, 3), m its midpoint (exact
  // in binary): no map takes it, so its part of the layout is kept as it is
  const testTriangulation t = gridWithSplitEdge(SPoint3(0., 0., 0.));
  ASSERT_EQ(t.triangles.size(), 130u);

  const std::vector<std::string> log = remeshWithRecipe(t, 0.1);
  int kept = 0;
  for(const auto &l : log) {
    EXPECT_EQ(l.find("Error"), std::string::npos) << l;
    kept += l.find("cannot be parametrized") != std::string::npos &&
            l.find("Warning") != std::string::npos;
  }
  EXPECT_EQ(kept, 1);
  EXPECT_EQ(facesKeptAsInput(GModel::current()).size(), 1u);

  EXPECT_TRUE(surfacesWithoutElements().empty());
  // whole: no edge of three triangles, the only free edges on the sides
  std::size_t nonManifold = 0;
  EXPECT_EQ(freeEdgesOffTheUnitSquaresSides(nonManifold), 0);
  EXPECT_EQ(nonManifold, 0u);
}

TEST(boundaryStitch, loopsWithoutBoundaryNodesStayAsTheyAre)
{
  // the 4 x 4 grid with no curve node at all: its input is kept whole; with
  // nodes on its corners only, its boundary nodes give way
  const testTriangulation grid = rectangleGrid(4, 4, 1., 1.);
  stitchedTriangulation st =
    stitchToBoundaryNodes(grid.points, grid.triangles, {}, 1e-9);
  EXPECT_EQ(st.triangles, grid.triangles);
  EXPECT_EQ(st.keptInputNodes, 0u);
  st = stitchToBoundaryNodes(
    grid.points, grid.triangles,
    {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(1, 1, 0), SPoint3(0, 1, 0)},
    1e-9);
  EXPECT_LT(st.triangles.size(), grid.triangles.size());
}

TEST(reparamInputMesh, aFaceMeshedGivesWayToItsInputWhenThatIsNoWorse)
{
  // a bumpy square remeshed by the recipe (one face, nothing against the
  // input): its input triangles stitched to its curves replace its mesh
  // when the planar mesh is said to keep one triangle against the input,
  // never when it keeps none
  GFace *gf = remeshedBumpySquare();
  ASSERT_NE(gf, nullptr);
  const std::size_t meshed = gf->triangles.size();
  EXPECT_GT(meshed, 500u); // size 0.05 on the unit square
  EXPECT_FALSE(reparamMeshFaceWithItsInput(gf, 0));
  EXPECT_EQ(gf->triangles.size(), meshed);
  EXPECT_FALSE(keptAsInput(gf));

  EXPECT_TRUE(reparamMeshFaceWithItsInput(gf, 1));
  EXPECT_TRUE(keptAsInput(gf));
  EXPECT_EQ(facesKeptAsInput(GModel::current()).size(), 1u);
  // the 200 input triangles, and one more for each curve node inserted on
  // an input boundary edge (the input's own boundary nodes given up)
  EXPECT_GE(gf->triangles.size(), 200u);
  EXPECT_LT(gf->triangles.size(), meshed);
  // whole: the free edges on the square's sides only
  std::size_t nonManifold = 0;
  EXPECT_EQ(freeEdgesOffTheUnitSquaresSides(nonManifold), 0);
  EXPECT_EQ(nonManifold, 0u);
}

TEST(reparamLostSegments, aFaceItsMesherLeftEmptyIsMeshedWithItsInput)
{
  // the bumpy square remeshed by the recipe; its planar mesher then said to
  // have lost a segment of one of its curves and left it empty: meshed with
  // its input, stitched to its curves, and the mesh whole
  GFace *gf = remeshedBumpySquare();
  ASSERT_NE(gf, nullptr);
  ASSERT_FALSE(gf->edges().empty());
  // a face still meshed keeps its mesh
  EXPECT_TRUE(reparamLostCurveSegment(gf, gf->edges()[0]));
  const std::size_t meshed = gf->triangles.size();
  meshFaceWithLostSegments(gf);
  EXPECT_EQ(gf->triangles.size(), meshed);
  EXPECT_FALSE(keptAsInput(gf));
  // an empty one gets its input
  EXPECT_TRUE(reparamLostCurveSegment(gf, gf->edges()[0]));
  gf->deleteMesh();
  meshFaceWithLostSegments(gf);
  EXPECT_GE(gf->triangles.size(), 200u);
  EXPECT_TRUE(keptAsInput(gf));
  EXPECT_EQ(gf->meshStatistics.status, GFace::DONE);
  std::size_t nonManifold = 0;
  EXPECT_EQ(freeEdgesOffTheUnitSquaresSides(nonManifold), 0);
  EXPECT_EQ(nonManifold, 0u);
}

TEST(reparamInputMesh, sliversAreParametrizedWithoutGmshsWarning)
{
  // the 8 x 8 grid of the unit square with the edge ab of the cells (4, 4)
  // and (4, 3) split by a node 1e-5 off its midpoint: a sliver of gamma
  // about 1e-4, which Reparam's maps take
  const testTriangulation t = gridWithSplitEdge(SPoint3(0., -1e-5, 0.));
  ASSERT_EQ(t.triangles.size(), 130u);

  const std::vector<std::string> log = remeshWithRecipe(t, 0.1);
  int taken = 0;
  for(const auto &l : log) {
    EXPECT_EQ(l.find("Error"), std::string::npos) << l;
    EXPECT_EQ(l.find("Warning"), std::string::npos) << l;
    taken += l.find("input triangles of gamma down to") != std::string::npos &&
             l.find("Info") != std::string::npos;
  }
  EXPECT_EQ(taken, 1);
  EXPECT_TRUE(facesKeptAsInput(GModel::current()).empty());
  EXPECT_TRUE(surfacesWithoutElements().empty());

  // with Gmsh's own map, Gmsh's warning stays
  GFace *gf = *GModel::current()->firstFace();
  double previous = 0.;
  gmsh::option::getNumber("Mesh.CompoundParametrization", previous);
  gmsh::option::setNumber("Mesh.CompoundParametrization", 0);
  EXPECT_FALSE(reparamTakesPoorInput(gf, 1e-4));
  gmsh::option::setNumber("Mesh.CompoundParametrization", 6);
  EXPECT_TRUE(reparamTakesPoorInput(gf, 1e-4));
  gmsh::option::setNumber("Mesh.CompoundParametrization", previous);
}
