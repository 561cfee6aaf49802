// Reparam - the mesh the optimization works on: a surfaceMesh with its
// per-point and per-triangle records, which removeDeadParts renumbers
// together, and its worst kappa

#include <cmath>
#include <gtest/gtest.h>
#include "optimizableMesh.h"
#include "triangleQuality.h"

using namespace reparam;

namespace {

  // The unit square cut by its diagonal (0, 2) into (0, 1, 2) and (0, 2, 3),
  // and a fifth point 4 in (1, 2, 4) outside it; every record filled
  optimizableMesh squareAndEar()
  {
    optimizableMesh m;
    m.points = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.), SPoint3(1., 1., 0.),
                SPoint3(0., 1., 0.), SPoint3(2., 0.5, 0.)};
    m.triangles = {{{0, 1, 2}}, {{0, 2, 3}}, {{1, 4, 2}}};
    m.movable = {false, true, false, true, true};
    m.landing = {-1, 10, -1, 13, 14};
    m.inputNode = {-1, -1, 22, -1, 24};
    m.size = {0.5, 1.5, 2.5, 3.5, 4.5};
    m.origin = {0, 1, 2, 3, -1};
    m.triangleOrigin = {0, 1, -1};
    m.against = {false, true, false};
    m.lockedEdges = {{0, 1}, {2, 3}, {1, 4}};
    return m;
  }

} // namespace

TEST(optimizableMesh, isASurfaceMeshOfTrianglesOnly)
{
  const optimizableMesh m = squareAndEar();
  const surfaceMesh &s = m;
  EXPECT_EQ(s.points.size(), 5u);
  EXPECT_EQ(s.numElements(), 3u);
  EXPECT_TRUE(s.quadrangles.empty());
}

TEST(optimizableMeshRemoveDeadParts, renumbersEveryRecordTogether)
{
  // point 1 and the two triangles on it removed: 0, 2, 3, 4 become 0-3
  optimizableMesh m = squareAndEar();
  const std::vector<int> newIndex =
    removeDeadParts(m, {false, true, false, false, false}, {true, false, true});
  EXPECT_EQ(newIndex, (std::vector<int>{0, -1, 1, 2, 3}));
  ASSERT_EQ(m.points.size(), 4u);
  EXPECT_EQ(m.points[3].x(), 2.);
  EXPECT_EQ(m.movable, (std::vector<bool>{false, false, true, true}));
  EXPECT_EQ(m.landing, (std::vector<int>{-1, -1, 13, 14}));
  EXPECT_EQ(m.inputNode, (std::vector<int>{-1, 22, -1, 24}));
  EXPECT_EQ(m.size, (std::vector<double>{0.5, 2.5, 3.5, 4.5}));
  EXPECT_EQ(m.origin, (std::vector<int>{0, 2, 3, -1}));
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{{0, 1, 2}}));
  EXPECT_EQ(m.triangleOrigin, (std::vector<int>{1}));
  EXPECT_EQ(m.against, (std::vector<bool>{true}));
  // the locked edges on point 1 go, (2, 3) becomes (1, 2)
  EXPECT_EQ(m.lockedEdges, (std::set<std::pair<int, int> >{{1, 2}}));
}

TEST(optimizableMeshRemoveDeadParts, leavesAgainstAloneWhenItIsNotKept)
{
  // `against` not sized per triangle (the optimizer has not marked them):
  // left as it is
  optimizableMesh m = squareAndEar();
  m.against.clear();
  removeDeadParts(m, std::vector<bool>(5, false), {false, true, false});
  EXPECT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangleOrigin, (std::vector<int>{0, -1}));
  EXPECT_TRUE(m.against.empty());
  EXPECT_EQ(m.points.size(), 5u);
}

TEST(optimizableMesh, worstKappaIsTheLowestOfItsTriangles)
{
  const optimizableMesh m = squareAndEar();
  // the right isosceles halves of the square: 4 sin(pi/4)^2 / (1 + sqrt 2);
  // the ear (1, 4, 2), of sides sqrt(1.25), sqrt(1.25), 1, is better:
  // sines 4/5 at 4 and 2/sqrt(5) at its base
  const double half = 2. / (1. + std::sqrt(2.));
  const double ear = 4. * 0.8 * 0.8 / (0.8 + 4. / std::sqrt(5.));
  EXPECT_NEAR(triangleKappa(m.points[1], m.points[4], m.points[2]), ear, 1e-12);
  EXPECT_NEAR(ear, 0.988854, 1e-6);
  EXPECT_NEAR(worstKappa(m), half, 1e-12);
  EXPECT_NEAR(half, 0.828427, 1e-6);
  EXPECT_EQ(worstKappa(optimizableMesh()), 1.);
}
